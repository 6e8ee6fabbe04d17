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

from dynsolve.errors import SpecError
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
    assert all(c.passed for c in solution.checks)
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
    assert all(c.passed for c in solution.checks)
    assert any(a.name == "elastic cord S taut at state 2" and a.holds for a in solution.assumptions)


def test_the_bundled_bungee_falls_to_its_hand_derived_lowest_point():
    # hand (problems/scenes/bungee_lowest_point.dyn): d = 21.00504 m, F_max = 4804.02 N
    path = Path(__file__).parent.parent / "problems" / "scenes" / "bungee_lowest_point.dyn"
    solution = solve_file(path)
    assert all(c.passed for c in solution.checks)
    got = {a.name: a.value for a in solution.answers}
    assert got["d"] == pytest.approx(21.00504, rel=1e-6)
    assert got["F_max"] == pytest.approx(4804.02, rel=1e-6)


def test_an_unknown_cord_state_in_a_chain_is_refused_not_assumed(tmp_path):
    # the taut/slack switch is not followed through stages yet: refused with the reason,
    # while the stage before (a fall to exactly L_0, the cord just taut) is decided
    path = tmp_path / "chain.dyn"
    path.write_text(
        "given:\n  m = 70 kg\n  k = 800 N/m\n  L_0 = 15 m\nscene:\n  point O: (0, 0)\n"
        "  body jumper: particle, mass m, at (0, 0)\n"
        "  spring S: jumper at G to O, k k, unstretched L_0, tension only\n  gravity\n"
        "  travel jumper: by L_0, down\n  travel jumper: by d, down, stops\nfind: d [m]\n"
    )
    with pytest.raises(SpecError, match=r"stage 2 .*not followed yet") as error:
        solve_file(path)
    assert error.value.position.line == 11
