"""The start and the stop of a one-line motion: v(x) takes the start's sense; past a stop it rests.

A newcomer found v(x) = +√(v₀² + 2∫a dx) taken whatever v₀'s sign, with every check green:
a given's symbol has no sign of its own, so ``v_0.is_negative`` was None and "+" was
chosen. The sign is now read at the givens' values. Every expected number is derived by
hand in the comment above it.
"""

import math

import pytest

from dynsolve.pipeline import solve_text
from dynsolve.system import SolveOptions

SPRING = """given:
  k = 16 1/s^2
  x_0 = 0.1 m
  v_0 = {v_0} m/s
  x_1 = 0.05 m
kinematics:
  a = -k*x
find: t_z = t_at(x, 0), v_1 = v(x_1), x_t = x_at(v, 0)
"""


def answers(text: str, mode: str) -> dict[str, float]:
    solution = solve_text(text, options=SolveOptions(mode=mode))
    return {a.name: float(a.value) for a in solution.answers}


@pytest.mark.parametrize("mode", ["exact", "numeric", "auto"])
def test_spring_law_moving_left_at_the_start(mode: str) -> None:
    # w = 4 rad/s; x = 0.1 cos 4t − 0.05 sin 4t: x = 0 at tan 4t = 2, t = atan(2)/4;
    # v² = v₀² + k (x₀² − x²) = 0.04 + 0.12 = 0.16 at x = 0.05, moving left: v = −0.4 m/s;
    # the turning point ahead (leftwards): x = −√(x₀² + v₀²/k) = −0.111803 m.
    found = answers(SPRING.format(v_0="-0.2"), mode)
    assert found["t_z"] == pytest.approx(math.atan(2) / 4, rel=1e-9)
    assert found["v_1"] == pytest.approx(-0.4, rel=1e-9)
    assert found["x_t"] == pytest.approx(-math.sqrt(0.0125), rel=1e-9)


@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_spring_law_released_from_rest_moves_the_way_a_points(mode: str) -> None:
    # from rest at x₀ = 0.1 m, a₀ = −k x₀ < 0: v(0.05) = −4 √(0.01 − 0.0025) = −√0.12
    found = answers(SPRING.format(v_0="0"), mode)
    assert found["v_1"] == pytest.approx(-math.sqrt(0.12), rel=1e-9)
    assert found["t_z"] == pytest.approx(math.pi / 8, rel=1e-9)  # x = 0.1 cos 4t
    assert found["x_t"] == pytest.approx(-0.1, rel=1e-9)


@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_constant_acceleration_moving_left(mode: str) -> None:
    # a = 2 m/s², v₀ = −5 m/s, x₀ = 0: at x = −3 m (before the turn at x = −6.25 m)
    # v² = 25 + 2·2·(−3) = 13, moving left: v = −√13; x = −5t + t² = −3: t = (5 − √13)/2
    text = """given:
  b = 2 m/s^2
  v_0 = -5 m/s
  x_1 = -3 m
kinematics:
  a = b
find: v_1 = v(x_1), t_1 = t(x_1)
"""
    found = answers(text, mode)
    assert found["v_1"] == pytest.approx(-math.sqrt(13), rel=1e-9)
    assert found["t_1"] == pytest.approx((5 - math.sqrt(13)) / 2, rel=1e-9)


# ---- past the stop of an a(v) motion (regression: the inverted v(t) was read past it)

SQRT_DRAG = """given:
  k = 3 m^(1/2)/s^(3/2)
  v_0 = 9 m/s
  t_1 = 1 s
  t_3 = 3 s
kinematics:
  a = -k*sqrt(v)
find: v_1 = v(t_1), x_1 = x(t_1), v_3 = v(t_3), x_3 = x(t_3)
"""


@pytest.mark.parametrize("mode", ["exact", "numeric", "auto"])
def test_an_a_of_v_motion_stays_at_rest_after_it_stops(mode: str) -> None:
    # Beer-Johnston 11.x style: dv/dt = −k√v → √v = √v₀ − k t/2 = 3 − 1.5 t: it stops at
    # t = 2 s after x = 2 v₀^(3/2)/(3k) = 6 m; at 1 s v = 2.25 m/s, x = (2/9)(27 − 3.375)
    # = 5.25 m. At 3 s it is at rest at 6 m, where a = −k√0 = 0 keeps it (v = (3 − 1.5·3)²
    # = 2.25 m/s is the formula's other branch: it was answered, with x = 5.25 m).
    found = answers(SQRT_DRAG, mode)
    assert found["v_1"] == pytest.approx(2.25, rel=1e-9)
    assert found["x_1"] == pytest.approx(5.25, rel=1e-9)
    assert found["v_3"] == 0
    assert found["x_3"] == pytest.approx(6.0, rel=1e-9)
