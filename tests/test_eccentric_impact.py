"""A rigid body striking a fixed point and turning about it (scene mode: `impact B at P`)."""

import math
from pathlib import Path

import pytest

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file

CUBE = """\
given:
  a = 0.25 m
  M = 8 kg
  v = {v}
scene:
  point B: (0, 0)
  body cube: mass M, block 2*a by 2*a, at (-a, a)
  velocity cube: v, {sense}
  gravity
  impact cube at B: e {e}
find: omega_1 = omega_after(cube)
"""


def solve(tmp_path: Path, v: str = "3 m/s", sense: str = "right", e: str = "0"):
    path = tmp_path / "cube.dyn"
    path.write_text(CUBE.format(v=v, sense=sense, e=e))
    return solve_file(path)


def test_angular_momentum_about_the_lip_is_kept(tmp_path):
    # H_B = M v a (G is a above B) = I_B ω₁, I_B = (2/3) M a² + M (√2 a)² = (8/3) M a²:
    # ω₁ = 3 v/(8 a) = 9/2 = 4.5 rad/s, turning the way the cube was going (cw)
    solution = solve(tmp_path)
    (answer,) = solution.answers
    assert answer.value == pytest.approx(4.5, rel=1e-12)
    assert answer.direction == "cw"
    assert "angular momentum of cube about B conserved" in solution.equations[0].note


def test_the_same_in_fps(tmp_path):
    # 3 m/s = 9.8425 ft/s: ω₁ does not depend on the units the speed is given in
    solution = solve(tmp_path, v=f"{3 / 0.3048!r} ft/s")
    assert solution.answers[0].value == pytest.approx(4.5, rel=1e-9)


def test_an_impact_about_a_point_with_e_above_zero_needs_its_line(tmp_path):
    # e > 0 is a rebound off the point (issue 8): it needs the line of impact
    with pytest.raises(SpecError) as caught:
        solve(tmp_path, e="0.5")
    assert "needs its line of impact" in caught.value.message
    assert caught.value.position.line == 10


def test_the_struck_point_must_be_a_fixed_point(tmp_path):
    path = tmp_path / "cube.dyn"
    path.write_text(CUBE.format(v="3 m/s", sense="right", e="0").replace("at B: e", "at Q: e"))
    with pytest.raises(SpecError, match="no fixed point 'Q'"):
        solve_file(path)


def test_an_unknown_speed_must_be_asked_for(tmp_path):
    # 'v_x' is neither a given nor in find: it is a typo, not an unknown
    path = tmp_path / "cube.dyn"
    path.write_text(CUBE.format(v="3 m/s", sense="right", e="0").replace("cube: v,", "cube: v_x,"))
    with pytest.raises(SpecError, match="'v_x' in the scene is not a given"):
        solve_file(path)


def test_the_cube_that_just_tips_over(tmp_path):
    # ½ I_B ω₁² = M g a (√2 − 1) with ω₁ = 3 v/(8 a): v = 4 sqrt(a g (√2 − 1)/3)
    seed = Path(__file__).resolve().parent.parent / "problems" / "seed" / "ci_seed_cube_lip.dyn"
    solution = solve_file(seed)
    v_min, omega_1 = solution.answers
    a, g = 0.25, 9.81
    assert v_min.value == pytest.approx(4 * math.sqrt(a * g * (math.sqrt(2) - 1) / 3), rel=1e-12)
    assert omega_1.value == pytest.approx(3 * v_min.value / (8 * a), rel=1e-12)
    assert any(c.name == "assumption: plastic impact at B" and c.passed for c in solution.checks)
