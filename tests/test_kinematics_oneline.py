"""One-line kinematics complete (issue 8, part 6): t_at, x_at, max/min, turning points,
total distance, constant acceleration, expressions as finds, and unused givens named.

Every expected number is derived by hand in the comment above it.
"""

import json
import math
from pathlib import Path

import pytest
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file, solve_text

ROOT = Path(__file__).resolve().parent.parent
BUNDLED = ("spring_turning_point", "cubic_distance", "car_braking")


def answer(solution, name: str) -> float:
    """The SI value of one answer."""
    row = next(a for a in solution.answers if a.name == name)
    return float(row.value)


@pytest.mark.parametrize("name", BUNDLED)
def test_bundled_newcomer_problems_pass_their_keys(name: str) -> None:
    solution = solve_file(ROOT / "problems" / "kinematics" / f"{name}.dyn")
    assert solution.key, "the problem has an answers: key"
    assert all(k.passed for k in solution.key), [k.detail for k in solution.key]


# x = t^3 - 6t^2 + 9t (m, s): v = 3(t - 1)(t - 3); x(0) = 0, x(1) = 4, x(3) = 0, x(4) = 4.
CUBIC = """given:
  c_3 = 1 m/s^3
  c_2 = 6 m/s^2
  c_1 = 9 m/s
  t_1 = 2 s
  t_2 = 4 s
kinematics:
  x = c_3*t^3 - c_2*t^2 + c_1*t
"""


def test_distance_between_two_times_splits_at_the_stop() -> None:
    # from t = 2 (x = 8 - 24 + 18 = 2) to t = 4 (x = 4), v = 0 at t = 3 (x = 0):
    # s = |0 - 2| + |4 - 0| = 6 m, while the displacement is only 2 m.
    solution = solve_text(CUBIC + "find: s = distance(t_1, t_2), x_1 = x(t_1)\n")
    assert answer(solution, "s") == pytest.approx(6.0, rel=1e-9)
    assert answer(solution, "x_1") == pytest.approx(2.0, rel=1e-9)


def test_max_over_an_interval_includes_the_end_point() -> None:
    # local max without an interval: x(1) = 4 m; over 0..5 s the end point x(5) = 20 m wins.
    text = CUBIC.replace("kinematics:", "  t_3 = 5 s\nkinematics:")
    solution = solve_text(text + "find: h = max(x), h_5 = max(x, t_3), v_low = min(v)\n")
    assert answer(solution, "h") == pytest.approx(4.0, rel=1e-9)
    assert answer(solution, "h_5") == pytest.approx(20.0, rel=1e-9)
    # v = 3t^2 - 12t + 9 is smallest where dv/dt = 6t - 12 = 0: t = 2, v = 12 - 24 + 9 = -3 m/s
    assert answer(solution, "v_low") == pytest.approx(-3.0, rel=1e-9)


def test_time_at_a_position_is_the_first_after_t0() -> None:
    # x = t (t - 3)^2 is 0 at t = 0 (not after t0) and again at t = 3 s.
    text = CUBIC.replace("kinematics:", "  x_b = 0 m\nkinematics:")
    solution = solve_text(text + "find: t_b = t_at(x, x_b)\n")
    assert answer(solution, "t_b") == pytest.approx(3.0, rel=1e-9)


def test_time_at_and_evaluation_at_an_earlier_find() -> None:
    # v = 0 first at t = 1 s; x there = 4 m; a = 6t - 12 = -6 m/s^2 there.
    text = CUBIC + "find: t_s = t_at(v, 0), x_s = x(t_s), a_s = a(t_s)\n"
    solution = solve_text(text)
    assert answer(solution, "t_s") == pytest.approx(1.0, rel=1e-9)
    assert answer(solution, "x_s") == pytest.approx(4.0, rel=1e-9)
    assert answer(solution, "a_s") == pytest.approx(-6.0, rel=1e-9)


