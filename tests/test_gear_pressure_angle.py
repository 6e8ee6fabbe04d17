"""Gears in mesh with a pressure angle: the tooth force along the line of action, its
radial part |F_t| tan φ parting the gears whichever way F_t turns them.

Hand derivation (problems/linkages/gears_pressure_angle.dyn): gears on fixed pins,
r_A = 0.1 m, r_B = 0.2 m, I_A = 0.064 kg·m², I_B = 0.9 kg·m², a couple M on A from rest:
α_A = M/(I_A + I_B r_A²/r_B²) = M/0.289, α_B = α_A r_A/r_B, F_t = I_B α_B/r_B; the radial
part F_r = |F_t| tan φ pushes B away from A (+x), so B's bearing holds B_x = −F_r and
B_y = −(the tangential part on B, +F_t ccw-sense up for M ccw): |R_B| = |F_t|/cos φ.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynsolve.pipeline import solve_file, solve_text
from dynsolve.system import SolveOptions

PROBLEMS = Path(__file__).parent.parent / "problems" / "linkages"
SPEC = PROBLEMS / "gears_pressure_angle.dyn"


def by_hand(M: float, phi_deg: float) -> tuple[float, float, float]:
    """(α_A ccw, F_t magnitude, F_r) for the bundled gears with a ccw couple M."""
    alpha_A = M / (0.064 + 0.9 * 0.1**2 / 0.2**2)
    F_t = 0.9 * (alpha_A * 0.1 / 0.2) / 0.2
    return alpha_A, abs(F_t), abs(F_t) * math.tan(math.radians(phi_deg))


def variant(sense: str = "ccw", phi: str = "20 deg", M: str = "20 N*m") -> str:
    text = SPEC.read_text().split("answers:")[0]
    text = text.replace("couple M on gearA: ccw", f"couple M on gearA: {sense}")
    text = text.replace("phi = 20 deg", f"phi = {phi}").replace("M = 20 N*m", f"M = {M}")
    return text.replace("find: alpha_A", "find: B_x, B_y, A_x, alpha_A")


@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_the_bundled_gears_by_hand(mode):
    solution = solve_file(SPEC, SolveOptions(mode=mode))
    assert not any(c.failed for c in solution.checks)
    assert any(c.name.startswith("pressure angle") for c in solution.checks)
    found = {a.name: a for a in solution.answers}
    alpha_A, F_t, F_r = by_hand(20.0, 20.0)
    assert alpha_A == pytest.approx(69.204, rel=1e-4)
    assert F_r == pytest.approx(56.674, rel=1e-4)
    assert found["alpha_A"].value == pytest.approx(alpha_A, rel=1e-12)
    assert found["F_t"].value == pytest.approx(F_t, rel=1e-12)
    for name in ("R_A", "R_B"):
        assert found[name].value == pytest.approx(F_t / math.cos(math.radians(20)), rel=1e-12)


@pytest.mark.parametrize("sense", ["ccw", "cw"])
def test_the_radial_part_parts_the_gears_whichever_way_they_turn(sense):
    """M ccw: F_t on A points down (first solve assumes F ≥ 0, finds it negative and
    re-solves); M cw: up. Either way B's bearing pulls B back toward A: B_x = −F_r, and
    A's pushes A toward B: A_x = +F_r."""
    solution = solve_text(variant(sense), "gears.dyn")
    assert not any(c.failed for c in solution.checks)
    found = {a.name: a for a in solution.answers}
    _, F_t, F_r = by_hand(20.0, 20.0)
    assert found["B_x"].value == pytest.approx(-F_r, rel=1e-12)
    assert found["A_x"].value == pytest.approx(F_r, rel=1e-12)
    assert abs(found["B_y"].value) == pytest.approx(F_t, rel=1e-12)
    assert found["B_y"].value * (1 if sense == "cw" else -1) > 0


