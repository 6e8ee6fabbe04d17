"""Two-state 3D scenes that start moving: ``travel B: turns … about (u), from omega W``.

Expected numbers: hand derivations below. For the seed's gear A rolling on the fixed gear
B (seed 002, 9.1), no slip gives ω_spin = (R_B/R_A) ω and T = m (3 R_B²/4 + R_A²/8) ω²; a
slender rod turning about a fixed horizontal axis through its end has T = ½ (m L²/3) ω²
and its weight does −m g (L/2)(1 − cos Δθ) as G rises from below the axis.
"""

import math
from pathlib import Path

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file, solve_text

PROBLEMS = Path(__file__).parent.parent / "problems"
G = 9.81


def answers(solution) -> dict:
    return {a.name: a.value for a in solution.answers}


GEAR = """\
given:
  m_A = 4 kg
  R_A = 0.1 m
  R_B = 0.3 m
  M = {M} N*m
  n = {n} rev
  w_1 = {w_1} rad/s
scene:
  body A: mass m_A, disk R_A, at (R_B, 0, 0)
  axis A: (1, 0, 0)
  rotates A: about (0, 1, 0), through (0, 0, 0), omega omega_CD
  spins A: about (-1, 0, 0), omega omega_spin
  rolls A at (R_B, -R_A, 0)
  torque M on A
  travel A: turns n about (0, 1, 0), from omega w_1
find: omega_CD, omega_spin, T = T(A)
"""
K = 4 * (3 * 0.3**2 / 4 + 0.1**2 / 8)  # T = K ω² = 0.275 ω²


def test_the_gear_from_a_moving_start():
    # T1 = 0.275 (2²) = 1.1 J, U = 5 (4π) = 62.83185 J: ω_CD = √(63.93185/0.275) = 15.24728
    solution = solve_file(PROBLEMS / "rigid3d" / "gear_rolling_moving.dyn")
    found = answers(solution)
    w_2 = math.sqrt((K * 4 + 5 * 4 * math.pi) / K)
    assert w_2 == pytest.approx(15.24728, rel=1e-6)
    assert found["omega_CD"] == pytest.approx(w_2, rel=1e-12)
    assert found["omega_spin"] == pytest.approx(3 * w_2, rel=1e-12)
    assert found["T"] == pytest.approx(K * 4 + 20 * math.pi, rel=1e-12)
    checks = {c.name: c for c in solution.checks}
    assert checks["T1 about the fixed point"].passed and checks["T about the fixed point"].passed
    assert "T1 = ½ m v_G² + ½ ωᵀ I_G ω" in checks["state 1"].detail


@settings(max_examples=5, deadline=None)
@given(M=st.integers(-4, 8), n=st.integers(1, 4), w_1=st.integers(4, 30))
def test_the_gear_follows_t1_plus_u_equals_t2(M, n, w_1):
    T1, U = K * w_1**2, M * 2 * math.pi * n
    if T1 + U <= 0:  # a braking couple that stops the gear first: refused (tested below)
        return
    found = answers(solve_text(GEAR.format(M=M, n=n, w_1=w_1), "gear.dyn"))
    assert found["omega_CD"] == pytest.approx(math.sqrt((T1 + U) / K), rel=1e-9)
    assert found["T"] == pytest.approx(T1 + U, rel=1e-9)


def test_from_rest_the_start_is_the_seeds():
    # w_1 = 0 is the seed's 9.1: 0.275 ω² = 5 (4π) -> ω_CD = 15.11554 rad/s
    found = answers(solve_text(GEAR.format(M=5, n=2, w_1=0), "gear.dyn"))
    assert found["omega_CD"] == pytest.approx(math.sqrt(20 * math.pi / K), rel=1e-12)
    assert found["omega_CD"] == pytest.approx(15.11554, rel=1e-6)


ROD = """\
given:
  m = 3 kg
  L = {L} m
  w_1 = {w_1} rad/s
  turn = {turn} deg
scene:
  body rod: mass m, rod L, at (0, -L/2, 0)
  axis rod: (0, 1, 0)
  rotates rod: about (0, 0, 1), through (0, 0, 0), omega w_2
  bearing O: at (0, 0, 0), ball
  gravity
  travel rod: turns turn about (0, 0, 1), from omega w_1
find: w_2, U = U(rod)
"""


def test_the_rod_a_quarter_turn_on():
    # I_O = 1.44 kg·m², T1 = 46.08 J, U = −3 (9.81)(0.6) = −17.658 J: ω2 = √(64 − 3g/L)
    solution = solve_file(PROBLEMS / "rigid3d" / "rod_swing_moving.dyn")
    found = answers(solution)
    assert found["w_2"] == pytest.approx(math.sqrt(64 - 3 * G / 1.2), rel=1e-12)
    assert found["U"] == pytest.approx(-3 * G * 0.6, rel=1e-12)
    assert solution.passed


@settings(max_examples=5, deadline=None)
@given(L=st.sampled_from([0.5, 1.0, 1.5]), w_1=st.integers(8, 20), turn=st.integers(10, 170))
@example(L=0.5, w_1=8, turn=96)
def test_the_rod_follows_the_pendulum_energy(L, w_1, turn):
    # ½ (m L²/3)(ω2² − ω1²) = −m g (L/2)(1 − cos Δθ): ω2² = ω1² − 3 g (1 − cos Δθ)/L;
    # where that is negative the rod stops first and the travel is refused (L = 0.5 m,
    # ω1 = 8 rad/s, 96°: ω1² = 64 < 3 g (1 − cos 96°)/L = 65.0, found by Hypothesis)
    text = ROD.format(L=L, w_1=w_1, turn=turn)
    drop = 3 * G * (1 - math.cos(math.radians(turn))) / L
    if w_1**2 <= drop:
        with pytest.raises(SpecError, match="stops before it has turned that far"):
            solve_text(text, "rod.dyn")
        return
    found = answers(solve_text(text, "rod.dyn"))
    assert found["w_2"] == pytest.approx(math.sqrt(w_1**2 - drop), rel=1e-9)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (GEAR.format(M=-5, n=2, w_1=2), "stops before it has turned that far"),
        (GEAR.format(M=5, n=2, w_1=-2), "turns against the travel"),
        (ROD.format(L=1.2, w_1=2, turn=90), "stops before it has turned that far"),
        (
            GEAR.format(M=5, n=2, w_1=2).replace("  rolls A at (R_B, -R_A, 0)\n", ""),
            "no known spin",
        ),
        (GEAR.format(M=5, n=2, w_1=2).replace("from omega w_1", "from omega w_0"), "'w_0'"),
    ],
)
def test_a_moving_start_that_cannot_be_is_refused(text, message):
    with pytest.raises(SpecError, match=message) as error:
        solve_text(text, "start.dyn")
    assert error.value.position is not None and error.value.position.line > 1
