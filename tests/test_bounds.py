"""Bounds on the size of numbers (issue 10, items 1 and 4): every reproducer is a clear error.

Each hostile spec must end with exit code 2 and a ``file:line:column`` message naming
the cause, quickly and without building the huge number (each case runs well under 1 s).
Magnitudes quoted in the comments are worked by hand from logarithms.
"""

from __future__ import annotations

import json
import math
import time
from pathlib import Path

import pytest
import sympy
from typer.testing import CliRunner

from dynsolve.cli import ExitCode, app
from dynsolve.format import quantity, sig
from dynsolve.magnitude import OutOfRange, bound, value_bound
from dynsolve.numbers import mpmath_function

runner = CliRunner()
SQUARES = "\n".join(f"  x_{i} = x_{i - 1}^2" for i in range(2, 31))


def _cpu_seconds() -> float:
    """CPU seconds of this process and of its children that have ended (the worker)."""
    try:
        import resource
    except ImportError:  # Windows: wall time
        return time.perf_counter()
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return time.process_time() + children.ru_utime + children.ru_stime


def _solve(tmp_path: Path, text: str, *options: str) -> tuple[int, str]:
    path = tmp_path / "hostile.dyn"
    path.write_text(text, encoding="utf-8")
    started = _cpu_seconds()
    result = runner.invoke(app, ["solve", str(path), *options])
    # CPU seconds of this process and its (joined) worker: the wall clock depends on the load
    assert _cpu_seconds() - started < 5, "the bound must trigger before any heavy work"
    return result.exit_code, result.output


@pytest.mark.parametrize(
    ("equations", "where", "cause"),
    [
        # 10^(10^10): log10 = 10^10
        pytest.param("  y = 10^10^10", ":2:7:", "1.0e10000000000 is out of range", id="tower"),
        # 2^(2^(2^(2^(2^2)))) = 2^(2^65536)... the first too large is 2^65536 ~ 10^19728
        pytest.param("  y = 2^2^2^2^2^2", ":2:", "e19728 is out of range", id="tower-of-2"),
        # (2^64)^64 = 2^4096 ~ 10^1233 (4096 * log10 2 = 1233.0)
        pytest.param("  y = ((2^64)^64)^64", ":2:", "1.0e1233 is out of range", id="nested"),
        # 64^5 = 2^30 = 1073741824
        pytest.param(
            "  y = 10^(64*64*64*64*64)", ":2:7:", "1.0e1073741824 is out", id="product-exponent"
        ),
        # exp(exp(10)) = exp(22026.5) ~ 10^9565.9
        pytest.param(
            "  y = exp(exp(exp(exp(10))))", ":2:", "e9565 is out of range", id="exp-tower"
        ),
        # exponent from another equation: 10^(10^5)
        pytest.param("  n = 10^5\n  y = 10^n", ":3:3:", "1.0e100000 is out of range", id="solved"),
        # x_k = 10^(50 * 2^(k-1)): x_4 = 10^400 is the first beyond 10^300 (line 5)
        pytest.param(
            f"  x_1 = 10^50\n{SQUARES}\n  y = x_30",
            ":5:3:",
            "1.0e400 is out of range",
            id="squares",
        ),
        # 10^-100 to the fourth power is 10^-400: it would print as 0
        pytest.param("  y = (1e-100)^4", ":2:", "1.0e-400 is too small", id="underflow"),
        # 1.000001^4096: about 7 * 4096 digits as an exact rational
        pytest.param("  y = (1.000001^64)^64", ":2:", "digits (limit 1000)", id="digits"),
        # a power of an unknown keeps the parser's exponent limit, however it is written
        pytest.param("  y = x^(8*8*8)\n  x = 2", ":2:", "exponent 512 is too large", id="power"),
    ],
)
@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_huge_values_are_refused_with_their_line(
    tmp_path: Path, equations: str, where: str, cause: str, mode: str
) -> None:
    code, output = _solve(tmp_path, f"equations:\n{equations}\nfind: y\n", "--mode", mode)
    assert code == ExitCode.BAD_INPUT, output
    assert f"hostile.dyn{where}" in output
    assert cause in output
    assert "hint:" in output
    assert "Traceback" not in output


