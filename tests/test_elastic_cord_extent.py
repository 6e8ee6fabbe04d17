"""An elastic cord (``spring …, tension only``) over a travel of unknown extent: its state
at the end is assumed taut, checked against the answer (s₂ > 0) and re-solved slack when
the answer contradicts it or no root keeps it stretched — the no-slip pattern for cords.

Hand results: a particle launched up from the anchor at v, cord of length L_0 and
stiffness k, rises d where ½ m v² = m g d (slack, d = v²/2g ≤ L_0) or
½ m v² = m g d + ½ k (d − L_0)² (taut, the root with d > L_0).
"""

import math
from pathlib import Path

import pytest

from dynsolve.pipeline import solve_file

G = 9.81
LAUNCH = """\
given:
  m = 0.5 kg
  k = 200 N/m
  L_0 = 3 m
  v_1 = {v}
scene:
  point O: (0, 0)
  body ball: particle, mass m, at (0, 0)
  spring S: ball at G to O, k k, unstretched L_0, tension only
  velocity ball: v_1, up
  gravity
  travel ball: by d, up, stops
find: d [m]
"""


def launch(tmp_path: Path, v: str):
    path = tmp_path / "launch.dyn"
    path.write_text(LAUNCH.format(v=v))
    solution = solve_file(path)
    return solution, next(a.value for a in solution.answers if a.name == "d")


def test_a_slow_launch_leaves_the_cord_slack_and_is_re_solved_so(tmp_path):
    # hand: v²/2g = 36/19.62 = 1.834862 m < L_0 = 3 m; the taut trial has no real root
    solution, d = launch(tmp_path, "6 m/s")
    assert d == pytest.approx(36 / (2 * G), rel=1e-9)
    assert not any(c.failed for c in solution.checks)
    trial = next(a for a in solution.assumptions if a.name == "elastic cord S taut at state 2")
    assert not trial.holds and "re-solved" in trial.detail
    final = next(a for a in solution.assumptions if a.name == "elastic cord S slack at state 2")
    assert final.holds


def test_a_fast_launch_stretches_the_cord_and_keeps_the_stretched_root(tmp_path):
    # hand: 100 d² − 595.095 d + 864 = 0 → d = 3.437483 m (the root 2.513 < L_0 is
    # the cord slack there, which the taut equation does not describe)
    solution, d = launch(tmp_path, "12 m/s")
    b, c = 0.5 * 9.81 - 200 * 3, 100 * 9 - 0.5 * 0.5 * 144
    assert d == pytest.approx((-b + math.sqrt(b * b - 400 * c)) / 200, rel=1e-9)
    assert d == pytest.approx(3.437483, rel=1e-6)
    assert not any(c.failed for c in solution.checks)
    assert any(a.name == "elastic cord S taut at state 2" and a.holds for a in solution.assumptions)


def test_the_bundled_bungee_falls_to_its_hand_derived_lowest_point():
    # hand (problems/scenes/bungee_lowest_point.dyn): d = 21.00504 m, F_max = 4804.02 N
    path = Path(__file__).parent.parent / "problems" / "scenes" / "bungee_lowest_point.dyn"
    solution = solve_file(path)
    assert not any(c.failed for c in solution.checks)
    got = {a.name: a.value for a in solution.answers}
    assert got["d"] == pytest.approx(21.00504, rel=1e-6)
    assert got["F_max"] == pytest.approx(4804.02, rel=1e-6)


def test_the_bundled_two_stage_bungee_stops_where_the_one_travel_jump_does():
    # hand (problems/stages/bungee_two_stages.dyn): v_2 = √(2 g L_0) = 17.15517 m/s, then
    # 400 d² − 686.7 d − 10300.5 = 0 → d = 6.005030 m: 21.00503 m in all, as in one travel
    path = Path(__file__).parent.parent / "problems" / "stages" / "bungee_two_stages.dyn"
    solution = solve_file(path)
    assert not any(c.failed for c in solution.checks)
    got = {a.name: a.value for a in solution.answers}
    assert got["d"] + 15 == pytest.approx(21.00503, rel=1e-6)
    # the second stage starts with the cord just taut (15 m below its anchor) and goes down
    # d ≥ 0 more: its stretch d is known not to be negative, so nothing need be assumed; were
    # it assumed, it must have held
    cord = [a for a in solution.assumptions if a.name.startswith("elastic cord S")]
    assert all(a.holds and "taut" in a.name for a in cord)


CHAIN = """\
given:
  m = 70 kg
  k = 800 N/m
  L_0 = 15 m
  h = {h}
scene:
  point O: (0, 0)
  body jumper: particle, mass m, at (0, 0)
  spring S: jumper at G to O, k k, unstretched L_0, tension only
  gravity
  travel jumper: by L_0, down
  travel jumper: by h, down
find: v = speed(jumper)
"""


def test_two_travels_in_a_row_keep_their_speeds_apart(tmp_path):
    # regression: the second travel's own rate and the first one's answer were both named
    # v_2_jumper, so T2 + ΣU = T3 read m v_3²/2 on both sides ("the equations conflict").
    # hand: 5 m past L_0, v² = 2 g (20) − (k/m) 5² = 392.4 − 285.714 → v = 10.32888 m/s
    path = tmp_path / "chain.dyn"
    path.write_text(CHAIN.format(h="5 m"))
    solution = solve_file(path)
    assert not any(c.failed for c in solution.checks)
    (v,) = solution.answers
    assert v.value == pytest.approx(10.32888, rel=1e-6)


def test_a_spring_on_a_particle_moves_with_it_through_the_stages(tmp_path):
    # regression: after a lone particle's travel the spring's end stayed where it was
    # drawn, so the stretch of the next stage was measured from the wrong place. Hand: the
    # jumper ends 2 m past L_0 both ways: one travel of 17 m, or 15 m then 2 m
    one = tmp_path / "one.dyn"
    one.write_text(
        CHAIN.format(h="2 m")
        .replace("  travel jumper: by L_0, down\n", "")
        .replace("travel jumper: by h, down", "travel jumper: by L_0 + h, down")
    )
    two = tmp_path / "two.dyn"
    two.write_text(CHAIN.format(h="2 m"))
    v_one = solve_file(one).answers[0].value
    v_two = solve_file(two).answers[0].value
    assert v_two == pytest.approx(v_one, rel=1e-12)
    assert v_one == pytest.approx((2 * 9.81 * 17 - (800 / 70) * 4) ** 0.5, rel=1e-9)
