"""A rigid body striking a fixed point and turning about it (scene mode: `impact B at P`)."""

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file, solve_text

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


REBOUND = """\
given:
  m = {m} kg
  L = {L} m
  v_1 = {v_1} m/s
  e = {e}
  d = {d} m
scene:
  point P: (d, 0)
  body rod: mass m, rod L, at (0, 0)
  velocity rod: v_1, down
  impact rod at P: e e, line down
find: v_2 = v_after(rod) [m/s], omega_2 = omega_after(rod), J_P [N*s]
"""


@settings(max_examples=12, deadline=None)
@given(
    m=st.integers(1, 20),
    L=st.sampled_from(["0.5", "1", "2.4"]),
    v_1=st.integers(1, 10),
    e=st.sampled_from(["0", "0.25", "0.5", "1"]),
    share=st.sampled_from([0.25, 0.4, 0.5]),
)
def test_a_free_rod_striking_a_point_keeps_its_angular_momentum_about_it(
    tmp_path_factory, m, L, v_1, e, share
):
    # a rod falling flat (no spin) at v_1 strikes a fixed point a distance d from G, line of
    # impact vertical. By hand: J up at P, m Δv_G = J, I_G ω_2 = d J, v_P2 = e v_1 (up), so
    # J = (1 + e) v_1 / (1/m + d²/I_G) with I_G = m L²/12; and H_P = m d v_1 is kept.
    L_m, e_v = float(L), float(e)
    d = round(share * L_m, 6)
    path = tmp_path_factory.mktemp("rebound") / "rebound.dyn"
    path.write_text(REBOUND.format(m=m, L=L, v_1=v_1, e=e, d=d), encoding="utf-8")
    got = {a.name: a for a in solve_file(path).answers}
    I_G = m * L_m**2 / 12
    J = (1 + e_v) * v_1 / (1 / m + d**2 / I_G)
    v_2y = -v_1 + J / m  # up positive
    omega_2 = d * J / I_G  # ccw positive
    signed_v = got["v_2"].value * (1 if got["v_2"].direction == "up" else -1)
    signed_w = got["omega_2"].value * (1 if got["omega_2"].direction == "ccw" else -1)
    assert got["J_P"].value == pytest.approx(J, rel=1e-9)
    assert signed_v == pytest.approx(v_2y, rel=1e-9, abs=1e-12)
    assert signed_w == pytest.approx(omega_2, rel=1e-9)
    # angular momentum about P: before m d v_1; after I_G ω_2 + (r_G/P × m v_2) = I_G ω_2 − d m v_2y
    assert I_G * signed_w - d * m * signed_v == pytest.approx(m * d * v_1, rel=1e-9)
    # kinetic energy never grows
    assert m * signed_v**2 + I_G * signed_w**2 <= m * v_1**2 * (1 + 1e-12)


def test_the_velocity_of_G_after_a_plastic_eccentric_impact() -> None:
    # newcomer round 6: v_after(rod) after 'impact rod at P: e 0' was refused with "rod takes
    # part in no impact". Hand: a 3 kg, 1.2 m rod falling flat at 4 m/s strikes a ledge
    # d = 0.3 m left of G: H_P = m v d = 3·4·0.3 = 3.6 = I_P ω, I_P = m L²/12 + m d² = 0.36
    # + 0.27 = 0.63 kg·m², ω₂ = 5.7143 rad/s cw; v_G2 = ω₂ d = 1.7143 m/s down.
    text = """given:
  m = 3 kg
  L = 1.2 m
  d = 0.3 m
  v_1 = 4 m/s
scene:
  point P: (-d, 0)
  body rod: mass m, rod L, at (0, 0)
  velocity rod: v_1, down
  impact rod at P: e 0
find: w_2 = omega_after(rod), v_2 = v_after(rod) [m/s]
"""
    solution = solve_text(text)
    values = {a.name: a for a in solution.answers}
    assert float(values["w_2"].value) == pytest.approx(3.6 / 0.63, rel=1e-9)
    assert float(values["v_2"].value) == pytest.approx(3.6 / 0.63 * 0.3, rel=1e-9)
    assert values["v_2"].direction == "down" and values["w_2"].direction == "cw"