@pytest.mark.parametrize(
    ("text", "where", "cause"),
    [
        # n^n = 10^10, so 10^(n^n) has 10^10 digits; caught before n is put in
        pytest.param(
            "given:\n  n = 10\nequations:\n  y = 10^(n^n)\nfind: y\n",
            ":4:3:",
            "1.0e10000000000 is out of range",
            id="exponent-from-a-given",
        ),
        pytest.param(
            "given:\n  n = 10\nequations:\n  y = 3*n\nfind: y\nanswers:\n  y = 10^(n^n)\n",
            ":7:3:",
            "1.0e10000000000 is out of range",
            id="answer-formula",
        ),
        # 10^64 to the 64th is 10^4096: 4097 digits, near what Python prints (4300 digits)
        pytest.param(
            "equations:\n  y = 3\nfind: y\nanswers:\n  y = (10^64)^64\n",
            ":5:",
            "1.0e4096 is out of range",
            id="answer-key-digits",
        ),
        pytest.param(
            "given:\n  n = 10\n  c = 1 1/s\n  v_0 = 2 m/s\n  t_1 = 2 s\n"
            "kinematics:\n  a = -10^(n^n)*c*v\nfind: v_1 = v(t_1)\n",
            ":7:8:",
            "1.0e10000000000 is out of range",
            id="kinematics",
        ),
        pytest.param(
            "given:\n  n = 10\n  g = 9.81 m/s^2\n  t_1 = 1 s\n"
            "kinematics:\n  a_x = 0\n  a_y = -10^(n^n)*g\nfind: y_1 = y(t_1)\n",
            ":7:10:",
            "1.0e10000000000 is out of range",
            id="plane-kinematics",
        ),
        pytest.param(
            "given:\n  n = 10\n  m = 2 kg\nscene:\n  point O: (0, 0)\n"
            "  body blk: particle, mass m*10^(n^n), at (0, 0)\n  gravity\nfind: a = a_G(blk)\n",
            ":6:30:",
            "1.0e10000000000 is out of range",
            id="scene",
        ),
    ],
)
def test_values_put_in_later_are_bounded(tmp_path: Path, text: str, where: str, cause: str) -> None:
    code, output = _solve(tmp_path, text)
    assert code == ExitCode.BAD_INPUT
    assert f"hostile.dyn{where}" in output and cause in output


@pytest.mark.parametrize(
    ("unit", "cause"),
    [
        # converting 1e99999999 to a Fraction would build a 10^8-digit integer
        pytest.param("N^1e99999999", "exponent 99999999 is out of range", id="e-notation"),
        # 300 digits: checked as text, never printed whole
        pytest.param("N^1" + "0" * 300, "more than 40 digits", id="long"),
        pytest.param("N^(1e50/3)", "unit exponent 100000000000… is out of range", id="fraction"),
        # 1e-30 = 1/10^30: small, but its denominator would make a unit no one can read back
        pytest.param("N^1e-30", "denominator at most 12", id="tiny"),
        pytest.param("N^(1/13)", "unit exponent 1/13 is out of range", id="denominator"),
    ],
)
def test_unit_exponents_are_checked_as_text(tmp_path: Path, unit: str, cause: str) -> None:
    code, output = _solve(tmp_path, f"given:\n  F = 2 {unit}\nequations:\n  y = F\nfind: y\n")
    assert code == ExitCode.BAD_INPUT
    assert "hostile.dyn:2:" in output and cause in output


@pytest.mark.parametrize("value", ["1e400", "1e-400"])
def test_out_of_range_givens_are_refused(tmp_path: Path, value: str) -> None:
    code, output = _solve(tmp_path, f"given:\n  W = {value} N\nequations:\n  y = W\nfind: y\n")
    assert code == ExitCode.BAD_INPUT
    assert "hostile.dyn:2:7:" in output and "out of range" in output


def _strict(text: str) -> object:
    def refuse(constant: str) -> None:
        raise ValueError(f"non-standard JSON constant {constant}")

    return json.loads(text, parse_constant=refuse)


