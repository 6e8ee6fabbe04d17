"""Each student's expected answers for their own variant: vectorized where a closed form
answers, a full solve per variant elsewhere, and which path each student took.

Values are floats in SI base units (kg, m, s, rad), whatever the problem's unit system
and the find's display unit; where ``dynsolve solve`` shows a magnitude with a direction
(scene mode: cw/ccw, up/down, an angle), ``value`` is that magnitude and ``direction``
the word. The fast path is checked against
full solves of a sample of its rows (the first, middle and last, and for each condition the
row nearest its edge): each must take the base problem's branch (same assumptions and
checks) and agree within ``AGREE`` relative; if not, every row is solved per variant and
``reason`` says why.

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec('''
... given:
...   m = 2 kg
...   F = 10 N
... equations:
...   F = m*a
... find: a
... ''', "p.dyn")
>>> result = expected_answers(spec, {"s1": {"m": "4 kg"}, "s2": {"m": "bad"}}, SolveOptions())
>>> result["s1"].answers["a"].value, result["s1"].answers["a"].si_unit, result.path
(2.5, 'm*s^-2', 'vectorized')
>>> result["s2"].error
"cannot read m = 'bad': unexpected 'bad' in a value; expected '-' or a number"
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field, replace

from dynsolve.errors import DynsolveError
from dynsolve.grade.generate import signature
from dynsolve.grade.substitute import with_variant
from dynsolve.grade.variants import read_variants
from dynsolve.grade.vectorized import Batch, ClosedForm, NotClosedForm, build_closed_form, evaluate
from dynsolve.quantities import unit_info
from dynsolve.results import Solution
from dynsolve.spec.ast import Spec
from dynsolve.system import SolveOptions
from dynsolve.units import Dim, base_unit

__all__ = ["Expected", "ExpectedAnswers", "StudentExpected", "expected_answers", "read_variants"]

AGREE = 1e-9  # relative agreement required between the two paths


@dataclass(frozen=True)
class Expected:
    """One find's expected answer for one student."""

    name: str
    value: float  # SI base units; a magnitude where ``direction`` is stated
    si_unit: str  # the SI base unit of ``value`` (``m*s^-2``; ``rad`` for an angle)
    unit: str  # the find's display unit, as ``dynsolve solve`` shows it
    dim: Dim
    direction: str = ""  # cw, ccw, up, down, left, right, "angle 53.1°" or ""


@dataclass(frozen=True)
class StudentExpected:
    """A student's expected answers (empty, with ``error``, when their variant failed)."""

    student: str
    answers: Mapping[str, Expected]
    path: str  # "vectorized" or "per-variant"
    error: str = ""  # why the variant could not be solved ("" when it was)
    why: str = ""  # why this row was solved per variant, when it was


@dataclass(frozen=True)
class ExpectedAnswers:
    """Every student's expected answers and how they were computed."""

    students: Mapping[str, StudentExpected]
    path: str  # "vectorized", "per-variant" or "mixed: N vectorized, M per-variant"
    reason: str = ""  # why the vectorized path was not used, or not for every row
    build_seconds: float = 0.0  # the one-time symbolic build and its check by full solves
    evaluate_seconds: float = 0.0  # every variant through the closed form (cells read too)
    counts: Mapping[str, int] = field(default_factory=dict)

    def __getitem__(self, student: str) -> StudentExpected:
        return self.students[student]

    def __iter__(self) -> Iterator[str]:
        return iter(self.students)

    def __len__(self) -> int:
        return len(self.students)


def expected_answers(
    spec: Spec,
    variants: Mapping[str, Mapping[str, str]],
    options: SolveOptions,
    vectorize: bool = True,
    progress: Callable[[int, int], None] | None = None,
) -> ExpectedAnswers:
    """Expected answers of every student in ``variants`` (student → {given: cell text}).

    ``vectorize=False`` solves every variant (the baseline); ``progress(done, total)`` is
    called as students are answered (the vectorized ones at once, then one by one)."""
    students = list(variants)
    rows = [dict(variants[s]) for s in students]
    names = tuple(dict.fromkeys(n for row in rows for n, text in row.items() if text.strip()))
    form: ClosedForm | None = None
    reason = "" if vectorize else "vectorized path turned off"
    if vectorize and names:
        try:
            form = build_closed_form(spec, names, options)
        except NotClosedForm as error:
            reason = str(error)
        except DynsolveError as error:  # the base problem itself is wrong: every row says so
            reason = error.message
        except Exception as error:  # a bug in the fast path: the full solves still answer
            reason = f"internal error in the vectorized path ({type(error).__name__}: {error})"
    elif vectorize:
        reason = "no given varies"
    out: dict[str, StudentExpected] = {}
    why: dict[str, str] = {}
    evaluate_seconds = verify_seconds = 0.0
    if form is not None:
        start = time.perf_counter()
        batch = evaluate(form, rows)
        out = _from_batch(form, batch, students)
        evaluate_seconds = time.perf_counter() - start
        disagreement = verify(spec, form, batch, students, rows, options)
        verify_seconds = time.perf_counter() - start - evaluate_seconds
        if disagreement:
            reason, form, out = disagreement, None, {}
        else:
            why = {students[i]: text for i, text in batch.why_slow.items()}
            reasons = dict.fromkeys(batch.why_slow.values())
            reason = "; ".join(list(reasons)[:5])
    solved: dict[tuple[tuple[str, str], ...], StudentExpected] = {}  # same cells, same solve
    done = len(out)
    if progress is not None:
        progress(done, len(students))
    for student, row in zip(students, rows, strict=True):
        if student not in out:
            key = tuple(sorted(row.items()))
            if key not in solved:
                solved[key] = per_variant(spec, student, row, options)
            out[student] = replace(solved[key], student=student, why=why.get(student, reason))
            done += 1
            if progress is not None:
                progress(done, len(students))
    counts = {"vectorized": 0, "per-variant": 0}
    for each in out.values():
        counts[each.path] += 1
    path = (
        "vectorized"
        if not counts["per-variant"]
        else "per-variant"
        if not counts["vectorized"]
        else f"mixed: {counts['vectorized']} vectorized, {counts['per-variant']} per-variant"
    )
    build = (form.build_seconds if form is not None else 0.0) + verify_seconds
    ordered = {s: out[s] for s in students}
    return ExpectedAnswers(ordered, path, reason, build, evaluate_seconds, counts)