def test_a_root_that_is_never_reached_is_a_positioned_error() -> None:
    # v = 3(t-1)(t-3) is zero only twice: a third time does not exist.
    with pytest.raises(SpecError, match="2 times after t₀, not 3") as caught:
        solve_text(CUBIC + "find: t_c = t_at(v, 0, 3)\n")
    assert caught.value.position.line == 9


# Constant deceleration b from v_0: v = v_0 - b t, x = v_0 t - b t^2/2, v^2 = v_0^2 - 2 b x.
CAR = """given:
  b = 5 m/s^2
  v_0 = 25 m/s
  v_1 = 10 m/s
  x_1 = 40 m
kinematics:
  a = -b
"""


def test_constant_acceleration_inverse_relations() -> None:
    # t(v_1) = (25 - 10)/5 = 3 s; x(v_1) = (625 - 100)/10 = 52.5 m;
    # v(x_1) = sqrt(625 - 400) = 15 m/s; t(x_1) = (25 - 15)/5 = 2 s.
    text = CAR + "find: t_1 = t(v_1), x_v = x(v_1), v_x = v(x_1), t_x = t(x_1)\n"
    solution = solve_text(text)
    assert answer(solution, "t_1") == pytest.approx(3.0, rel=1e-9)
    assert answer(solution, "x_v") == pytest.approx(52.5, rel=1e-9)
    assert answer(solution, "v_x") == pytest.approx(15.0, rel=1e-9)
    assert answer(solution, "t_x") == pytest.approx(2.0, rel=1e-9)


def test_constant_acceleration_symbolic_stopping_formulas() -> None:
    # symbolic givens: t_s = v_0/b and x_s = v_0^2/(2 b) (v = 0 in v = v_0 - b t, v^2 = ...)
    text = """given:
  b: m/s^2
  v_0: m/s
kinematics:
  a = -b
find: t_s = t_at(v, 0), x_s = x_at(v, 0)
answers:
  t_s = v_0/b
  x_s = v_0^2/(2*b)
"""
    solution = solve_text(text)
    assert all(k.passed for k in solution.key), [k.detail for k in solution.key]


# a = -k x with k = 4 1/s^2, v_0 = 6 m/s from x_0 = 1 m: v^2 = 36 - 4 (x^2 - 1) = 40 - 4 x^2,
# v = 0 at x = sqrt(10) = 3.16228 m (ahead of x_0, the sense of v_0).
SPRING = """given:
  k = 4 1/s^2
  v_0 = 6 m/s
  x_0 = 1 m
kinematics:
  a = -k*x
find: x_s = x_at(v, 0), x_top = max(x), x_low = min(x)
"""


def test_turning_point_of_an_a_of_x_law() -> None:
    solution = solve_text(SPRING)
    assert answer(solution, "x_s") == pytest.approx(math.sqrt(10), rel=1e-9)
    assert answer(solution, "x_top") == pytest.approx(math.sqrt(10), rel=1e-9)
    # it swings back to -sqrt(10) (the amplitude of x = A sin(2t + φ), A^2 = 1 + 9 = 10)
    assert answer(solution, "x_low") == pytest.approx(-math.sqrt(10), rel=1e-9)


# a = -k v (k = 2 1/s, v_0 = 4 m/s): v = v_0 e^(-k t) never reaches 0; x(v) = (v_0 - v)/k.
DRAG = """given:
  k = 2 1/s
  v_0 = 4 m/s
  v_1 = 1 m/s
kinematics:
  a = -k*v
"""


def test_a_of_v_time_at_a_speed_and_never_stopping() -> None:
    # t(v_1) = ln(v_0/v_1)/k = ln 4 / 2 = 0.693147 s; x there = (4 - 1)/2 = 1.5 m
    solution = solve_text(DRAG + "find: t_1 = t_at(v, v_1), x_1 = x_at(v, v_1)\n")
    assert answer(solution, "t_1") == pytest.approx(math.log(4) / 2, rel=1e-9)
    assert answer(solution, "x_1") == pytest.approx(1.5, rel=1e-9)
    with pytest.raises(SpecError, match="never"):
        solve_text(DRAG + "find: t_s = t_at(v, 0)\n")


