"""The Python API: solve, check or sweep specs (a path or the text itself) and get pint
quantities.

Each solve runs in a worker process under a time and memory budget, exactly as the
command line does, so a hostile or runaway spec cannot hang a notebook.

>>> result = solve("given:\\n  m = 2 kg\\nequations:\\n  W = m*g\\nfind: W\\n")
>>> result["W"]
<Quantity(19.62, 'newton')>
>>> result.passed
True
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

from dynsolve.budget import DEFAULT_MEGABYTES, DEFAULT_SECONDS, Budget, run, run_each
from dynsolve.errors import DynsolveError
from dynsolve.results import Check, Solution

if TYPE_CHECKING:
    import pint

    from dynsolve.parametric.result import SweepResult

Mode = Literal["exact", "numeric", "auto"]
BLOCK_SECONDS = 5.0  # symbolic solve of one nonlinear block, before the numeric fallback


@dataclass(frozen=True)
class Result:
    """A solved spec: its answers as pint quantities, and the full derivation as data.

    ``result["alpha"]`` is a pint quantity (a symbolic answer is its formula as
    text); ``result.solution`` is the :class:`~dynsolve.results.Solution` every
    renderer shows. In Jupyter a result displays as its derivation.
    """

    solution: Solution

    @property
    def answers(self) -> dict[str, pint.Quantity | str]:
        """Every answer by name: a pint quantity in its display unit, or a formula."""
        from dynsolve.units import registry

        ureg = registry()
        return {
            row.name: row.formula if row.value is None else ureg.Quantity(row.value, row.unit)
            for row in self.solution.answers
        }

    @property
    def passed(self) -> bool:
        """True when every check (the answer key included) passed."""
        return self.solution.passed

    @property
    def failed_checks(self) -> tuple[Check, ...]:
        """The checks that failed, each with its reason."""
        return tuple(check for check in self.solution.checks if not check.passed)

    def __getitem__(self, name: str) -> pint.Quantity | str:
        answers = self.answers
        if name not in answers:
            raise KeyError(f"{name!r} is not an answer; the answers are {', '.join(answers)}")
        return answers[name]

    def render(
        self,
        format: Literal["text", "json", "markdown", "latex", "html"] = "text",
        layout: Literal["full", "handout", "key"] = "full",
    ) -> str:
        """The derivation as plain text, JSON, Markdown, a LaTeX document or an HTML page
        (``layout``: the full sheet, the ``handout`` or the ``key``, for Markdown, LaTeX and
        HTML)."""
        from dynsolve.render import renderer

        return renderer(format, layout)(self.solution)

    def _repr_markdown_(self) -> str:
        return self.render("markdown")

    def _repr_html_(self) -> str:
        from dynsolve.render.html import html_fragment

        return html_fragment(self.solution)

    def _repr_latex_(self) -> str:
        from dynsolve.render.latex import answers_math

        return answers_math(self.solution)


@dataclass(frozen=True)
class FileCheck:
    """One spec checked against its answer key: passed, failed (with checks) or malformed."""

    file: str
    failed: tuple[Check, ...]  # the checks that failed; empty when it passed
    errors: tuple[str, ...]  # why it could not be solved; empty when it was

    @property
    def passed(self) -> bool:
        """True when the spec was solved and every check passed."""
        return not self.failed and not self.errors


def solve(
    source: str | os.PathLike[str],
    *,
    mode: Mode = "exact",
    time_budget: float = DEFAULT_SECONDS,
    memory_budget: int | None = DEFAULT_MEGABYTES,
) -> Result:
    """Solve one spec, given as a path (``Path``, or a ``str`` ending in ``.dyn`` with no
    line break) or as the spec's text, and check it.

    Raises :class:`~dynsolve.errors.DynsolveError` (its subclasses ``SpecError``,
    ``UnitError``, ``DimensionError``, ``SolveError``, ``OverBudget``) for bad input,
    with the position and hint the command line shows.

    >>> solve("given:\\n  m = 2 kg\\nequations:\\n  W = m*g\\nfind: W\\n").answers
    {'W': <Quantity(19.62, 'newton')>}
    """
    budget = Budget(time_budget, memory_budget)
    outcome = run(_solve_in_worker, (_source(source), mode, budget.seconds), budget)
    if isinstance(outcome, DynsolveError):
        raise outcome
    return Result(outcome)


def check(
    paths: Iterable[str | os.PathLike[str]],
    *,
    mode: Mode = "exact",
    time_budget: float = DEFAULT_SECONDS,
    memory_budget: int | None = DEFAULT_MEGABYTES,
) -> list[FileCheck]:
    """Solve every ``.dyn`` spec under ``paths`` (files or folders) and compare it with its
    answer key; one :class:`FileCheck` per file, in order. Each file gets the whole budget.

    >>> [c.passed for c in check(["problems/seed/fa_hib_drum.dyn"])]
    [True]
    """
    files = list(_spec_files(paths))
    budget = Budget(time_budget, memory_budget)
    jobs = [(("file", str(file)), mode, budget.seconds) for file in files]
    checks: list[FileCheck] = []
    for file, outcome in zip(files, run_each(_solve_in_worker, jobs, budget), strict=True):
        if isinstance(outcome, DynsolveError):
            checks.append(FileCheck(str(file), (), _messages(outcome)))
        elif isinstance(outcome, BaseException):
            detail = (str(outcome).strip().splitlines() or ["no detail"])[-1]
            checks.append(FileCheck(str(file), (), (f"internal error: {detail}",)))
        else:
            failed = tuple(c for c in outcome.checks if c.failed)
            checks.append(FileCheck(str(file), failed, ()))
    return checks


def sweep(
    source: str | os.PathLike[str],
    *,
    answers: Iterable[str] | None = None,
    points: int | None = None,
    mode: Mode = "exact",
    time_budget: float = DEFAULT_SECONDS,
    memory_budget: int | None = DEFAULT_MEGABYTES,
    **givens: Any,
) -> SweepResult:
    """Sweep givens of one spec (a path or its text) and get every answer at every point.

    Each keyword names a given: a pint quantity (an array or a number), plain numbers (in
    the unit the spec gives it in), or a range as ``dynsolve sweep`` reads one
    (``"10..30 kg"``, ``"10..30 kg step 0.5"``, ``"±10%"``; ``points`` spreads a range
    without a step). Arrays broadcast together, point by point; ranges form a grid. The
    whole sweep runs in one worker process under the budget: the closed form where the
    answers have one, full solves elsewhere (``result.path`` says which, per point).
    ``answers`` names the finds to report (default: every one).

    >>> import numpy as np
    >>> result = sweep("problems/seed/fa_hib_drum.dyn", m_b=np.array([10.0, 20.0]))  # 17.11
    >>> result["alpha"].to("rad/s^2").magnitude.round(3).tolist(), result.path.tolist()
    ([7.335, 11.292], ['closed form', 'closed form'])
    """
    if not givens:
        raise DynsolveError("name a given to sweep", hint="e.g. sweep(spec, m_b=values)")
    inputs = []
    for name, value in givens.items():
        if isinstance(value, str):
            inputs.append((name, "range", value, None))
        elif hasattr(value, "magnitude") and hasattr(value, "units"):
            inputs.append((name, "values", _plain(value.magnitude), str(value.units)))
        else:
            inputs.append((name, "values", _plain(value), None))
    kinds = {kind for _, kind, _, _ in inputs}
    if len(kinds) > 1:
        raise DynsolveError(
            "ranges (text) and values (arrays) cannot be mixed in one sweep",
            hint="pass every given as a range, or every one as values",
        )
    if points is not None and "values" in kinds:
        raise DynsolveError(
            "points spreads a range (text); values passed as arrays are the points already",
            hint="leave points out, or pass ranges such as m_b='10..30 kg'",
        )
    chosen = tuple(answers) if answers is not None else None
    budget = Budget(time_budget, memory_budget)
    job = (_source(source), tuple(inputs), chosen, points, mode, budget.seconds)
    outcome = run(_sweep_in_worker, job, budget)
    if isinstance(outcome, DynsolveError):
        raise outcome
    from dynsolve.parametric.result import SweepResult

    return SweepResult(outcome)


def _plain(value: object) -> Any:
    """A value as a float array (numbers, lists, numpy arrays)."""
    import numpy as np

    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise DynsolveError(
            f"cannot read {type(value).__name__} values as numbers",
            hint="pass numbers, a numpy array, a pint quantity or a range text",
        ) from None


def _sweep_in_worker(
    source: tuple[str, str],
    inputs: tuple[tuple[str, str, Any, str | None], ...],
    answers: tuple[str, ...] | None,
    points: int | None,
    mode: str,
    seconds: float,
) -> Any:
    """The worker's job for :func:`sweep`: the Sweep, or the DynsolveError to raise."""
    import time

    import numpy as np

    from dynsolve.parametric.command import sweep_spec
    from dynsolve.parametric.evaluate import sweep_points
    from dynsolve.parametric.ranges import axis_of_values
    from dynsolve.spec.parser import parse_file, parse_spec
    from dynsolve.system import SolveOptions

    options = SolveOptions(mode=mode, time_budget=min(BLOCK_SECONDS, seconds / 4))
    deadline = time.perf_counter() + seconds
    kind, value = source
    try:
        spec = parse_file(value) if kind == "file" else parse_spec(value, "<spec>")
        if inputs[0][1] == "range":
            ranges = [f"{name}={text}" for name, _, text, _ in inputs]
            return sweep_spec(spec, ranges, points, answers, options, deadline)
        try:
            arrays = np.broadcast_arrays(*(array for _, _, array, _ in inputs))
        except ValueError:
            shapes = ", ".join(f"{n} {np.shape(a)}" for n, _, a, _ in inputs)
            raise DynsolveError(
                f"the values' shapes do not broadcast together: {shapes}",
                hint="pass arrays of one shape, or a grid from numpy.meshgrid",
            ) from None
        axes = [
            axis_of_values(name, array, unit, spec)
            for (name, _, _, unit), array in zip(inputs, arrays, strict=True)
        ]
        shape = arrays[0].shape or (1,)
        columns = [a.values for a in axes]
        return sweep_points(spec, axes, columns, shape, answers, options, deadline=deadline)
    except DynsolveError as error:
        return error


