"""`method ic` where a bar translates at the instant: its instantaneous centre is at
infinity (Hibbeler 16.6: the normals to two of its points' velocities are parallel, so
ω = 0 and every point moves alike), and the degenerate cases that are still refused.

Hand derivations:
- four-bar, AB = 0.2 m and DC = 0.3 m both vertical, A and D 0.5 m apart, ω_AB = 6 rad/s
  ccw (problems/linkages/ic_translating_coupler.dyn): ω_BC = 0, v_C = v_B = 6 × 0.2 =
  1.2 m/s left, ω_DC = 1.2/0.3 = 4 rad/s ccw; with the crank at any angle φ and DC parallel
  to it the same holds: ω_DC = ω_AB L_AB / L_DC;
- crank AB = 0.15 m horizontal at 8 rad/s cw, rod BC = 0.25 m, block C in a vertical guide
  through A: v_B = (0, −1.2) m/s, v_C vertical, so BC translates: ω_BC = 0, v_C = 1.2 m/s
  down.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file, solve_text
from dynsolve.system import SolveOptions

PROBLEMS = Path(__file__).parent.parent / "problems" / "linkages"


def values(solution) -> dict[str, tuple[float, str]]:
    return {a.name: (a.value, a.direction) for a in solution.answers}


@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_a_coupler_that_translates_has_its_ic_at_infinity(mode):
    solution = solve_file(PROBLEMS / "ic_translating_coupler.dyn", SolveOptions(mode=mode))
    assert not any(c.failed for c in solution.checks)
    found = values(solution)
    assert found["w_BC"][0] == 0
    assert found["w_CD"][0] == pytest.approx(4.0, rel=1e-12) and found["w_CD"][1] == "ccw"
    assert found["v_C"][0] == pytest.approx(1.2, rel=1e-12) and found["v_C"][1] == "left"
    check = next(c for c in solution.checks if c.name == "relative velocity")
    assert check.passed  # v_C = v_B + ω_BC × r_C/B with ω_BC = 0, put back
    stated = next(g for g in solution.givens if g.name == "omega_BC")
    assert "infinity" in stated.description and "translates" in stated.description


SLIDER = """given:
  L_AB = {L_AB} m
  L_BC = 0.25 m
  omega_0 = 8 rad/s
{extra_given}scene:
  point A: (0, 0)
  bar AB: A to B, length L_AB, angle 0
  bar BC: B to C, length L_BC
  slider C: along up, through A
  joint C: near (0, L_BC)
  omega AB: omega_0 cw
{extra}  method ic
find: w_BC = omega(BC), v_C = v(C)
"""


def test_a_rod_that_translates_moves_its_piston_with_the_crank_pin():
    text = SLIDER.format(L_AB=0.15, extra_given="", extra="")
    solution = solve_text(text, "slider.dyn")
    assert not any(c.failed for c in solution.checks)
    found = values(solution)
    assert found["w_BC"][0] == 0
    assert found["v_C"][0] == pytest.approx(1.2, rel=1e-12) and found["v_C"][1] == "down"
    assert any("IC at infinity" in row.note for row in solution.equations)


def test_a_translating_rod_whose_points_are_given_different_speeds_is_refused():
    """v_B = 1.2 m/s by the crank, v_C = 2 m/s given: BC cannot translate with both."""
    text = SLIDER.format(
        L_AB=0.15, extra_given="  v_0 = 2 m/s\n", extra="  velocity C: v_0, down\n"
    )
    with pytest.raises(SpecError) as error:
        solve_text(text, "overdriven.dyn")
    message = str(error.value)
    assert "translates" in message and "inconsistent" in message
    assert "speeds 2 and 1.2" in message


def test_normals_on_one_line_are_refused_with_the_reason():
    """A, B, C, D on one vertical line (a toggle): the normals to v_B and v_C are the same
    line, so directions alone cannot place the IC."""
    text = """given:
  L = 0.2 m
  omega_0 = 6 rad/s
  up = 90 deg
scene:
  point A: (0, 0)
  point D: (0, 3*L)
  bar AB: A to B, length L, angle up
  bar BC: B to C, length L
  bar CD: D to C, length L, angle -up
  omega AB: omega_0 ccw
  method ic
find: w_BC = omega(BC)
"""
    with pytest.raises(SpecError) as error:
        solve_text(text, "in_line.dyn")
    assert "one line" in str(error.value)
    assert error.value.position.line == 9  # the bar BC


def test_a_driven_bar_that_would_translate_is_refused():
    text = (PROBLEMS / "ic_translating_coupler.dyn").read_text()
    text = text.replace("  method ic", "  omega BC: omega_0 ccw\n  method ic")
    with pytest.raises(SpecError) as error:
        solve_text(text, "driven_coupler.dyn")
    assert "translates" in str(error.value)


@settings(max_examples=8, deadline=None)
@given(
    degrees=st.integers(20, 160),
    L_AB=st.integers(10, 40),
    L_CD=st.integers(10, 40),
    w=st.integers(1, 20),
)
def test_parallel_crank_and_rocker_at_any_angle(degrees, L_AB, L_CD, w):
    """AB and DC parallel at φ (lengths in cm, D 0.5 m right of A): the normals (the lines
    AB and DC) are parallel and distinct, so ω_BC = 0 and ω_DC = ω_AB L_AB / L_DC, same
    sense; v_C = ω_AB L_AB."""
    text = (PROBLEMS / "ic_translating_coupler.dyn").read_text().split("answers:")[0]
    text = text.replace("L_AB = 0.2 m", f"L_AB = {L_AB} cm").replace(
        "L_CD = 0.3 m", f"L_CD = {L_CD} cm"
    )
    text = text.replace("omega_0 = 6 rad/s", f"omega_0 = {w} rad/s")
    text = text.replace("up = 90 deg", f"up = {degrees} deg")
    solution = solve_text(text, "parallel.dyn", SolveOptions(mode="numeric"))
    assert not any(c.failed for c in solution.checks)
    found = values(solution)
    assert found["w_BC"][0] == 0
    assert found["w_CD"][0] == pytest.approx(w * L_AB / L_CD, rel=1e-9)
    assert found["w_CD"][1] == "ccw"
    assert found["v_C"][0] == pytest.approx(w * L_AB / 100, rel=1e-9)
    assert math.isfinite(found["v_C"][0])


def test_the_heavy_block_linkage_by_instantaneous_centres():
    """problems/linkages/piston_vertical_guide.dyn (its header's hand derivation) with
    `method ic`: the rod BC translates at the instant (crank square to the guide), and the
    forces come out as by relative velocity: M = 0.15 B_y, B_y = 2 (3.6 + 9.81) + C_y,
    C_y = 3 (9.81 + 7.2)."""
    text = (PROBLEMS / "piston_vertical_guide.dyn").read_text()
    solution = solve_text(text.replace("  gravity\n", "  gravity\n  method ic\n"), "ic.dyn")
    assert not any(c.failed for c in solution.checks)
    found = values(solution)
    C_y = 3 * (9.81 + 7.2)
    assert found["M"][0] == pytest.approx(0.15 * (2 * (3.6 + 9.81) + C_y), rel=1e-9)
    assert found["alpha_BC"] == (pytest.approx(48, rel=1e-12), "cw")


def test_the_centre_of_a_translating_bar_is_not_asked_for_a_number():
    text = (PROBLEMS / "ic_translating_coupler.dyn").read_text().split("find:")[0]
    with pytest.raises(SpecError) as error:
        solve_text(text + "find: x = x_IC(BC)\n", "centre.dyn")
    assert "at infinity" in str(error.value)
    assert error.value.position.column > 1
