"""A body under Coulomb friction in time: it stops where static friction can hold it, and a
simulation is bounded by the run's budget (regressions: the newcomer's block on a spring
ran for more than 10 minutes, chattering about q' = 0 after its last stop).

Hand solution (Coulomb damping; Meriam & Kraige 8/2, Hibbeler 22.4 for the method): a
2-kg block on a floor (μs = μk = 0.1) tied to a wall by a spring k = 200 N/m, released
from rest stretched 0.1 m. Each half swing lasts π √(m/k) = 0.3141593 s and the amplitude
drops by 2 μ m g/k = 0.01962 m per half swing: x = 0.1, −0.08038, 0.06076, −0.04114,
0.02152, −0.00190 m. There k |x| = 0.38 N < μs m g = 1.962 N: it stays, from
t = 5 π √(m/k) = 1.570796 s.
"""

from __future__ import annotations

import math

import pytest
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.simulate.integrator import AT_REST
from dynsolve.simulate.run import simulate_spec
from dynsolve.spec.parser import parse_spec

BLOCK = """\
problem: Block on a spring with Coulomb friction
units: SI
given:
  m = 2 kg
  k = 200 N/m
  mu_k = 0.1
  mu_s = 0.1
  d = 1 m
  x_0 = 0.1 m
scene:
  point C: (x_0, 0)
  point W: (-d, 0)
  body block: particle, mass m, at (x_0, 0)
  contact block at C: normal up, mu_s mu_s, mu_k mu_k
  spring S: block at G to W, k k, unstretched d
  gravity
"""
HALF = math.pi * math.sqrt(2 / 200)
DROP = 2 * 0.1 * 2 * 9.81 / 200


def test_the_block_stops_where_static_friction_holds_it():
    history = simulate_spec(parse_spec(BLOCK, "block.dyn"), None, 2.5)
    stops = [e for e in history.events if e[0] in ("max", "min")]
    x = [0.1 + e[2] for e in stops]  # q is the travel from x_0
    expected = [(-1) ** (i + 1) * (0.1 - (i + 1) * DROP) for i in range(5)]
    assert x == pytest.approx(expected, abs=1e-8)
    assert [e[1] for e in stops] == pytest.approx([HALF * (i + 1) for i in range(5)], rel=1e-8)
    (rest,) = [e for e in history.events if e[0] == AT_REST]
    assert rest[1] == pytest.approx(5 * HALF, rel=1e-8)
    assert history.run.q[-1] == pytest.approx(rest[2]) and history.run.qd[-1] == 0
    assert history.run.t[-1] == pytest.approx(2.5)
    assert history.run.drift < 1e-8  # T + V − U_f over the stops


def test_a_block_that_friction_holds_from_the_start_never_moves():
    # stretched 5 mm: k x = 1 N < μs m g = 1.962 N
    history = simulate_spec(parse_spec(BLOCK.replace("0.1 m", "0.005 m"), "b.dyn"), None, 1.0)
    assert [e[0] for e in history.events] == [AT_REST]
    assert max(abs(history.run.q)) == 0


def test_a_simulation_over_its_time_budget_stops_with_the_step_named(tmp_path):
    file = tmp_path / "pendulum.dyn"
    file.write_text(
        "given:\n  L = 1 m\n  m = 2 kg\nscene:\n  point O: (0, 0)\n"
        "  body bar: mass m, rod L, at (L/2, 0)\n  pin bar at O\n  gravity\n"
    )
    result = CliRunner().invoke(
        app,
        ["simulate", str(file), "--t-end", "1e7 s", "--rtol", "1e-13", "--time-budget", "2"],
    )
    assert result.exit_code == 2
    assert "time budget of 2 s, while integrating the motion in time" in result.output
    assert "--t-end" in result.output  # the hint fits a simulation


def test_a_block_that_stops_on_the_side_it_came_from_does_not_hang():
    # regression (newcomer, round 3): 10 lb, k = 20 lb/ft, μs = μk = 0.2, released 0.93 ft
    # stretched. By hand the amplitude drops by 2 μ W/k = 0.2 ft per half swing: x = 0.93,
    # −0.73, 0.53, −0.33, 0.13; from 0.13 the block swings about +0.1 ft (the friction's
    # offset μ W/k) and stops at 0.07 ft, on the side it came from, where k x = 1.4 lb ≤
    # μs W = 2 lb holds it: at rest from t = 5 π √(m/k) = 1.957388 s. The integrator used to
    # creep toward q' = 0 there with ever smaller steps (minutes, then the budget).
    text = """\
units: FPS
given:
  W = 10 lb
  k = 20 lb/ft
  mu = 0.2
  x_0 = 0.93 ft
  L_0 = 2 ft
scene:
  point A: (-L_0, 0)
  body block: particle, weight W, at (x_0, 0)
  contact block at G: normal up, mu_s mu, mu_k mu
  spring S: block at G to A, k k, unstretched L_0
  gravity
"""
    history = simulate_spec(parse_spec(text, "fps.dyn"), None, 2.5)
    half = math.pi * math.sqrt(10 / 32.2 / 20)
    stops = [e for e in history.events if e[0] in ("max", "min")]
    x = [0.93 + e[2] for e in stops]
    assert x == pytest.approx([-0.73, 0.53, -0.33, 0.13, 0.07], abs=1e-8)
    (rest,) = [e for e in history.events if e[0] == AT_REST]
    assert rest[1] == pytest.approx(5 * half, rel=1e-8)


def test_a_travel_of_unknown_extent_gets_a_hint_that_fits_a_simulation(tmp_path):
    # newcomer report (round 3): "'d' in the scene is not a given (hint: declare it under
    # given:)" sent them to declare what `solve` finds
    file = tmp_path / "drop.dyn"
    file.write_text(
        "given:\n  m = 2 kg\n  k = 100 N/m\n  L = 1 m\nscene:\n  point A: (0, L)\n"
        "  body b: particle, mass m, at (0, 0)\n  spring S: b at G to A, k k, unstretched L\n"
        "  gravity\n  travel b: by d, down, stops\nfind: d\n"
    )
    result = CliRunner().invoke(app, ["simulate", str(file)])
    assert result.exit_code == 2
    assert "leave the travel line out" in result.output and "--until" in result.output


def test_a_sliding_contact_is_judged_moving_at_any_length_scale() -> None:
    """A contact point that moves with G (1e-13 m per unit of the travel coordinate, a
    problem in picometres) slides: the test compares |dr_C/dq|² with |dr_G/dq|², not with an
    absolute 1e-24 (which called it still); a contact that does not move is still."""
    import sympy

    from dynsolve.simulate.equations import _is_still

    tiny = sympy.Float(1e-13)
    assert not _is_still((tiny, 0), (tiny, 0), {})
    assert _is_still((0, 0), (tiny, 0), {})
    assert _is_still((0, 0), (0, 0), {})