def _source(source: str | os.PathLike[str]) -> tuple[str, str]:
    """("file", path) or ("text", spec text)."""
    if isinstance(source, os.PathLike):
        return ("file", os.fspath(source))
    if "\n" not in source and source.strip().endswith(".dyn"):
        return ("file", source.strip())
    return ("text", source)


def _spec_files(paths: Iterable[str | os.PathLike[str]]) -> Iterator[Path]:
    for each in paths:
        path = Path(each)
        if path.is_dir():
            yield from sorted(p for p in path.rglob("*.dyn") if not p.is_dir())
        else:
            yield path  # reading it says why when it is missing or not a regular file


def _solve_in_worker(
    source: tuple[str, str], mode: str, seconds: float
) -> Solution | DynsolveError:
    """The worker's job: parse the file or text, solve and check it."""
    from dynsolve.pipeline import solve_file, solve_text
    from dynsolve.system import SolveOptions

    options = SolveOptions(mode=mode, time_budget=min(BLOCK_SECONDS, seconds / 4))
    kind, value = source
    try:
        if kind == "file":
            return solve_file(value, options)
        return solve_text(value, "<spec>", options)
    except DynsolveError as error:
        return error  # raised by the caller: the worker reports only bugs as exceptions


def _messages(error: BaseException) -> tuple[str, ...]:
    others: Any = getattr(error, "others", ())
    return tuple(str(each) for each in (error, *others))


__all__ = ["FileCheck", "Result", "check", "solve", "sweep"]