def test_json_output_is_strict(tmp_path: Path) -> None:
    # 2e299 is finite (the limit is 1e300); 1/(n - 2) with n = 2 has no value
    text = "given:\n  n = 2\nequations:\n  y = 2e100*1e100*1e99\n  z = 1/(n - 2)\nfind: y, z\n"
    code, output = _solve(tmp_path, text, "--format", "json")
    assert code == ExitCode.FAILED  # z's equation has no solution
    data = _strict(output)
    assert isinstance(data, dict)
    assert data["answers"][0]["value"] == pytest.approx(2e299)


def test_a_non_finite_answer_is_a_failed_check_not_inf() -> None:
    from dynsolve.render.json import render_json
    from dynsolve.results import AnswerRow, Check, Solution

    row = AnswerRow("y", math.inf, "N", quantity(math.inf, "N"), "", "", "")
    solution = Solution(
        "f.dyn", "T", "", "SI", "equations", (), (), (), (row,), (Check("finite", False, ""),),
        (), "solved",
    )  # fmt: skip
    assert "inf" not in row.shown and not solution.passed
    assert _strict(render_json(solution))["answers"][0]["value"] is None  # type: ignore[index]
    assert sig(math.nan) == sig(math.inf) == "not a finite number"


def test_large_but_finite_values_still_solve(tmp_path: Path) -> None:
    # 10^150 squared is 10^300: the largest magnitude allowed
    code, output = _solve(tmp_path, "equations:\n  x = 1e100*1e50\n  y = x^2\nfind: y\n")
    assert code == ExitCode.OK, output
    assert "1.00e300" in output


@pytest.mark.parametrize("name", ["mpf", "mpc", "matrix"])
def test_unknowns_named_like_mpmath_functions_solve_numerically(tmp_path: Path, name: str) -> None:
    # x = cos(y)/2 + 1/4, y = sin(x) + 1 has the root x = 0.358897 rad = 20.56 deg
    # (Newton by hand: x = 0.3589, y = 1 + sin(0.3589) = 1.3512, cos(1.3512)/2 + 0.25 = 0.3589)
    text = f"equations:\n  {name} = cos(y)/2 + 0.25\n  y = sin({name}) + 1\nfind: {name}, y\n"
    code, output = _solve(tmp_path, text, "--mode", "numeric")
    assert code == ExitCode.OK, output
    assert "20.6 deg" in output


def test_mpmath_function_renames_colliding_names() -> None:
    mpf = sympy.Symbol("mpf")
    function = mpmath_function([mpf], sympy.Matrix([[mpf * sympy.Rational(1, 2)]]))
    assert float(function(3)[0]) == 1.5  # type: ignore[index]


def test_bounds_of_known_values() -> None:
    # 2^64 = 1.8e19 is fine; its square is 3.4e38
    x = sympy.Symbol("x")
    assert bound(x**2, {x: value_bound(sympy.Integer(2) ** 64)}).high == pytest.approx(2.0**128)
    with pytest.raises(OutOfRange, match=r"1\.0e308"):
        bound(x**2, {x: value_bound(sympy.Integer(10) ** 154)})
    assert not bound(x**2, {}).known  # an unknown stays unbounded


def test_an_underflowing_coefficient_does_not_reach_math_log() -> None:
    # 1e-400 is a nonzero sympy Float whose float() is 0.0: no scale can be taken from it;
    # x^3 + x = 1e-400 has the single real root x = 1e-400 (to first order), i.e. about 0
    from dynsolve.solver.blocks import numeric_roots

    x = sympy.Symbol("x")
    roots = numeric_roots([x**3 + x - sympy.Float("1e-400")], [x])
    assert roots and abs(float(sympy.re(roots[0][0]))) < 1e-12


def test_a_decimal_beyond_a_float_is_reported_by_its_size_not_as_inf():
    # regression: float() of a 30-digit Float 1.5e36683 is inf, and the message read
    # "a value of about 10^inf"
    import sympy

    from dynsolve.magnitude import OutOfRange, value_bound

    with pytest.raises(OutOfRange) as info:
        value_bound(sympy.Float("1.5e36683", 30))
    assert "1.5e36683" in info.value.message and "inf" not in info.value.message
