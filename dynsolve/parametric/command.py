"""``dynsolve sweep``'s work, run in the worker: read the spec and the ranges, answer every
point, and write the table (CSV or JSON text) and the plot (image bytes) for the command
line to save.

>>> from dynsolve.system import SolveOptions
>>> out = sweep_job(SweepRequest("problems/seed/fa_hib_drum.dyn", ("m_b=10..30 kg",), 3,
...                 ("alpha",), ".csv"), SolveOptions())
>>> out.table.splitlines()[0], out.result.counts()["closed form"]
('m_b [kg],alpha [rad/s^2],alpha direction,regime,path', 3)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from dynsolve.errors import DynsolveError, Position, SpecError
from dynsolve.parametric.evaluate import ANSWERS_FILE, Sweep, sweep_points
from dynsolve.parametric.plot import not_plottable, sweep_plot
from dynsolve.parametric.ranges import Axis, grid, label, parse_range
from dynsolve.parametric.table import csv_text, json_text
from dynsolve.spec.ast import Spec
from dynsolve.system import SolveOptions

TABLE_FORMATS = (".csv", ".json")


@dataclass(frozen=True)
class SweepRequest:
    """What ``dynsolve sweep`` was asked: the spec, its ranges and what to write."""

    spec: str  # the .dyn file
    ranges: tuple[str, ...]  # "m_b=10..30 kg", as typed
    points: int | None = None  # points of a range without a step (None: the default)
    answers: tuple[str, ...] | None = None  # the finds to report (None: every one)
    table: str = ""  # the -o file's suffix (.csv, .json), "" for none
    plot: str = ""  # the --plot file's suffix (.png, .svg, .pdf), "" for none


@dataclass(frozen=True)
class SweepOutput:
    """A sweep, its table as text and its plot as bytes (None when not asked for)."""

    result: Sweep
    table: str = ""
    plot: bytes | None = None


def sweep_job(
    request: SweepRequest, options: SolveOptions, seconds: float | None = None
) -> SweepOutput:
    """Read, sweep and write (raises :class:`~dynsolve.errors.DynsolveError` on bad input);
    ``seconds`` is the time the job has (its full solves stop early past it)."""
    import time

    from dynsolve.budget import step
    from dynsolve.spec.parser import parse_file

    deadline = time.perf_counter() + seconds if seconds is not None else None
    with step("parsing the spec"):
        spec = parse_file(request.spec)
    if request.plot and len(request.ranges) > 2:
        raise not_plottable(len(request.ranges))
    result = sweep_spec(spec, request.ranges, request.points, request.answers, options, deadline)
    with step("writing the table"):
        table = (
            json_text(result)
            if request.table == ".json"
            else csv_text(result)
            if request.table
            else ""
        )
    with step("drawing the plot"):
        plot = sweep_plot(result, request.plot) if request.plot else None
    return SweepOutput(result, table, plot)


def sweep_spec(
    spec: Spec,
    ranges: Sequence[str],
    points: int | None = None,
    answers: Sequence[str] | None = None,
    options: SolveOptions | None = None,
    deadline: float | None = None,
) -> Sweep:
    """``spec`` swept over the grid of ``ranges`` (each in the ``vary:`` grammar); see
    :func:`~dynsolve.parametric.evaluate.sweep_points` for ``deadline``."""
    if not ranges:
        raise SpecError("a sweep needs a range", hint="e.g. 'm_b=10..30 kg'")
    axes: list[Axis] = []
    for index, text in enumerate(ranges, start=1):
        axis = parse_range(text, index, spec, points)
        if any(a.name == axis.name for a in axes):
            raise SpecError(
                f"'{axis.name}' is swept twice",
                Position(label(index), 1, 1),
                hint="give each given one range",
            )
        axes.append(axis)
    columns, shape = grid(axes)
    return sweep_points(spec, axes, columns, shape, answers, options, deadline=deadline)


def parse_answers(text: str) -> tuple[str, ...]:
    """The --answers list (``alpha,T``) as names; an empty name is an error.

    >>> parse_answers("alpha, T")
    ('alpha', 'T')
    """
    names = tuple(name.strip() for name in text.split(","))
    if not all(names):
        column = text.find(",,") + 2 if ",," in text else 1
        raise SpecError(
            "--answers has an empty name",
            Position(ANSWERS_FILE, 1, column),
            hint="e.g. --answers alpha,T",
        )
    return names


def input_text(error: DynsolveError, ranges: Sequence[str], answers: str) -> str | None:
    """The text an error in a range or in --answers points into (for its source line)."""
    file = error.position.file if error.position is not None else ""
    if file == ANSWERS_FILE:
        return answers
    for index, text in enumerate(ranges, start=1):
        if file == label(index):
            return text
    return None