def test_define_an_expression_of_finds() -> None:
    # cubic: x(t_2 = 4) - x(t_1 = 2) = 4 - 2 = 2 m; a define may call x(t_2) directly.
    text = CUBIC + "define:\n  d = x(t_2) - x(t_1)\n  w = 2*d\nfind: x_2 = x(t_2), d\n"
    solution = solve_text(text)
    assert answer(solution, "d") == pytest.approx(2.0, rel=1e-9)
    assert answer(solution, "w") == pytest.approx(4.0, rel=1e-9)


def test_event_errors_are_positioned_with_hints() -> None:
    with pytest.raises(SpecError, match="'y' is not a quantity of one-line motion") as caught:
        solve_text(CUBIC + "find: t_y = t_at(y, 0)\n")
    assert (caught.value.position.line, caught.value.position.column) == (9, 13)
    with pytest.raises(SpecError, match="has no unit"):
        solve_text(CUBIC + "find: t_y = t_at(x, 3)\n")
    with pytest.raises(SpecError, match="'t_1' is time, but x is length"):
        solve_text(CUBIC + "find: t_y = t_at(x, t_1)\n")
    with pytest.raises(SpecError, match="takes 1 or 2 arguments"):
        solve_text(CUBIC + "find: s = distance(t_1, t_2, t_1)\n")


def test_unused_given_is_named_with_a_did_you_mean_in_the_json(tmp_path: Path) -> None:
    # t_20 is never read (the finds read t_1 and t_2); it is close to t_2.
    spec = tmp_path / "k.dyn"
    text = CUBIC.replace("  t_2 = 4 s\n", "  t_2 = 4 s\n  t_20 = 3 s\n")
    spec.write_text(text + "find: s = distance(t_1, t_2)\n")
    result = CliRunner().invoke(app, ["solve", str(spec), "--format", "json"])
    assert result.exit_code == 0, result.output
    checks = json.loads(result.output)["checks"]
    note = next(c for c in checks if c["name"] == "unused givens")
    assert note["detail"] == "t_20 (line 7; did you mean 't_2'?) is given but not used"


def test_a_start_the_law_does_not_read_is_unused() -> None:
    # x = c t carries its own start (x(0) = 0): a given x_0 = 5 m is not read.
    text = "given:\n  c = 2 m/s\n  x_0 = 5 m\nkinematics:\n  x = c*t\nfind: v_t = v(t)\n"
    solution = solve_text(text)
    note = next(c for c in solution.checks if c.name == "unused givens")
    assert "x_0 (line 3" in note.detail


def test_numeric_root_when_sympy_cannot_solve_states_the_branch() -> None:
    # v = cos t - t (m/s, t in s) is zero where cos t = t: the Dottie number 0.7390851332 s.
    # x = sin t - t²/2 there; sin t* = sqrt(1 - t*²) = 0.6736120 (cos t* = t*), so
    # x_s = 0.6736120 - 0.7390851²/2 = 0.6736120 - 0.2731234 = 0.4004886 m.
    text = """given:
  v_1 = 1 m/s
  w = 1 1/s
  c = 1 m/s^2
kinematics:
  v = v_1*cos(w*t) - c*t
find: t_s = t_at(v, 0), x_s = x_at(v, 0)
"""
    solution = solve_text(text)
    assert answer(solution, "t_s") == pytest.approx(0.7390851332, rel=1e-8)
    assert answer(solution, "x_s") == pytest.approx(0.4004886, rel=1e-6)
    step = next(s for s in solution.steps if s.unknowns == ("t_s",))
    assert "first sign change" in step.note and "later roots not sought" in step.note


def test_a_position_past_the_turning_point_is_an_error_not_a_complex_answer() -> None:
    # the car stops at x = v_0²/(2b) = 62.5 m; v(100 m) = sqrt(625 - 1000) is not real.
    text = CAR.replace("x_1 = 40 m", "x_1 = 100 m") + "find: v_x = v(x_1)\n"
    with pytest.raises(SpecError, match="v_x is not real") as caught:
        solve_text(text)
    assert (caught.value.position.line, caught.value.position.column) == (8, 7)
