"""Draw, solve and check each student's variant; redraw those whose assumptions change.

A variant is kept when it solves with the same outcome as the base problem: the same
status, every assumption (no slip, contact kept, cord taut, …) holding or failing as in
the base problem, and no check failing that passes there (the answer key is the base
problem's, so it is not compared); otherwise it is redrawn, at most ``MAX_ATTEMPTS``
times, then refused with an error that names the student. With ``allow changes`` in the
``vary`` section only the checks count: a variant may slip where the base problem rolls
(re-solved with kinetic friction and checked).

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec('''
... given:
...   m = 50 kg
... vary:
...   m = 40..60 kg step 5
... equations:
...   W = m*g
... find: W
... ''', "p.dyn")
>>> rows = make_variants(spec, ["s01", "s02"], seed=7)
>>> [r.student for r in rows], all(r.cells["m"].endswith(" kg") for r in rows)
(['s01', 's02'], True)
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

from dynsolve.budget import Budget
from dynsolve.errors import DynsolveError, Position, SpecError
from dynsolve.format import sig
from dynsolve.grade.substitute import read_cell, with_variant
from dynsolve.grade.variants import TWIN_SUFFIX, VariantRow
from dynsolve.grade.vary import Variation, allows_changes, draw, vary_plan
from dynsolve.quantities import resolve_quantity, unit_info
from dynsolve.results import Solution
from dynsolve.spec.ast import Spec
from dynsolve.system import SolveOptions
from dynsolve.units import from_base, natural_unit

MAX_ATTEMPTS = 20
VARIANT_BUDGET = Budget(seconds=60.0)  # one variant's full solve (every bundled one: < 6 s)
Units = str  # "si", "us" or "both"


@dataclass(frozen=True)
class Signature:
    """What must not change between the base problem and a variant."""

    status: str
    assumptions: tuple[tuple[str, str], ...]  # name, "passed", "failed" or "not_run"
    failed: tuple[str, ...]  # checks that fail (answer key left out)

    def differs(self, other: Signature, allow_changes: bool = False) -> str:
        """Why ``other`` (a variant) is not like ``self`` (the base); "" when it is. With
        ``allow_changes``, its assumptions may differ (its checks must still pass)."""
        if allow_changes:
            new = sorted(set(other.failed) - set(self.failed))
            return f"check '{new[0]}' fails" if new else ""
        if other.status != self.status:
            return f"the solve ends '{other.status}', not '{self.status}'"
        mine = dict(self.assumptions)
        words = {"passed": "holds", "failed": "fails", "not_run": "is not decided"}
        for name, status in other.assumptions:
            if mine.get(name) != status:
                return f"assumption '{name}' {words[status]} (base: " + (
                    "not made)" if name not in mine else f"{words[mine[name]]})"
                )
        if len(other.assumptions) != len(self.assumptions):
            return "its assumptions are not the base problem's"
        new = sorted(set(other.failed) - set(self.failed))
        return f"check '{new[0]}' fails" if new else ""


def signature(solution: Solution) -> Signature:
    """The outcome of a solve that a variant must share with its base problem.

    >>> from dynsolve.pipeline import solve_text
    >>> signature(solve_text("given:\\n  m = 2 kg\\nequations:\\n  W = m*g\\nfind: W\\n"))
    Signature(status='solved', assumptions=(), failed=())
    """
    return Signature(
        solution.status,
        tuple((a.name, a.status) for a in solution.assumptions),
        tuple(c.name for c in solution.checks if c.failed and not c.name.startswith("answer ")),
    )


def make_variants(
    spec: Spec,
    roster: Sequence[str],
    seed: int,
    units: Units = "si",
    options: SolveOptions | None = None,
    progress: Callable[[int], None] | None = None,
) -> list[VariantRow]:
    """Every student's checked variant (and US twin for ``units`` us/both), in roster order."""
    from dynsolve.pipeline import solve_spec

    plan = vary_plan(spec)
    if not plan:
        raise SpecError(
            "the problem has no 'vary:' section",
            Position(spec.file, 1, 1),
            hint="add one, e.g. 'vary:' then '  m = 40..60 kg step 5'",
        )
    options = options or SolveOptions()
    base = signature(solve_spec(with_variant(spec, {}, "base"), options))
    if base.failed:
        raise SpecError(
            f"the base problem fails check '{base.failed[0]}': fix it before drawing variants",
            Position(spec.file, 1, 1),
            hint="run 'dynsolve solve' on it",
        )
    accepted = _closed_form_accepts(spec, plan, seed, roster, options)
    rows: list[VariantRow] = []
    for done, student in enumerate(roster, start=1):
        cells = accepted.get(student) or _checked_draw(spec, plan, seed, student, base, options)
        if units in ("si", "both"):  # as drawn: in the spec's own system
            rows.append(VariantRow(student, "US" if spec.system == "FPS" else "SI", cells))
        if units in ("us", "both"):
            twin = us_twin(spec, cells)
            reason = _why_not(spec, twin, f"{student}{TWIN_SUFFIX}", base, options)
            if reason:
                raise SpecError(
                    f"student {student}: the US customary twin of the variant differs from "
                    f"the base problem: {reason}",
                    Position(spec.file, 1, 1),
                    hint="use --units si, or narrow the vary ranges",
                )
            student_id = student if units == "us" else f"{student}{TWIN_SUFFIX}"
            rows.append(VariantRow(student_id, "US", twin))
        if progress is not None:
            progress(done)
    return rows


