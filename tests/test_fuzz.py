"""Grammar-aware fuzzing: the parser and the solve path give a result or a clean error.

A clean error is a DynsolveError (the CLI prints it and exits 2); anything else is
a crash. bench/fuzz.py runs the same generators over 100,000+ inputs under time
and memory limits; this test runs a few hundred so it stays fast in CI.
"""

from __future__ import annotations

import random
import re
import tempfile
from pathlib import Path

from fuzz_grammar import bundled_problems, grammar_spec, mutated_problem
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.errors import DynsolveError
from dynsolve.spec.parser import parse_spec

SEEDS = bundled_problems()
POSITION = re.compile(r"fuzz\.dyn:\d+:\d+: ")


def spec_texts() -> st.SearchStrategy[str]:
    """Grammar-built specs and mutated bundled problems, half each."""
    built = st.randoms(use_true_random=False).map(grammar_spec)
    mutated = st.randoms(use_true_random=False).map(lambda rng: mutated_problem(rng, SEEDS))
    return st.one_of(built, mutated)


@settings(
    max_examples=200, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow]
)
@given(spec_texts())
def test_parser_gives_a_spec_or_a_positioned_error(text: str) -> None:
    try:
        parse_spec(text, "fuzz.dyn")
    except DynsolveError as error:
        assert error.position is not None, f"no file:line:column in {error}"


def _solve(text: str, mode: str) -> object:
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "fuzz.dyn"
        path.write_text(text, encoding="utf-8")
        args = ["solve", str(path), "--mode", mode, "--time-budget", "1"]
        return CliRunner().invoke(app, args)


@settings(
    max_examples=40, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow]
)
@given(spec_texts(), st.sampled_from(("exact", "numeric")))
def test_solve_exits_0_1_or_2_without_a_traceback(text: str, mode: str) -> None:
    result = _solve(text, mode)
    # CliRunner stores an uncaught exception (a traceback for a user) in result.exception;
    # typer.Exit shows up there as SystemExit.
    assert result.exception is None or isinstance(result.exception, SystemExit), repr(
        result.exception
    )
    assert result.exit_code in (0, 1, 2)
    assert "Traceback" not in result.output
    if result.exit_code == 2:
        assert "error:" in result.output


def test_generators_are_deterministic_per_seed() -> None:
    # The bench reproduces an input from its seed, so the same seed must give the same text.
    assert grammar_spec(random.Random(7)) == grammar_spec(random.Random(7))
    assert mutated_problem(random.Random(7), SEEDS) == mutated_problem(random.Random(7), SEEDS)
