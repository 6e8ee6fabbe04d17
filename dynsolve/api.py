"""The Python API: solve or check specs (a path or the text itself) and get pint quantities.

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
            failed = tuple(c for c in outcome.checks if not c.passed)
            checks.append(FileCheck(str(file), failed, ()))
    return checks


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


__all__ = ["FileCheck", "Result", "check", "solve"]
