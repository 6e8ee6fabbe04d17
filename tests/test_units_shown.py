"""A step's numbers are in the units it shows, and every value a check or an assumption
states has its unit (issue 25 item 13): `sqrt(4.762^2 + 7.937^2) = 33.3 km/h` read m/s
numbers as km/h; `10.47*12^2/2 + 31.42*12 = 180 rev` summed radians; an FPS slide "moved
at 20 m/s"; `T = 19.77 ≥ 0` and `relative acceleration 23.78` had no unit at all.
"""

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.pipeline import solve_file, solve_text
from dynsolve.render.json import render_json
from dynsolve.render.latex import render_latex
from dynsolve.render.markdown import render_markdown
from dynsolve.system import SolveOptions

PROBLEMS = Path(__file__).parent.parent / "problems"

CONVERTED = """\
given:
  v_x = 4.762 m/s
  v_y = 7.937 m/s
  alpha = 10.47 rad/s^2
  omega_0 = 31.42 rad/s
  t = 12 s
equations:
  v = sqrt(v_x^2 + v_y^2)
  n = alpha*t^2/2 + omega_0*t
find: v [km/h], n [rev]
"""


def _row(solution, name):
    return next(r for s in solution.steps for r in s.results if r.name == name)


@pytest.mark.parametrize("mode", ["exact", "numeric", "auto"])
def test_a_hand_calculation_in_base_units_states_its_value_in_them_before_converting(mode):
    # v = √(4.762² + 7.937²) = √(22.677 + 62.996) = √85.673 = 9.256 m/s = 33.32 km/h;
    # n = 10.47·12²/2 + 31.42·12 = 753.84 + 377.04 = 1130.88 rad = 1130.88/(2π) = 179.99 rev
    solution = solve_text(CONVERTED, "converted.dyn", SolveOptions(mode=mode))
    v, n = _row(solution, "v"), _row(solution, "n")
    assert mode != "exact" or v.substituted  # exact mode puts the numbers in
    if not v.substituted:  # solved in floats (numeric; auto here): the value stands alone
        assert (v.value, n.value) == ("33.3 km/h", "180 rev")
    else:
        assert v.substituted == "sqrt(4.762^2 + 7.937^2)"
        assert v.value == "9.26 m/s = 33.3 km/h"
        assert n.value == "1131 rad = 180 rev"
        assert "9.26\\,\\mathrm{m/s} = 33.3\\,\\mathrm{km/h}" in v.value_latex
    assert [a.shown for a in solution.answers] == ["33.3 km/h", "180 rev"]


def test_every_format_shows_the_value_in_the_units_of_its_numbers(tmp_path):
    path = tmp_path / "converted.dyn"
    path.write_text(CONVERTED)
    solution = solve_file(path)
    terminal = CliRunner().invoke(app, ["solve", str(path)], env={"COLUMNS": "200"}).output
    assert "sqrt(4.762^2 + 7.937^2) = 9.26 m/s = 33.3 km/h" in terminal
    assert "9.26\\,\\mathrm{m/s} = 33.3\\,\\mathrm{km/h}" in render_markdown(solution)
    assert "\\qty{9.26}{m/s} = \\qty{33.3}{km/h}" in render_latex(solution)
    steps = json.loads(render_json(solution))["steps"]
    assert {r["value"] for s in steps for r in s["results"]} >= {"9.26 m/s = 33.3 km/h"}


def test_a_step_already_in_the_asked_unit_is_not_repeated():
    # a_G asked in m/s² (the base unit): "= 4.52 m/s²" once, not "4.52 m/s² = 4.52 m/s²"
    text = "given:\n  F = 9.04 N\n  m = 2 kg\nequations:\n  a = F/m\nfind: a [m/s^2]\n"
    assert _row(solve_text(text), "a").value == "4.52 m/s²"


FPS_SLIDE = """\
units: FPS
given:
  W = 10 lb
  v_1 = 20 ft/s
  mu_k = 0.25
scene:
  body block: particle, weight W
  contact block at G: normal up, mu_k mu_k
  velocity block: v_1, right
  gravity
find: a = a_G(block) [ft/s^2]
"""


def test_an_fps_slide_states_its_speed_in_feet_per_second():
    # the block slides at the given 20 ft/s; N = W = 10 lb; a = μk g = 0.25 · 32.2 = 8.05 ft/s²
    solution = solve_text(FPS_SLIDE, "fps.dyn")
    assert solution.answers[0].value == pytest.approx(8.05, rel=1e-9)
    details = {a.name: a.detail for a in solution.assumptions}
    assert details["sliding at G"].startswith("its contact point moves at 20 ft/s along")
    assert details["contact at G kept"] == "N_G = 10 lb ≥ 0"
    checks = {c.name: c.detail for c in solution.checks}
    assert checks["assumption: contact at G kept"] == "N_G = 10 lb ≥ 0"


def test_a_slip_check_states_its_relative_acceleration_with_its_unit():
    # spring_launch_rough_floor at release: a = (k δ − μk m g)/m = (160 − 3.924)/2
    # = 78.04 m/s²; friction needed 160 N > μk N = 0.2 · 19.62 = 3.924 N
    solution = solve_file(PROBLEMS / "scenes" / "spring_launch_rough_floor.dyn")
    details = {a.name: a.detail for a in solution.assumptions}
    assert details["slip at G"].endswith("(relative acceleration 78.04 m/s²)")
    assert details["no slip at G"].startswith("|F| = 160 N > μk N = 3.924 N")
    assert details["contact at G kept"] == "N_G = 19.62 N ≥ 0"


def test_a_kinematics_event_states_its_value_with_its_unit():
    # a = −k v^(1/3): t = 3 (v_0^(2/3) − v_1^(2/3))/(2k) = 3 (4.641589 − 2.924018)/1 = 5.15271 s
    spec = "given:\n  k = 0.5 m^(2/3)*s^(-5/3)\n  v_0 = 10 m/s\n  v_1 = 5 m/s\n"
    spec += "kinematics:\n  a = -k*v^(1/3)\nfind: t_2 = t_at(v, v_1) [min]\n"
    solution = solve_text(spec, "event.dyn")
    assert _row(solution, "t_2").value == "5.15271 s"  # the numbers' unit; answers: min
    assert solution.answers[0].shown == "0.0859 min"  # 5.15271/60


def test_a_stage_chain_states_energies_and_closing_speeds_with_their_units():
    # pile_driver: the ram falls h = 1.5 m: T1 + ΣU = m_r g h = 800 · 9.81 · 1.5 = 11772 J;
    # it strikes the pile at √(2 g h) = 5.425 m/s; T4 = 0 where the pile stops
    solution = solve_file(PROBLEMS / "stages" / "pile_driver.dyn")
    details = {a.name: a.detail for a in solution.assumptions}
    assert details["reaches state 2"] == "T1 + ΣU = 1.177e+04 J ≥ 0"
    assert details["approach in stage 2"] == "before the impact (v_A − v_B)·n = 5.425 m/s > 0"
    assert details["at rest in state 4"] == "T4 = T3 + ΣU = 0 J"
