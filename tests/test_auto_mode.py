"""``--mode auto``: float64 first, a 30-digit re-solve, exact when more than 3 digits are lost."""

from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.pipeline import solve_file, solve_text
from dynsolve.system import SolveOptions

DATA = Path(__file__).resolve().parent / "data" / "scale"


def _precision(solution) -> str:  # type: ignore[no-untyped-def]
    (check,) = [c for c in solution.checks if c.name == "precision"]
    assert check.passed
    return check.detail


def test_well_conditioned_problem_stays_numeric() -> None:
    # W = m g = 2 kg * 9.81 m/s^2 = 19.62 N: nothing to lose, float64 is kept.
    solution = solve_text(
        "given:\n  m = 2 kg\nequations:\n  W = m*g\nfind: W\n", options=SolveOptions(mode="auto")
    )
    assert solution.answers[0].value == pytest.approx(19.62, rel=1e-15)
    assert _precision(solution).startswith("auto mode: numeric (float64) kept")


def test_cancellation_after_a_rounded_root_escalates_to_exact() -> None:
    # y^3 = 2, then z (y^3 - 2 + c) = 1 with c = 1e-10: exactly z = 1/c = 1e10. A 15-digit
    # y leaves ~1e-15 in y^3 - 2, about 1e-5 of c, so float64 loses ~5 digits of z (numeric
    # mode gives 9.99999917e9); auto must notice and answer exactly.
    numeric = solve_file(DATA / "cancellation.dyn", SolveOptions(mode="numeric"))
    auto = solve_file(DATA / "cancellation.dyn", SolveOptions(mode="auto"))
    z_numeric = {r.name: r.value for r in numeric.answers}["z"]
    z_auto = {r.name: r.value for r in auto.answers}["z"]
    assert abs(z_numeric - 1e10) > 1e-9 * 1e10  # float64 really lost digits here
    assert z_auto == pytest.approx(1e10, rel=1e-12)
    assert "escalated to exact" in _precision(auto)


def test_cli_accepts_mode_auto_and_says_what_ran() -> None:
    result = CliRunner().invoke(app, ["solve", "--mode", "auto", str(DATA / "cancellation.dyn")])
    assert result.exit_code == 0, result.output
    assert "precision" in result.output
    assert "escalated to exact" in " ".join(result.output.split())


def test_exact_past_its_share_of_the_budget_keeps_the_30_digit_answers() -> None:
    # The same cancellation (z = 1/c = 1e10 exactly), with an exact solve that never ends
    # (a stand-in for a symbolic cliff): auto must not fail the whole solve, but keep the
    # 30-digit re-solve's answer, which has the digits float64 lost, and say so.
    from dynsolve.pipeline import solve_spec
    from dynsolve.precision import EXACT_SHARE, solve_auto
    from dynsolve.spec.parser import parse_file

    def endless_exact(spec, options):  # type: ignore[no-untyped-def]
        if options.mode == "exact":
            while True:
                sum(range(1000))
        return solve_spec(spec, options)

    options = SolveOptions(mode="auto", time_budget=0.2)
    auto = solve_auto(parse_file(DATA / "cancellation.dyn"), options, endless_exact)
    assert {r.name: r.value for r in auto.answers}["z"] == pytest.approx(1e10, rel=1e-12)
    detail = _precision(auto)
    assert "ran past its share of the budget" in detail
    assert f"({EXACT_SHARE * 0.2:g} s CPU)" in detail and "30-digit" in detail