def _from_batch(form: ClosedForm, batch: Batch, students: list[str]) -> dict[str, StudentExpected]:
    """The rows the closed form answers (errors in cells become failed students)."""
    units = {t.name: (_si_unit(t.dim, t.unit), t.unit, t.dim) for t in form.targets}
    out: dict[str, StudentExpected] = {}
    columns = {name: values.tolist() for name, values in batch.values.items()}
    for i, student in enumerate(students):
        if i in batch.errors:
            out[student] = StudentExpected(student, {}, "vectorized", batch.errors[i])
        elif batch.fast[i]:
            answers = {
                name: Expected(name, column[i], *units[name], batch.directions[name][i])
                for name, column in columns.items()
            }
            out[student] = StudentExpected(student, answers, "vectorized")
    return out


def verify(
    spec: Spec,
    form: ClosedForm,
    batch: Batch,
    students: Sequence[str],
    rows: Sequence[Mapping[str, str]],
    options: SolveOptions,
) -> str:
    """Full solves of a few fast rows (the first, middle and last, and each condition's
    closest to its edge) must take ``spec``'s branch and agree with the closed form within
    ``AGREE`` ("" when they do, else why not)."""
    fast = [i for i in range(len(rows)) if batch.fast[i]]
    if not fast:
        return ""
    sample = sorted({fast[0], fast[len(fast) // 2], fast[-1], *batch.closest})
    base = signature(_solve(spec, "base", {}, options))  # type: ignore[arg-type]
    for i in sample:
        solution = _solve(spec, students[i], rows[i], options)
        if isinstance(solution, str):
            return f"student {students[i]}: the full solve fails ({solution})"
        branch = base.differs(signature(solution))
        if branch:
            return (
                f"student {students[i]}: the closed form takes the base problem's branch, but "
                f"a full solve differs: {branch}"
            )
        slow = _from_solution(students[i], solution)
        if slow.error:
            return f"student {students[i]}: the full solve fails ({slow.error})"
        for name, expected in slow.answers.items():
            value = float(batch.values[name][i])
            if not _agree(value, expected.value) or expected.direction != batch.directions[name][i]:
                return (
                    f"student {students[i]}: {name} is {value!r} in closed form but "
                    f"{expected.value!r} {expected.direction} by a full solve"
                )
    return ""


def _agree(a: float, b: float) -> bool:
    return abs(a - b) <= AGREE * max(abs(a), abs(b)) or abs(a - b) <= 1e-12 * AGREE


def per_variant(
    spec: Spec, student: str, cells: Mapping[str, str], options: SolveOptions
) -> StudentExpected:
    """One student's expected answers by a full solve of their variant.

    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("given:\\n  m = 2 kg\\nequations:\\n  W = m*g\\nfind: W\\n")
    >>> per_variant(spec, "s1", {"m": "3 kg"}, SolveOptions()).answers["W"].value  # 3·9.81
    29.43
    """
    solution = _solve(spec, student, cells, options)
    if isinstance(solution, str):
        return StudentExpected(student, {}, "per-variant", solution)
    return _from_solution(student, solution)


def _solve(
    spec: Spec, student: str, cells: Mapping[str, str], options: SolveOptions
) -> Solution | str:
    """The full solve of a student's variant, or why it cannot be solved."""
    from dynsolve.pipeline import solve_spec

    try:
        return solve_spec(with_variant(spec, cells, student), options)
    except DynsolveError as error:
        return error.message.removeprefix(f"student {student}: ")


def _from_solution(student: str, solution: Solution) -> StudentExpected:
    failed = [c for c in solution.checks if c.failed and not c.name.startswith("answer ")]
    if failed:
        detail = f"check '{failed[0].name}' fails: {failed[0].detail}"
        return StudentExpected(student, {}, "per-variant", detail)
    answers = {}
    for row in solution.answers:
        if row.value is None or not math.isfinite(row.value):
            return StudentExpected(student, {}, "per-variant", f"{row.name} is {row.shown}")
        unit = unit_info(row.unit)
        answers[row.name] = Expected(
            row.name,
            row.value * unit.factor,
            _si_unit(unit.dim, row.unit),
            row.unit,
            unit.dim,
            row.direction,
        )
    return StudentExpected(student, answers, "per-variant")


def _si_unit(dim: Dim, unit: str) -> str:
    """The SI base unit of a value: ``rad`` for an angle shown in deg, rev or rad."""
    if dim.dimensionless:
        return "rad" if (unit and unit_info(unit).factor != 1) or unit == "rad" else ""
    return base_unit(dim, "SI")
