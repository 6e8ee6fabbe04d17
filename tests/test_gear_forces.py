"""Forces between gears in mesh (issue 11, part 1: "gear-tooth forces"): the tooth force
F_A_B along the common tangent at the pitch point, on gear A, and its opposite on B.

Hand derivations (ideal teeth, no pressure angle):
- gears on fixed pins, I_A = 0.064, I_B = 0.9 kg·m², r_A = 0.1, r_B = 0.2 m, M = 20 N·m on A:
  M = α_A (I_A + I_B r_A²/r_B²) → α_A = 69.204 rad/s² ccw, α_B = 34.602 cw, F = 155.71 N
  (problems/linkages/gears_couple_tooth_force.dyn, and its FPS twin gears_couple_fps.dyn);
- the couple for α_A = 10 rad/s²: F = I_B α_B/r_B = 22.5 N, M = I_A α_A + F r_A = 2.89 N·m;
- a planet gear (2 kg, r_P = 50 mm, a disk) on a 1-kg uniform arm (150 mm) about a fixed sun
  (r_S = 100 mm, held by a couple C), the arm driven by M = 3 N·m from rest: ω_P = 3 ω_arm,
  T = ½ ω_arm² (m_arm L²/3 + m_P L² + 9 I_P) = ½ ω_arm² × 0.075 → α_arm = 40 rad/s²;
  planet: F r_P = I_P α_P = 0.0025 × 120 → F = 6 N; sun: C = −F r_S = −0.6 N·m.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from dynsolve.pipeline import solve_file, solve_text

LINKAGES = Path(__file__).parent.parent / "problems" / "linkages"


def found(solution) -> dict[str, tuple[float, str]]:
    return {a.name: (a.value, a.direction) for a in solution.answers}


@pytest.mark.parametrize("name", ["gears_couple_tooth_force", "gears_couple_fps"])
def test_two_gears_driven_by_a_couple(name):
    solution = solve_file(LINKAGES / f"{name}.dyn")
    assert not any(c.failed for c in solution.checks)
    moments = [e.text for e in solution.equations if "ΣM_G" in e.note]
    assert moments[0].startswith("F_gearA_gearB*r_A + M")  # M − F r_A = I_A α, as by hand
    assert moments[1].startswith("F_gearA_gearB*r_B")


def test_the_couple_a_required_acceleration_needs():
    got = found(solve_file(LINKAGES / "gears_couple_needed.dyn"))
    assert got["M"][0] == pytest.approx(0.064 * 10 + 22.5 * 0.1, rel=1e-12)
    assert got["F"][0] == pytest.approx(22.5, rel=1e-12)


PLANET = """\
given:
  r_S = 100 mm
  r_P = 50 mm
  m_P = 2 kg
  m_arm = 1 kg
  M = 3 N*m
scene:
  point O: (0, 0)
  bar sun: O
  bar arm: O to B, mass m_arm
  bar planet: B, mass m_P
  joint B: (r_S + r_P, 0)
  mesh sun with planet: radii r_S, r_P
  omega sun: 0
  alpha sun: 0
  omega arm: 0
  couple M on arm: ccw
  couple C on sun: ccw
find: alpha_arm = alpha(arm), F = F_sun_planet, C
"""


def test_a_planet_gear_on_an_arm_round_a_held_sun():
    got = found(solve_text(PLANET))
    assert got["alpha_arm"] == (pytest.approx(40.0, rel=1e-12), "ccw")
    assert got["F"][0] == pytest.approx(6.0, rel=1e-12)
    assert got["C"][0] == pytest.approx(-0.6, rel=1e-12)  # cw: the sun is held against F


# ---- internal gears (a ring gear). Hand derivations:
# - fixed ring 150 mm, sun 50 mm at 10 rad/s ccw, planet 50 mm: ω_P = 5 cw, ω_arm = 2.5 ccw
#   (problems/linkages/planetary_ring_fixed.dyn; the sun held and the ring driven, and an
#   FPS arm-driven planet: planetary_sun_fixed.dyn, ring_planet_arm_fps.dyn);
# - a 2-kg disk planet (r_P = 50 mm) inside a held ring (r_R = 150 mm) on a 1-kg, 100-mm
#   arm driven by M = 3 N·m from rest: ω_P = −2 ω_arm, T = ½ ω_arm² (m L²/3 + m_P L² +
#   4 I_P) = ½ ω_arm² / 30 → α_arm = 90 rad/s²; planet: −r_P F = I_P α_P = −0.45 → F = 9 N;
#   ring: C + r_R F = 0 → C = −1.35 N·m.

RING = """\
given:
  r_R = 150 mm
  r_P = 50 mm
  m_P = 2 kg
  m_arm = 1 kg
  M = 3 N*m
scene:
  point O: (0, 0)
  bar ring: O
  bar arm: O to B, mass m_arm
  bar planet: B, mass m_P
  joint B: (r_R - r_P, 0)
  mesh ring with planet: radii r_R, r_P, internal
  omega ring: 0
  alpha ring: 0
  omega arm: 0
  couple M on arm: ccw
  couple C on ring: ccw
find: alpha_arm = alpha(arm), alpha_P = alpha(planet), F = F_ring_planet, C
"""


@pytest.mark.parametrize(
    "name", ["planetary_ring_fixed", "planetary_sun_fixed", "ring_planet_arm_fps"]
)
def test_planetary_trains_with_a_ring_gear(name):
    solution = solve_file(LINKAGES / f"{name}.dyn")
    assert not any(c.failed for c in solution.checks)
    assert any("internal mesh" in e.note for e in solution.equations)


def test_a_planet_driven_round_inside_a_held_ring():
    got = found(solve_text(RING))
    assert got["alpha_arm"] == (pytest.approx(90.0, rel=1e-12), "ccw")
    assert got["alpha_P"] == (pytest.approx(180.0, rel=1e-12), "cw")
    assert got["F"][0] == pytest.approx(9.0, rel=1e-12)
    assert got["C"][0] == pytest.approx(-1.35, rel=1e-12)


def test_an_internal_mesh_with_its_centres_the_sum_apart_is_refused():
    from dynsolve.errors import SpecError

    text = RING.replace("joint B: (r_R - r_P, 0)", "joint B: (r_R + r_P, 0)")
    with pytest.raises(SpecError, match="their radii differ by"):
        solve_text(text)
