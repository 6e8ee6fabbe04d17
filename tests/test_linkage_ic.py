"""Linkage velocities by instantaneous centres, `method ic` (issue 11, part 1: "the
derivation ... via the instantaneous centre where the user asks").

Hand derivations (IC method, Hibbeler 16.6), cited in each bundled file:
- slider-crank, AB = 75 mm at 60°, BC = 200 mm, 2000 rpm cw: IC of BC where line AB meets
  the vertical through C, r_B/IC = 378.319 mm, r_C/IC = 392.585 mm, ω_BC = 41.520 rad/s ccw,
  v_C = 16.300 m/s right;
- Hibbeler 12e Example 16.6 data (A down at 2 m/s in a vertical slot, B in a horizontal
  one, L = 0.2 m at 45°): IC at (x_B, y_A), ω = v_A/x_B = 14.142 rad/s ccw, v_B = 2 m/s;
- wheel (0.5 m, 4 rad/s cw, rolling) driving bar AB (1.5 m): the wheel's IC is its contact
  point, the bar's where line KA meets the vertical through B, ω_AB = 1.14652 rad/s ccw,
  v_B = 4.3928 m/s right.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file, solve_text

PROBLEMS = Path(__file__).parent.parent / "problems" / "linkages"


def values(solution) -> dict[str, tuple[float, str]]:
    return {a.name: (a.value, a.direction) for a in solution.answers}


def test_the_slider_crank_by_its_instantaneous_centre():
    solution = solve_file(PROBLEMS / "ic_slider_crank.dyn")
    found = values(solution)
    assert found["w_BC"][0] == pytest.approx(41.52046, rel=1e-6) and found["w_BC"][1] == "ccw"
    assert found["v_C"][0] == pytest.approx(16.30033, rel=1e-6) and found["v_C"][1] == "right"
    assert found["x_IC"][0] == pytest.approx(0.2266593, rel=1e-6)  # m
    assert found["y_IC"][0] == pytest.approx(0.3925855, rel=1e-6)
    derived = {g.name: g.base for g in solution.givens if g.name.startswith("r_")}
    assert derived == {"r_B_AB": "0.075 m", "r_B_BC": "0.3783 m", "r_C_BC": "0.3926 m"}
    notes = [e.note for e in solution.equations]
    assert "v_B = ω_AB r_B/IC(AB) = ω_BC r_B/IC(BC)" in notes
    assert "v_C = ω_BC r_C/IC(BC) (along the guide of C)" in notes
    checks = {c.name: c for c in solution.checks}
    assert checks["relative velocity"].passed  # the default method, as a second one
    assert not any(c.failed for c in solution.checks)


def test_blocks_in_slots_by_ic_state_the_centre_and_its_distances():
    solution = solve_file(PROBLEMS / "ic_blocks_in_slots.dyn")
    found = values(solution)
    assert found["omega"] == (pytest.approx(2 / (0.2 * math.cos(math.pi / 4))), "ccw")
    assert found["v_B"] == (pytest.approx(2.0), "right")
    written = {g.name: g.written for g in solution.givens}
    assert written["x_IC_AB"].startswith("= x_B") and written["y_IC_AB"].startswith("= y_A")
    assert written["r_A_AB"].startswith("= x_B") and written["r_B_AB"].startswith("= y_A")


def test_a_rolling_wheel_turns_about_its_contact_point():
    solution = solve_file(PROBLEMS / "ic_wheel_and_bar.dyn")
    found = values(solution)
    assert found["w_AB"] == (pytest.approx(1.146524, rel=1e-5), "ccw")
    assert found["v_B"] == (pytest.approx(4.39284, rel=1e-5), "right")
    wheel = {g.name: g.base for g in solution.givens if g.name.endswith("_wheel")}
    assert wheel["x_IC_wheel"] == wheel["y_IC_wheel"] == "0 m"  # the contact point K
    assert wheel["r_A_wheel"] == "0.9239 m"  # r_A/K = 0.92388 m


CRANK = """\
given:
  L_AB = 75 mm
  L_BC = 200 mm
  theta = {theta} deg
  n = 2000 rpm
scene:
  point A: (0, 0)
  bar AB: A to B, length L_AB, angle theta
  bar BC: B to C, length L_BC
  slider C: along right, through A
  joint C: near (L_BC, 0)
  omega AB: n cw
{method}
find: w_BC = omega(BC), v_C = v(C)
"""


@settings(max_examples=12, deadline=None)
@given(theta=st.floats(min_value=5, max_value=175).filter(lambda t: abs(t - 90) > 3))
def test_ic_and_relative_velocity_agree_at_any_crank_angle(theta):
    # the two methods of Hibbeler 16.5 and 16.6 on the same slider-crank; and by hand,
    # v_C = ω_AB L_AB (sin θ + cos θ tan φ) with sin φ = L_AB sin θ / L_BC (φ: rod angle)
    ic = solve_text(CRANK.format(theta=repr(theta), method="  method ic"))
    relative = solve_text(CRANK.format(theta=repr(theta), method=""))
    for a, b in zip(ic.answers, relative.answers, strict=True):
        assert (a.value, a.direction) == (pytest.approx(b.value, rel=1e-9), b.direction)
    t = math.radians(theta)
    phi = math.asin(0.075 * math.sin(t) / 0.2)
    v_C = 2000 * 2 * math.pi / 60 * 0.075 * (math.sin(t) + math.cos(t) * math.tan(phi))
    assert values(ic)["v_C"][0] == pytest.approx(abs(v_C), rel=1e-9)


def test_gears_in_mesh_are_refused_by_ic_with_the_way_out():
    text = (PROBLEMS / "planetary.dyn").read_text().replace("scene:\n", "scene:\n  method ic\n")
    with pytest.raises(SpecError, match="'method ic' does not take gears in mesh") as error:
        solve_text(text, "planetary.dyn")
    assert "without 'method ic'" in (error.value.hint or "")


def test_a_collar_on_a_moving_bar_is_refused_by_ic():
    text = (PROBLEMS / "quick_return.dyn").read_text().replace("scene:\n", "scene:\n  method ic\n")
    with pytest.raises(SpecError, match="sliding along the moving bar"):
        solve_text(text, "quick_return.dyn")


def test_an_unknown_method_is_a_parse_error_with_its_place():
    text = CRANK.format(theta="60", method="  method graphical")
    result = CliRunner().invoke(app, ["solve", "-"], input=text)
    assert result.exit_code == 2
    assert "<stdin>:13:10" in result.stderr  # where the method is written
    assert "ic (instantaneous centres) or relative" in result.stderr


def test_method_ic_through_the_cli():
    result = CliRunner().invoke(app, ["solve", str(PROBLEMS / "ic_slider_crank.dyn")])
    assert result.exit_code == 0, result.output
    assert "r_B/IC(BC)" in result.stdout and "41.5 rad/s" in result.stdout
