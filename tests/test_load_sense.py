"""A load whose solved size contradicts its stated sense is re-solved the other way (issue 25, 6).

A couple declared ``ccw`` on a flywheel spinning ccw that ``stops`` was answered
M = −27.4 lb·ft with every check green: the couple that stops a ccw spin acts cw. A force or
couple of unknown size acts in the sense the scene states; a negative size is a failed
assumption, re-solved with the sense reversed and said so, as a friction's sense is (in a
linkage, a failed check that says which way it acts).
Expected numbers are derived by hand in the comments.
"""

from pathlib import Path

import pytest

from dynsolve.pipeline import solve_text
from dynsolve.system import SolveOptions

MODES = ["exact", "numeric", "auto"]
ROOT = Path(__file__).resolve().parent.parent

FLYWHEEL = """units: FPS
given:
  W = 100 lb
  k = 0.75 ft
  omega_1 = 300 rev/min
  dt = 2 s
scene:
  point O: (0, 0)
  body wheel: weight W, gyration k, at (0, 0)
  pin wheel at O
  omega wheel: omega_1 ccw
  couple M on wheel: {sense}
  gravity
  travel wheel: for dt, stops
find: M [lb*ft]
"""


@pytest.mark.parametrize("mode", MODES)
def test_a_couple_stated_ccw_that_stops_a_ccw_spin_acts_cw(mode: str) -> None:
    # I_O = (W/g) k² = (100/32.2)(0.5625) = 1.74689 slug·ft², ω₁ = 300 rev/min = 10π rad/s:
    # I_O ω₁ + M Δt = 0 with M ccw-positive gives M = −I_O ω₁/Δt = −27.44 lb·ft: 27.44 cw.
    solution = solve_text(FLYWHEEL.format(sense="ccw"), options=SolveOptions(mode=mode))
    M = next(a for a in solution.answers if a.name == "M")
    expected = 100 / 32.2 * 0.75**2 * 10 * 3.141592653589793 / 2
    assert float(M.value) == pytest.approx(expected, rel=1e-9)
    senses = [a for a in solution.assumptions if a.name == "sense of couple M"]
    assert not senses[0].holds and "it acts cw" in senses[0].detail
    assert senses[-1].holds and "cw" in senses[-1].detail
    assert solution.passed  # re-solved the right way; said so in the assumptions


@pytest.mark.parametrize("mode", MODES)
def test_a_couple_stated_the_right_way_is_kept(mode: str) -> None:
    # stated cw: M = I_O ω₁/Δt = 27.44 lb·ft as stated, no re-solve.
    solution = solve_text(FLYWHEEL.format(sense="cw"), options=SolveOptions(mode=mode))
    M = next(a for a in solution.answers if a.name == "M")
    assert float(M.value) == pytest.approx(100 / 32.2 * 0.5625 * 31.41592653589793 / 2, rel=1e-9)
    (sense,) = [a for a in solution.assumptions if a.name == "sense of couple M"]
    assert sense.holds and "re-solved" not in sense.detail


PILE = """given:
  m_r = 800 kg
  m_p = 1200 kg
  h = 1.5 m
  d = 0.1549967 m
scene:
  body ram: particle, mass m_r, at (0, h)
  body pile: particle, mass m_p, at (0, -h)
  force R on pile at G: down
  gravity
  travel ram: by h, down
  impact ram with pile: e 0, line down
  travel pile: by d, down, stops
find: R [kN]
"""


@pytest.mark.parametrize("mode", MODES)
def test_a_soil_resistance_stated_down_acts_up(mode: str) -> None:
    # problems/stages/pile_driver.dyn with the resistance's size unknown, its penetration
    # given and its sense stated down: v_2 = √(2 g h) = 5.42494 m/s, v_3 = m_r v_2/(m_r + m_p)
    # = 2.16998 m/s; over d: ½(2000)(2.16998²) + 2000 g d + R d = 0 with R down-positive,
    # R = −(4708.8 + 3041.04)/0.1549967 = −50.0 kN: it acts up, 50.0 kN.
    solution = solve_text(PILE, options=SolveOptions(mode=mode))
    R = next(a for a in solution.answers if a.name == "R")
    assert float(R.value) == pytest.approx(50.0, rel=1e-5)
    senses = [a for a in solution.assumptions if a.name == "sense of force R"]
    assert not senses[0].holds and "it acts up" in senses[0].detail
    assert senses[-1].holds


@pytest.mark.parametrize("mode", MODES)
def test_a_linkage_couple_stated_the_wrong_way_fails_its_check(mode: str) -> None:
    # problems/linkages/slider_crank_forces.dyn needs M = 20.5 N·m ccw (its key); stated cw,
    # the solve gives M = −20.5 N·m: a failed check that says it acts ccw, never green.
    text = (ROOT / "problems" / "linkages" / "slider_crank_forces.dyn").read_text()
    text = text.replace("couple M on AB: ccw", "couple M on AB: cw").split("answers:")[0]
    solution = solve_text(text, options=SolveOptions(mode=mode))
    (sense,) = [c for c in solution.checks if c.name == "sense of couple M"]
    assert not sense.passed and "it acts ccw" in sense.detail
    assert not solution.passed
