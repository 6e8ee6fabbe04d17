"""A periodic law in one-line kinematics: crossings, stops and extremes in every period.

sympy's ``solve`` returns one period's roots of ``A sin(w t) = h``; before the fix a third
crossing was refused with a false claim ("x equals the value 2 times after t₀, not 3"),
and a distance over several periods missed stops (refused by the ∫|v| dt check). Every
expected number is derived by hand in the comment above it.
"""

import math
from pathlib import Path

import pytest
import sympy

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file, solve_text
from dynsolve.principles.rectilinear import MAX_CROSSINGS, T, crossing_times, extreme_time

ROOT = Path(__file__).resolve().parent.parent
BUNDLED = ("oscillation_distance", "oscillation_third_pass", "oscillation_later_start")


def answer(solution, name: str) -> float:
    """The SI value of one answer."""
    return float(next(a for a in solution.answers if a.name == name).value)


@pytest.mark.parametrize("name", BUNDLED)
def test_bundled_periodic_problems_pass_their_keys(name: str) -> None:
    solution = solve_file(ROOT / "problems" / "kinematics" / f"{name}.dyn")
    assert solution.key, "the problem has an answers: key"
    assert all(k.passed for k in solution.key), [k.detail for k in solution.key]


def test_crossings_are_repeated_by_whole_periods_after_t0() -> None:
    # sin(10 t) = 1/2 at 10 t = pi/6 + 2k pi and 5 pi/6 + 2k pi; after t0 = 0.3 s (past one
    # period's roots pi/60 = 0.052 and pi/12 = 0.262) the next three are 13 pi/60 = 0.681,
    # 17 pi/60 = 0.890 and 25 pi/60 = 1.309 s.
    q = sympy.sin(10 * T)
    found = crossing_times(q, sympy.Rational(1, 2), sympy.Rational(3, 10), count=3)
    times = [float(t) for t in found.times[:3]]
    assert times == pytest.approx([13 * math.pi / 60, 17 * math.pi / 60, 25 * math.pi / 60])
    assert all(float(t) <= 0.3 for t, _ in found.discarded)


def test_largest_value_after_a_later_start_is_the_next_maximum() -> None:
    # x = sin(10 t), t0 = 0.2 s: dx/dt = 0 at 10 t = pi/2 + k pi; after 0.2 s the first is
    # 3 pi/20 = 0.471 (a minimum), then 5 pi/20 = 0.785 (a maximum, x = 1).
    found = extreme_time(sympy.sin(10 * T), sympy.Rational(1, 5))
    assert float(found.times[0]) == pytest.approx(5 * math.pi / 20)
    reasons = [why for t, why in found.discarded if float(t) == pytest.approx(3 * math.pi / 20)]
    assert reasons == ["a minimum"]


def test_a_symbolic_periodic_law_does_not_count_crossings_it_cannot_place() -> None:
    # with w a letter the periods cannot be placed in time: no false "2 times, not 3"
    w = sympy.Symbol("w", positive=True)
    with pytest.raises(ValueError, match="repeats every"):
        crossing_times(sympy.sin(w * T), sympy.Rational(1, 2), sympy.Integer(0), count=3)


def test_too_many_periods_are_refused_with_the_reason() -> None:
    # sin(1000 t) over 10 s crosses 0 about 3183 times (> MAX_CROSSINGS)
    with pytest.raises(ValueError, match="shorter interval"):
        crossing_times(
            sympy.sin(1000 * T), sympy.Integer(0), sympy.Integer(0), until=sympy.Integer(10)
        )
    assert MAX_CROSSINGS < 3183


PERIODIC = """given:
  A = 1 m
  w = 1 1/s
  t_2 = 10 s
kinematics:
  x = A*sin(w*t)
find: {find}
"""


def test_distance_over_several_periods() -> None:
    # x = sin t over 0..10 s: stops at pi/2, 3pi/2, 5pi/2 (7.85 s); distance =
    # 1 + 2 + 2 + (1 - sin 10) = 6 - sin 10 = 6.54402 m. (It was refused: a stop missed.)
    solution = solve_text(PERIODIC.format(find="s = distance(t_2)"))
    assert answer(solution, "s") == pytest.approx(6 - math.sin(10), rel=1e-9)


def test_smallest_over_an_interval_spanning_periods() -> None:
    # x = sin t over t0 = 0 … 10 s: smallest -1 at 3pi/2 (and 7pi/2 = 11.0 s, after the end)
    solution = solve_text(PERIODIC.format(find="x_lo = min(x, t_2)"))
    assert answer(solution, "x_lo") == pytest.approx(-1.0, rel=1e-12)


def test_a_crossing_count_far_past_the_first_period() -> None:
    # sin t = 0 after t0 = 0: t = pi, 2pi, ...; the 7th is 7 pi = 21.99 s
    solution = solve_text(PERIODIC.format(find="t_7 = t_at(x, 0, 7)"))
    assert answer(solution, "t_7") == pytest.approx(7 * math.pi, rel=1e-12)


def test_a_never_reached_level_of_a_periodic_law_is_still_an_error() -> None:
    # |sin t| <= 1: x = 2 m is never reached
    with pytest.raises(SpecError, match="never"):
        solve_text(PERIODIC.format(find="t_f = t_at(x, h)").replace("t_2 = 10 s", "h = 2 m"))


def test_distance_when_sympy_cannot_solve_v_equals_0() -> None:
    # Beer & Johnston 11.x style: x = 6t² − 8 + 40 cos πt (in, s); v = 12 t − 40π sin πt = 0
    # has no closed form: the stops 0.9705, 2.0631, 2.9104, 4.1290, 4.8468 s come from a
    # scan. Hand: x(0) = 32, x(0.970459) = −42.1771, x(2.063124) = 57.29..., ...; the total
    # over 0..6 s is 536.188 in (newcomer's Newton roots; also ∫|v| dt by quadrature).
    solution = solve_file(ROOT / "problems" / "kinematics" / "poly_cos_distance.dyn")
    assert solution.key and all(k.passed for k in solution.key), [k.detail for k in solution.key]
    (s,) = [a for a in solution.answers if a.name == "s"]
    assert float(s.value) == pytest.approx(536.188, rel=1e-5)  # in inches, as asked
