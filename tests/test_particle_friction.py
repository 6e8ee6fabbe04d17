"""Friction on a particle: a given velocity slides it, a pull it cannot hold slips it (regressions).

A newcomer's block moving up a rough incline was answered with friction up the slope
(2.78 m/s², the sliding-down value) and an equation printed ``nan = 0``, every check
green: a given velocity on a rough contact without ``slides`` was read as rolling
(ω = v/r with r = 0 for a particle). A particle now never turns, an undefined equation
is a failed check, and so is a slip speed that is not a number. A crate pulled for 3 s was
answered v_2 = 0: its speed needed no equation, so "no slip" was assumed and never checked.
Every expected number is derived by hand in the comment above it.
"""

import math
from pathlib import Path

import pytest

from dynsolve.pipeline import solve_file, solve_text
from dynsolve.system import SolveOptions

ROOT = Path(__file__).resolve().parent.parent

UP_THE_SLOPE = """given:
  m = 10 kg
  theta = 30 deg
  mu_k = 0.25
  v_1 = 5 m/s
  g = 9.81 m/s^2
scene:
  body block: particle, mass m, at (0, 0)
  contact block at G: normal (-sin(theta), cos(theta)), mu_k mu_k
  velocity block: v_1, angle theta
  gravity
find: a = a_G(block) [m/s^2], F = F_G [N]
"""


@pytest.mark.parametrize("mode", ["exact", "numeric", "auto"])
def test_block_moving_up_a_rough_incline(mode: str) -> None:
    # N = m g cos 30° = 84.957 N; friction opposes the upward slide, down the slope:
    # a = g (sin 30° + μk cos 30°) = 9.81 (0.5 + 0.216506) = 7.028928 m/s² down the slope,
    # F = μk N = 21.2393 N.
    solution = solve_text(UP_THE_SLOPE, options=SolveOptions(mode=mode))
    values = {a.name: float(a.value) for a in solution.answers}
    assert values["a"] == pytest.approx(9.81 * (0.5 + 0.25 * math.sqrt(3) / 2), rel=1e-9)
    assert values["F"] == pytest.approx(0.25 * 98.1 * math.sqrt(3) / 2, rel=1e-9)
    assert solution.passed
    assert not any("nan" in e.text for e in solution.equations)


@pytest.mark.parametrize("name", ["block_moving_up_incline", "block_moving_up_incline_fps"])
def test_bundled_moving_up_problems_pass_their_keys(name: str) -> None:
    solution = solve_file(ROOT / "problems" / "scenes" / f"{name}.dyn")
    assert solution.key and all(k.passed for k in solution.key), [k.detail for k in solution.key]


def test_a_sliding_crate_on_its_base_translates() -> None:
    # a 50 kg crate (1 m by 1.5 m) sliding right at 3 m/s on its base, μk = 0.2: N = m g,
    # a = −μk g = −1.962 m/s², α = 0, and N acts h μk/2 = 0.15 m ahead of G (ΣM_G = 0).
    text = """given:
  m = 50 kg
  b = 1 m
  h = 1.5 m
  v_1 = 3 m/s
  mu_k = 0.2
scene:
  body crate: mass m, block b by h, at (0, h/2)
  base C on crate: from (-b/2, -h/2) to (b/2, -h/2), mu_k mu_k
  velocity crate: v_1, right
  gravity
find: a_x = a_Gx, al = alpha(crate), x_C
"""
    solution = solve_text(text)
    values = {a.name: float(a.value) for a in solution.answers}
    assert values["a_x"] == pytest.approx(-0.2 * 9.81, rel=1e-9)
    assert values["al"] == 0
    assert values["x_C"] == pytest.approx(0.15, rel=1e-9)
    assert solution.passed


# ---- an answer that follows from the givens alone still has its assumptions checked

CRATE = """given:
  m = 20 kg
  P = {P} N
  phi = 30 deg
  mu_s = 0.3
  mu_k = 0.2
  dt = 3 s
  g = 9.81 m/s^2
scene:
  body crate: particle, mass m, at (0, 0)
  contact crate at G: normal up, mu_s mu_s, mu_k mu_k
  force P on crate at G: angle phi
  gravity
  travel crate: for dt
find: v_2 = speed(crate) [m/s]
"""


@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_a_pulled_crate_that_slips_gains_speed(mode: str) -> None:
    # Hibbeler 15.x style: N = m g − P sin 30° = 196.2 − 50 = 146.2 N; P cos 30° = 86.60 N
    # > μs N = 43.86 N, so it slides: m v_2 = (P cos 30° − μk N) Δt = (86.603 − 29.24)·3,
    # v_2 = 8.604381 m/s. (It was answered 0: "no slip" assumed and never checked.)
    solution = solve_text(CRATE.format(P=100), options=SolveOptions(mode=mode))
    (v_2,) = [float(a.value) for a in solution.answers]
    assert v_2 == pytest.approx((100 * math.sqrt(3) / 2 - 0.2 * 146.2) * 3 / 20, rel=1e-9)


def test_a_pulled_crate_that_holds_stays_at_rest() -> None:
    # P = 30 N: N = 196.2 − 15 = 181.2 N, μs N = 54.36 N ≥ P cos 30° = 25.98 N: it stays put
    solution = solve_text(CRATE.format(P=30))
    (v_2,) = [float(a.value) for a in solution.answers]
    assert v_2 == 0
    assert solution.passed
    assert any(c.name == "assumption: no slip at G" and c.passed for c in solution.checks)


# ---- an interval of constant forces whose sliding stops inside it (newcomer round 2)

SLIDING_LEFT = """given:
  m = 10 kg
  mu_k = 0.2
  v_1 = 3 m/s
  dt = 2 s
scene:
  body block: particle, mass m, at (0, 0)
  contact block at G: normal up, mu_k mu_k
  velocity block: v_1, left
  gravity
  travel block: {travel}
find: {find}
"""


@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_a_block_that_stops_inside_the_interval_fails_its_check(mode: str) -> None:
    # sliding left at 3 m/s, friction alone: a = μk g = 1.962 m/s², it stops at
    # 3/1.962 = 1.529 s < 2 s and stays. Impulse and momentum with friction to the right for
    # the whole 2 s gave v_2 = 2·1.962 − 3 = 0.924 m/s to the right, every check green.
    text = SLIDING_LEFT.format(travel="for dt", find="v_2 = speed(block) [m/s]")
    solution = solve_text(text, options=SolveOptions(mode=mode))
    assert not solution.passed
    (failed,) = [
        c for c in solution.checks if "through the interval" in c.name and "assum" in c.name
    ]
    assert not failed.passed and "stops sliding before the interval ends" in failed.detail


def test_the_time_it_takes_to_stop_is_found_with_stops() -> None:
    # the same block, asked how long it slides: t_s = v_1/(μk g) = 3/1.962 s
    text = SLIDING_LEFT.format(travel="for t_s, stops", find="t_s [s]").replace("  dt = 2 s\n", "")
    solution = solve_text(text)
    (t_s,) = [float(a.value) for a in solution.answers]
    assert t_s == pytest.approx(3 / (0.2 * 9.81), rel=1e-9)
    assert solution.passed