def _closed_form_accepts(
    spec: Spec, plan: Sequence[Variation], seed: int, roster: Sequence[str], options: SolveOptions
) -> dict[str, dict[str, str]]:
    """The first draws that the problem's closed form answers on the base problem's branch
    (its conditions, and a sample checked by full solves: :mod:`dynsolve.grade.expected`),
    kept without a full solve each; the others (and every draw when there is no closed
    form) go through :func:`_checked_draw`. 10,000 students: seconds instead of minutes."""
    from dynsolve.grade.expected import expected_answers

    first = {student: draw(plan, seed, student, 0) for student in roster}
    result = expected_answers(spec, first, options)
    return {
        student: first[student]
        for student in roster
        if result[student].path == "vectorized" and not result[student].error
    }


def _checked_draw(
    spec: Spec,
    plan: Sequence[Variation],
    seed: int,
    student: str,
    base: Signature,
    options: SolveOptions,
) -> dict[str, str]:
    reason = ""
    for attempt in range(MAX_ATTEMPTS):
        cells = draw(plan, seed, student, attempt)
        reason = _why_not(spec, cells, student, base, options)
        if not reason:
            return cells
    lines = ", ".join(str(v.line) for v in plan)
    raise SpecError(
        f"student {student}: no valid variant in {MAX_ATTEMPTS} draws; the last one: {reason}",
        Position(spec.file, plan[0].line, 1),
        hint=f"narrow the vary ranges (lines {lines}) to where the base problem's "
        "assumptions hold, or write 'allow changes' in 'vary:' to keep variants whose "
        "assumptions differ",
    )


def _why_not(
    spec: Spec, cells: dict[str, str], student: str, base: Signature, options: SolveOptions
) -> str:
    """Why this variant cannot be used ("" when it can). Its full solve runs in a worker
    process under ``VARIANT_BUDGET`` (as ``dynsolve solve`` does): a variant that would
    solve for ever is redrawn, not waited for."""
    from dynsolve.budget import WorkerFailed, run

    try:
        solution = run(_solve_variant, (spec, cells, student, options), VARIANT_BUDGET)
    except DynsolveError as error:
        return error.message
    except WorkerFailed as error:  # a bug: said, and the variant not used
        return f"internal error while solving it: {str(error).strip().splitlines()[-1]}"
    return base.differs(signature(solution), allows_changes(spec))


def _solve_variant(
    spec: Spec, cells: dict[str, str], student: str, options: SolveOptions
) -> Solution:
    """The worker's job: one student's variant solved (module level: ``spawn`` pickles it)."""
    from dynsolve.pipeline import solve_spec

    return solve_spec(with_variant(spec, cells, student), options)


def us_twin(spec: Spec, cells: dict[str, str]) -> dict[str, str]:
    """The variant with every dimensional given (varied or not) in US customary units, to 4
    significant figures; angles and pure numbers stay as written.

    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("given:\\n  m = 50 kg\\n  L = 2 m\\nequations:\\n  W = m*g\\nfind: W\\n")
    >>> us_twin(spec, {"m": "45 kg"})
    {'m': '3.083 slug', 'L': '6.562 ft'}
    """
    twin: dict[str, str] = {}
    for given in spec.givens:
        if given.quantity is None:
            continue
        quantity = read_cell(cells[given.name]) if given.name in cells else given.quantity
        value, dim = resolve_quantity(quantity, "SI", spec.file)
        if dim.dimensionless:
            if given.name in cells:
                twin[given.name] = cells[given.name]
            continue
        unit = natural_unit(dim, "FPS", given.name)
        number = from_base(float(value), unit_info(unit), "SI")
        twin[given.name] = f"{sig(number, 4)} {unit}"
    return twin
