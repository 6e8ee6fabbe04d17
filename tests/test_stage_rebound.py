"""A rebound off a fixed point (``impact B at P: e E, line DIR``) chained after other
stages: a rod that falls without turning (``motion rod: translation``), then strikes a
ledge with one end. Hand results (problems/stages/rod_falls_rebounds.dyn): with a rod of
mass m, length L struck at its end, J (1/m + L²/(4 I_G)) = (1 + e) v, so for a slender
rod J = (1 + e) m v/4, v_G after = −v + J/m, ω = 6 J/(m L).
"""

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file

G = 9.81
ROD = """\
given:
  m = {m}
  L = {L}
  h = {h}
  e = {e}
scene:
  point P: (L/2, 0)
  body rod: mass m, rod L, at (0, h)
  motion rod: translation
  gravity
  travel rod: by h, down
  impact rod at P: e e, line down
find: v_3 = v_after(rod), omega_3 = omega_after(rod), J_P, T_2 = T(2), T_3 = T(3)
"""


def solve(tmp_path: Path, text: str):
    path = tmp_path / "rebound.dyn"
    path.write_text(text)
    return solve_file(path)


def answers(solution) -> dict:
    return {a.name: a for a in solution.answers}


def test_the_bundled_rod_meets_its_hand_derivation():
    path = Path(__file__).parent.parent / "problems" / "stages" / "rod_falls_rebounds.dyn"
    solution = solve_file(path)
    assert not any(c.failed for c in solution.checks)
    got = answers(solution)
    v_2 = math.sqrt(2 * G * 0.5)
    assert got["J_P"].value == pytest.approx(0.75 * v_2, rel=1e-9)
    assert got["omega_3"].value == pytest.approx(2.25 * v_2, rel=1e-9)
    assert got["omega_3"].direction == "ccw"


@settings(max_examples=8, deadline=None)
@given(
    m=st.floats(0.2, 20.0),
    L=st.floats(0.2, 3.0),
    h=st.floats(0.05, 5.0),
    e=st.floats(0.0, 1.0).map(lambda x: round(x, 4)),
)
def test_the_fall_feeds_the_rebound_and_energy_never_grows(tmp_path_factory, m, L, h, e):
    text = ROD.format(m=f"{m!r} kg", L=f"{L!r} m", h=f"{h!r} m", e=repr(e))
    solution = solve(tmp_path_factory.mktemp("r"), text)
    assert not any(c.failed for c in solution.checks)
    got = answers(solution)
    v = math.sqrt(2 * G * h)  # the fall's speed is the impact's speed before
    J = (1 + e) * m * v / 4
    assert got["J_P"].value == pytest.approx(J, rel=1e-9)
    assert got["omega_3"].value == pytest.approx(6 * J / (m * L), rel=1e-9, abs=1e-12)
    assert got["T_3"].value <= got["T_2"].value * (1 + 1e-12)
    if e == 1.0:  # elastic: no energy lost
        assert got["T_3"].value == pytest.approx(got["T_2"].value, rel=1e-9)


def test_a_held_body_is_refused_for_a_rebound(tmp_path):
    text = """\
given:
  m = 2 kg
  L = 1 m
  v_1 = 2 m/s
scene:
  point P: (L, 0)
  point Q: (0, 0)
  body rod: mass m, rod L, at (0, 0)
  contact rod at Q: normal up, smooth
  velocity rod: v_1, right
  impact rod at P: e 0.5, line right
find: dE = energy_lost(1)
"""
    with pytest.raises(SpecError, match="rod is held"):
        solve(tmp_path, text)


def test_a_rod_moving_away_from_the_ledge_fails_the_strike_check(tmp_path):
    # the rod is thrown up past the ledge's line: at the "impact" its end moves away
    text = ROD.format(m="2 kg", L="1 m", h="0.5 m", e="0.5")
    text = text.replace("  e = 0.5\n", "  e = 0.5\n  v_1 = 5 m/s\n").replace(
        "  travel rod: by h, down\n", "  velocity rod: v_1, up\n  travel rod: by h, up\n"
    )
    solution = solve(tmp_path, text.replace("at (0, h)", "at (0, -h)"))
    strike = next(a for a in solution.assumptions if a.name == "rod strikes P in stage 2")
    assert not strike.holds