def test_ideal_teeth_have_no_radial_part():
    found = {a.name: a for a in solve_text(variant(phi="0 deg"), "ideal.dyn").answers}
    assert found["B_x"].value == pytest.approx(0, abs=1e-12)


@settings(max_examples=6, deadline=None)
@given(phi=st.integers(10, 30), M=st.integers(-50, 50).filter(bool))
def test_any_pressure_angle_and_couple(phi, M):
    text = variant(phi=f"{phi} deg", M=f"{M} N*m")
    solution = solve_text(text, "gears.dyn", SolveOptions(mode="numeric"))
    assert not any(c.failed for c in solution.checks)
    found = {a.name: a for a in solution.answers}
    alpha_A, F_t, F_r = by_hand(float(M), float(phi))
    assert found["B_x"].value == pytest.approx(-F_r, rel=1e-9)
    assert abs(found["B_y"].value) == pytest.approx(F_t, rel=1e-9)
    signed = found["alpha_A"].value * (1 if found["alpha_A"].direction == "ccw" else -1)
    assert signed == pytest.approx(alpha_A, rel=1e-9)


def test_graded_variants_decide_the_radial_push_per_variant():
    """A student's variant (M = 22 N·m, φ = 18°): the expected answers come from the full
    solve with its re-solve, not a closed form of the first trial (whose radial push had
    the wrong sense): R_A at atan(F_t/F_r) = 90° − φ = 72° above the horizontal, right."""
    from dynsolve.grade.expected import expected_answers
    from dynsolve.spec.parser import parse_file

    result = expected_answers(
        parse_file(SPEC), {"s1": {"M": "22 N*m", "phi": "18 deg"}}, SolveOptions()
    )
    R_A = result["s1"].answers["R_A"]
    _, F_t, _ = by_hand(22.0, 18.0)
    assert R_A.value == pytest.approx(F_t / math.cos(math.radians(18)), rel=1e-9)
    assert R_A.direction == "72.0° above the horizontal, to the right"


RING = """given:
  r_R = 0.3 m
  r_P = 0.1 m
  m_R = 8 kg
  m_P = 1 kg
  M = 5 N*m
  phi = 20 deg
scene:
  point O: (0, 0)
  point Q: (r_R - r_P, 0)
  bar ring: O, mass m_R
  bar pinion: Q, mass m_P
  mesh ring with pinion: radii r_R, r_P, internal, pressure angle phi
  couple M on pinion: ccw
  omega pinion: 0
find: O_x, Q_x, F = F_ring_pinion, a = alpha(pinion)
"""


def test_a_pinion_inside_a_ring_gear():
    """Ring (0.3 m, 8 kg, I_R = 0.36) and pinion (0.1 m, 1 kg, I_P = 0.005) on fixed pins,
    the pitch point at (0.3, 0), M = 5 N·m ccw on the pinion, from rest. Internal mesh:
    α_R r_R = α_P r_P (same sense); F r_R = I_R α_R, M − F r_P = I_P α_P →
    α_P = M/(I_P + I_R r_P²/r_R²) = 111.11 rad/s², F = I_R α_P r_P/r_R² = 44.444 N;
    F_r = F tan 20° = 16.176 N pushes the pinion toward its centre (−x) and the ring
    outward (+x): the pinion's bearing Q_x = +F_r, the ring's O_x = −F_r."""
    found = {a.name: a for a in solve_text(RING, "ring.dyn").answers}
    alpha_P = 5 / (0.005 + 0.36 * 0.1**2 / 0.3**2)
    F = 0.36 * alpha_P * 0.1 / 0.3**2
    F_r = F * math.tan(math.radians(20))
    assert found["a"].value == pytest.approx(alpha_P, rel=1e-12)
    assert found["F"].value == pytest.approx(F, rel=1e-12)
    assert found["Q_x"].value == pytest.approx(F_r, rel=1e-12)
    assert found["O_x"].value == pytest.approx(-F_r, rel=1e-12)
