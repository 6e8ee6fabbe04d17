"""Reactions at any state (``cord(2)``, ``N_G(2)``): Newton–Euler at that instant with each
body where the stages leave it and moving as they leave it, a cord's end accelerating
v²/ℓ toward its fixed point. And a contact whose point already slides at an instant gets
kinetic friction against the slip (regression: a block given 3 m/s on a rough floor was
reported at rest relative to it, a = 0 and F = 0, with every check green).

Hand results (g = 9.81 m/s²): a pendulum released from θ has T = m g (3 − 2 cos θ) at the
bottom and m g cos θ at release; a block sliding on a rough floor decelerates at μk g.
"""

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file

G = 9.81
PROBLEMS = Path(__file__).parent.parent / "problems"
PENDULUM = """\
given:
  m = {m}
  L = {L}
  theta = {theta}
scene:
  point O: (0, 0)
  body bob: particle, mass m, at (-L*sin(theta), -L*cos(theta))
  link cord: bob at G to O
  gravity
  travel bob: to (0, -L)
find: T_2 = cord(2), T_1 = cord(1)
"""


def solve(tmp_path: Path, text: str):
    path = tmp_path / "states.dyn"
    path.write_text(text)
    return solve_file(path)


def answers(solution) -> dict:
    return {a.name: a for a in solution.answers}


def test_the_bundled_pendulum_pulls_its_cord_by_m_g_3_minus_2_cos_theta():
    # hand (problems/stages/pendulum_tension_bottom.dyn): T_2 = 39.24 N, T_1 = 9.81 N
    solution = solve_file(PROBLEMS / "stages" / "pendulum_tension_bottom.dyn")
    assert not any(c.failed for c in solution.checks)
    got = answers(solution)
    assert got["T_2"].value == pytest.approx(39.24, rel=1e-9)
    assert got["T_1"].value == pytest.approx(9.81, rel=1e-9)


def test_the_cord_just_after_a_bullet_embeds_carries_both_masses():
    # hand (problems/stages/bullet_bob_slack.dyn): T_2 = (m_b + M)(g + v_2²/L) = 83.62676 N
    solution = solve_file(PROBLEMS / "stages" / "bullet_bob_slack.dyn")
    assert not any(c.failed for c in solution.checks)
    assert answers(solution)["T_2"].value == pytest.approx(83.62676, rel=1e-7)


def test_the_collar_presses_its_rod_by_its_weight_alone_above_the_anchor(tmp_path):
    # hand (seed 001 Sec. 4.4): above O the spring is at its unstretched length, so at
    # state 2 N = W = 2 lb; at release N = W + k (1.236)(L/√5) = 4.763932 lb
    text = (PROBLEMS / "seed" / "we_seed_collar.dyn").read_text()
    text = text.split("find:")[0] + "find: N_2 = N_G(2) [lb], N_1 = N_G(1) [lb]\n"
    got = answers(solve(tmp_path, text))
    assert got["N_2"].value == pytest.approx(2.0, rel=1e-12)
    assert got["N_1"].value == pytest.approx(4.763932, rel=1e-6)


def test_a_body_whose_place_is_not_followed_is_refused_for_reactions_there(tmp_path):
    text = """\
given:
  m = 3 kg
  L = 1 m
  phi = 90 deg
scene:
  point O: (0, 0)
  body bar: mass m, rod L, at (L/2, 0)
  pin bar at O
  gravity
  travel bar: turns phi cw
find: O_2 = O_y(2)
"""
    with pytest.raises(SpecError, match="not followed"):
        solve(tmp_path, text)


@settings(max_examples=10, deadline=None)
@given(
    m=st.floats(0.1, 50.0),
    L=st.floats(0.2, 5.0),
    theta=st.floats(5.0, 85.0),
)
def test_tension_at_the_bottom_agrees_with_the_hand_formula(tmp_path_factory, m, L, theta):
    # two principles in a row: work and energy for v_2, then ΣF_n = m v²/L at state 2
    text = PENDULUM.format(m=f"{m!r} kg", L=f"{L!r} m", theta=f"{theta!r} deg")
    got = answers(solve(tmp_path_factory.mktemp("p"), text))
    c = math.cos(math.radians(theta))
    assert got["T_2"].value == pytest.approx(m * G * (3 - 2 * c), rel=1e-9)
    assert got["T_1"].value == pytest.approx(m * G * c, rel=1e-9)


# ---- a contact that slides at the instant
SLIDING = """\
given:
  m = 2 kg
  mu_k = 0.3
  mu_s = 0.4
  v = {v}
scene:
  point C: (0, 0)
  body block: particle, mass m, at (0, 0)
  contact block at C: normal up, mu_s mu_s, mu_k mu_k
  velocity block: v, {way}
  gravity
find: a = a_G(block), F = F_C
"""


