"""``--mode auto``: solve in float64, measure the digits it loses, escalate when too many.

The spec is solved numerically (15 significant digits, float64-like), then again with
every numeric value computed to 30 digits (the root finder works 20 guard digits beyond).
The largest relative gap between the two sets of answers estimates what float64 lost
through the problem's conditioning. When it exceeds 1e-12 (more than 3 of float64's 15
digits lost), or the two runs disagree on a check, the exact solve runs and its answers
are the result. The exact solve gets a share of the budget, :data:`EXACT_SHARE` times the
per-block symbolic budget in CPU seconds (10 s by default): past it, the 30-digit
re-solve's answers are kept instead of failing the whole solve. The solution's messages
and its ``precision`` check say which mode finally ran and why.

>>> from dynsolve.spec.parser import parse_spec
>>> from dynsolve.pipeline import solve_spec
>>> spec = parse_spec("given:\\n  m = 2 kg\\nequations:\\n  W = m*g\\nfind: W\\n")
>>> solution = solve_auto(spec, SolveOptions(mode="auto"), solve_spec)
>>> solution.messages[-1].startswith("auto mode: numeric (float64) kept")
True
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import replace

from dynsolve.errors import DynsolveError
from dynsolve.results import Check, Solution
from dynsolve.solver.blocks import BudgetExceeded, time_budget, working_digits
from dynsolve.spec.ast import Spec
from dynsolve.system import SolveOptions

HIGH_DIGITS = 30  # the reference re-solve
LOST_LIMIT = 1e-12  # float64 keeps ~15 digits; more than 3 lost means a gap above this
EXACT_SHARE = 2.0  # the exact solve's CPU seconds, in per-block budgets (SolveOptions)

__all__ = ["EXACT_SHARE", "HIGH_DIGITS", "LOST_LIMIT", "relative_gap", "solve_auto"]


def relative_gap(fast: Solution, reference: Solution) -> float:
    """The largest relative difference between two solutions' answers (inf if they differ
    in kind: one symbolic or missing where the other has a number).

    >>> from dynsolve.results import AnswerRow
    >>> row = AnswerRow("x", 2.0, "m", "2 m", "2", "2", "")
    >>> a = Solution("f", "t", "", "SI", "equation", (), (), (), (row,), (), (), "solved")
    >>> b = replace(a, answers=(replace(row, value=2.0 + 2e-9),))
    >>> f"{relative_gap(a, b):.0e}"
    '1e-09'
    """
    reference_values = {row.name: row.value for row in reference.answers}
    worst = 0.0
    for row in fast.answers:
        other = reference_values.get(row.name, math.nan)
        if row.value is None or other is None:
            if (row.value is None) != (other is None):
                return math.inf
            continue
        if math.isnan(other) or not math.isfinite(row.value) or not math.isfinite(other):
            return math.inf
        scale = max(abs(row.value), abs(other))
        if scale:
            worst = max(worst, abs(row.value - other) / scale)
    return worst


def _verdicts(solution: Solution) -> tuple[tuple[str, bool], ...]:
    return tuple((check.name, check.passed) for check in solution.checks)


def solve_auto(
    spec: Spec, options: SolveOptions, solve: Callable[[Spec, SolveOptions], Solution]
) -> Solution:
    """Numeric first; a 30-digit re-solve measures float64's loss; exact when it is too large.

    ``solve`` is the pipeline's ``solve_spec`` (passed in to keep the import one-way).
    """
    numeric = replace(options, mode="numeric")
    fast = solve(spec, numeric)
    with working_digits(HIGH_DIGITS):
        reference = solve(spec, numeric)
    gap = relative_gap(fast, reference)
    if gap <= LOST_LIMIT and _verdicts(fast) == _verdicts(reference):
        note = (
            f"auto mode: numeric (float64) kept; a {HIGH_DIGITS}-digit re-solve agrees "
            f"to {gap:.1e} relative (limit {LOST_LIMIT:.0e})"
        )
        return _noted(fast, note)
    why = (
        f"the checks differ from a {HIGH_DIGITS}-digit re-solve"
        if gap <= LOST_LIMIT
        else f"float64 answers differ from a {HIGH_DIGITS}-digit re-solve by {gap:.1e} "
        f"relative, more than 3 digits lost"
    )
    share = EXACT_SHARE * options.time_budget
    started = time.process_time()
    try:
        with time_budget(share):
            exact = solve(spec, replace(options, mode="exact"))
    except BudgetExceeded:
        return _numeric_kept(reference, why, share, gap)
    except DynsolveError:
        if time.process_time() - started < share:
            raise  # the spec's own error, not the budget's
        return _numeric_kept(reference, why, share, gap)  # a step gave up as the budget ran out
    return _noted(exact, f"auto mode: escalated to exact; {why}")


def _numeric_kept(reference: Solution, why: str, share: float, gap: float) -> Solution:
    """The 30-digit re-solve as the result, when the exact solve ran past its share of the
    budget; its ``precision`` check passes only when its answers could be compared with
    float64's (a finite gap), since nothing else confirms them."""
    note = (
        f"auto mode: {why}; the exact solve ran past its share of the budget "
        f"({share:g} s CPU), so the {HIGH_DIGITS}-digit numeric re-solve's answers are kept"
    )
    return _noted(reference, note, passed=math.isfinite(gap))


def _noted(solution: Solution, note: str, passed: bool = True) -> Solution:
    """``solution`` with the auto-mode verdict as a message and as a ``precision`` check."""
    return replace(
        solution,
        messages=(*solution.messages, note),
        checks=(*solution.checks, Check("precision", passed, note)),
    )
