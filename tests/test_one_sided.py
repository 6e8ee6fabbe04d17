"""One-sided elements at an instant: a cord pulls only and a contact pushes only. A trial
whose tension or normal force comes out negative is a failed assumption, and the scene is
re-solved with the cord slack or the contact lost, which is stated and checked."""

import math

import pytest

from dynsolve.pipeline import solve_text

LIFT = """\
given:
  m = 2 kg
  P = {P} N
  phi = 60 deg
scene:
  body block: particle, mass m, at (0, 0)
  contact block at G: normal up, smooth
  force P on block at G: angle phi
  gravity
find: a = a_G(block) [m/s^2], N_G [N], N_1 = trial(N_G) [N]
"""

HANG = """\
given:
  m = 5 kg
  P = {P} N
scene:
  body block: particle, mass m, at (0, 0)
  cord T: block at G, up, fixed
  force P on block at G: up
  gravity
find: a = a_G(block) [m/s^2], T [N]
"""


def answers(solution) -> dict:
    return {a.name: a for a in solution.answers}


def assumption(solution, name):
    return next(a for a in solution.assumptions if a.name == name)


def test_a_pull_steeper_than_the_weight_lifts_the_block_off_the_floor():
    # P sin 60° = 25.98 N > m g = 19.62 N, so the trial's N = m g − P sin φ = −6.361 N < 0.
    # Without the contact: a_x = P cos φ / m = 7.5, a_y = (P sin φ − m g)/m = 3.180 m/s²;
    # |a| = 8.146 m/s² at atan(3.180/7.5) = 22.98° (hand derivation).
    solution = solve_text(LIFT.format(P=30), "lift.dyn")
    got = answers(solution)
    a_y = (30 * math.sin(math.radians(60)) - 2 * 9.81) / 2
    assert got["a"].value == pytest.approx(math.hypot(7.5, a_y), rel=1e-9)
    elevation = math.degrees(math.atan2(a_y, 7.5))
    assert got["a"].direction == f"{elevation:.1f}° above the horizontal, to the right"
    assert got["N_G"].value == pytest.approx(0.0, abs=1e-12)
    # the trial's normal force, a magnitude with its sense: 6.361 N down (a pull)
    assert got["N_1"].value == pytest.approx(30 * math.sin(math.radians(60)) - 2 * 9.81)
    assert got["N_1"].direction == "down"
    kept = assumption(solution, "contact at G kept")
    assert not kept.holds and "re-solved" in kept.detail
    assert assumption(solution, "contact at G lost").holds
    assert solution.passed


def test_a_pull_weaker_than_the_weight_keeps_the_contact():
    # P sin 60° = 8.66 N < m g: N = 19.62 − 8.66 = 10.96 N, a = P cos φ / m = 2.5 m/s².
    solution = solve_text(LIFT.format(P=10), "lift.dyn")
    got = answers(solution)
    assert got["N_G"].value == pytest.approx(2 * 9.81 - 10 * math.sin(math.radians(60)))
    assert got["a"].value == pytest.approx(2.5)
    assert all(a.holds for a in solution.assumptions)
    assert not any(a.name.endswith(" lost") for a in solution.assumptions)


def test_a_push_up_larger_than_the_weight_slackens_the_cord():
    # T = m g − P = 49.05 − 60 = −10.95 N in the trial: slack. Without the cord the block
    # accelerates up at (P − m g)/m = 10.95/5 = 2.19 m/s² (hand derivation).
    solution = solve_text(HANG.format(P=60), "hang.dyn")
    got = answers(solution)
    assert got["a"].value == pytest.approx(2.19, rel=1e-9)
    assert got["a"].direction == "up"
    assert got["T"].value == pytest.approx(0.0, abs=1e-12)
    assert not assumption(solution, "cord T taut").holds
    assert assumption(solution, "cord T slack").holds
    assert solution.passed


def test_a_taut_cord_is_not_released():
    # P = 20 N < m g: T = 49.05 − 20 = 29.05 N and the block stays (a = 0).
    solution = solve_text(HANG.format(P=20), "hang.dyn")
    got = answers(solution)
    assert got["T"].value == pytest.approx(29.05, rel=1e-9)
    assert got["a"].value == pytest.approx(0.0, abs=1e-12)
    assert assumption(solution, "cord T taut").holds