@pytest.mark.parametrize("way, against", [("right", "left"), ("left", "right")])
def test_a_block_sliding_at_a_given_speed_decelerates_at_mu_k_g(tmp_path, way, against):
    # hand: F = μk m g = 5.886 N against the slide, a = μk g = 2.943 m/s² against it
    solution = solve(tmp_path, SLIDING.format(v="3 m/s", way=way))
    got = answers(solution)
    assert got["a"].value == pytest.approx(0.3 * G, rel=1e-12)
    assert got["a"].direction == against and got["F"].direction == against
    assert got["F"].value == pytest.approx(0.3 * 2 * G, rel=1e-12)
    sliding = next(a for a in solution.assumptions if a.name == "sliding at C")
    assert sliding.holds and "3 m/s" in sliding.detail
    assert not any(a.name == "no slip at C" for a in solution.assumptions)


def test_a_block_at_rest_keeps_static_friction(tmp_path):
    # hand: at rest with no push, F = 0 and no slip holds
    text = SLIDING.format(v="0 m/s", way="right")
    got = answers(solve(tmp_path, text))
    assert got["a"].value == pytest.approx(0.0, abs=1e-12)


def test_a_slide_whose_sense_depends_on_symbols_asks_for_it(tmp_path):
    text = SLIDING.format(v="m/s", way="right").replace("  v = m/s\n", "  v: m/s\n")
    with pytest.raises(SpecError, match="slides right"):
        solve(tmp_path, text)


def test_an_angle_with_many_digits_does_not_stall_the_exact_trig(tmp_path):
    # regression: cos(37.1234°) kept exact made sympy build the minimal polynomial of
    # cos(371234π/1800000) (degree ~10^5) in the chain's presolve and in the simulation
    # check's placements: minutes, where the numbers alone are needed. Hand: T_2 =
    # m g (3 − 2 cos 37.1234°) = 27.5724 N; the worker's budget makes a stall a failure.
    import dynsolve

    path = tmp_path / "digits.dyn"
    path.write_text(PENDULUM.format(m="2 kg", L="1.2 m", theta="37.1234 deg"))
    result = dynsolve.solve(str(path), time_budget=30)
    c = math.cos(math.radians(37.1234))
    assert result["T_2"].to("N").magnitude == pytest.approx(2 * G * (3 - 2 * c), rel=1e-9)


LINK_TURN = """\
given:
  m = 1 kg
  L = 0.8 m
  n = 90 deg
scene:
  point O: (0, 0)
  body bob: particle, mass m, at (-L, 0)
  link cord: bob at G to O
  gravity
  travel cord: turns n ccw
find: v = speed(bob), T_b = cord(2)
"""


def test_a_link_turned_in_a_stage_places_its_bob_for_the_reactions_there(tmp_path):
    # regression (newcomer report): 'travel cord: turns n ccw' with a stage find crashed
    # with KeyError 'cord' (a link, not a body). Hand: released with the cord horizontal,
    # v = √(2 g L) = 3.96181 m/s at the bottom, T = 3 m g = 29.43 N
    got = answers(solve(tmp_path, LINK_TURN))
    assert got["v"].value == pytest.approx((2 * G * 0.8) ** 0.5, rel=1e-9)
    assert got["T_b"].value == pytest.approx(3 * G, rel=1e-9)


def test_a_bullet_and_bob_swing_together_after_a_plastic_impact(tmp_path):
    # regression (newcomer report): refused ("a travel of particles moving together is
    # supported on its own only"). Hand: v_2 = 0.03·400/3.03 = 3.960396 m/s; after the cord
    # turns 50°, v_3 = √(v_2² − 2 g L (1 − cos 50°)) = 2.114504 m/s
    text = """\
given:
  m_b = 30 g
  v_0 = 400 m/s
  M = 3 kg
  L = 1.6 m
  D = 0.1 m
  n = 50 deg
scene:
  point O: (0, 0)
  body bullet: particle, mass m_b, at (-D, -L)
  body bob: particle, mass M, at (0, -L)
  link cord: bob at G to O
  velocity bullet: v_0, right
  gravity
  impact bullet with bob: e 0, line right
  travel cord: turns n ccw
find: v_3 = speed(bob), T_3 = cord(3)
"""
    solution = solve(tmp_path, text)
    assert not any(c.failed for c in solution.checks)
    got = answers(solution)
    v_3 = 2.114504
    assert got["v_3"].value == pytest.approx(v_3, rel=1e-6)
    # at 50° past the bottom: T − (m_b + M) g cos 50° = (m_b + M) v_3²/L
    c = math.cos(math.radians(50))
    assert got["T_3"].value == pytest.approx(3.03 * (G * c + v_3**2 / 1.6), rel=1e-6)


def test_a_travel_off_its_surface_is_refused_at_the_contact_line(tmp_path):
    # regression (newcomer report): the error pointed at 1:1 (the problem line)
    text = """\
given:
  m = 5 kg
  d = 2 m
scene:
  body block: particle, mass m, at (0, 0)
  contact block at G: smooth
  gravity
  travel block: by d, angle -pi/6
find: v = speed(block)
"""
    with pytest.raises(SpecError, match="would leave its contact G") as error:
        solve(tmp_path, text)
    assert error.value.position.line == 6
