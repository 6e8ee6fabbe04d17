"""Lay out a sweep for the terminal: a rich table (abridged past :data:`MAX_ROWS` points,
keeping the first and last points and those where the regime changes) and a summary.

Nothing is printed here (the command line prints); values are shown to 4 significant
figures (the CSV or JSON table has full precision).

>>> import numpy as np
>>> from dynsolve.spec.parser import parse_spec
>>> from dynsolve.parametric.evaluate import sweep_points
>>> from dynsolve.parametric.ranges import Axis
>>> text = "given:\\n  m = 2 kg\\n  F = 10 N\\nequations:\\n  F = m*a\\nfind: a"
>>> spec = parse_spec(text, "p.dyn")
>>> axis = Axis("m", "kg", np.array([1.0, 4.0]), 1.0)
>>> lines = summary_lines(sweep_points(spec, (axis,), (axis.values,), (2,)))
>>> lines[0], lines[1].startswith("closed form: 2 points (built in")
('2 points of p.dyn', True)
"""

from __future__ import annotations

import math

import numpy as np
from rich.console import RenderableType
from rich.table import Table
from rich.text import Text

from dynsolve.format import sig
from dynsolve.parametric.evaluate import CLOSED, PER_POINT, Sweep
from dynsolve.parametric.table import columns, rows

MAX_ROWS = 25  # rows shown before the table is abridged
MAX_REASONS = 3


def shown_rows(result: Sweep, limit: int = MAX_ROWS) -> list[int]:
    """The points the table shows: all up to ``limit``, else evenly spaced ones (the first
    and last among them) and both sides of every change of regime.

    >>> from types import SimpleNamespace
    >>> fake = SimpleNamespace(size=100, regimes=np.array(["a"] * 50 + ["b"] * 50))
    >>> shown_rows(fake, 5)
    [0, 33, 49, 50, 66, 99]
    """
    if result.size <= limit:
        return list(range(result.size))
    chosen = set(np.linspace(0, result.size - 1, limit - 1).round().astype(int).tolist())
    changes = np.flatnonzero(result.regimes[1:] != result.regimes[:-1])
    for i in changes[:limit].tolist():
        chosen.update((i, i + 1))
    return sorted(chosen)


def sweep_table(result: Sweep) -> Table:
    """The points as a rich table, one line each; abridged, its caption says how many it
    shows. A direction stated as an angle ("16.7° below the horizontal") is left to the
    file (-o), where it has full width."""
    headers = [name for name in columns(result) if name != "note"]
    keep = [
        i
        for i, name in enumerate(headers)
        if not name.endswith(" direction") or not _angled(result, name.removesuffix(" direction"))
    ]
    picked = shown_rows(result)
    caption = (
        f"{len(picked)} of {result.size} points shown (evenly spaced, and each side of a "
        "change of regime); -o FILE writes them all"
        if len(picked) < result.size
        else None
    )
    table = Table(title=Text(result.title or result.file), caption=caption)
    for i in keep:
        name = headers[i].replace(" direction", " sense")
        table.add_column(Text(name), no_wrap=name in ("regime", "path"))
    wanted = set(picked)
    for i, row in enumerate(rows(result)):
        if i in wanted:
            table.add_row(*(Text(_cell(row[k])) for k in keep))
    return table


def _angled(result: Sweep, name: str) -> bool:
    """Whether a find's direction is stated as an angle at some point."""
    answer = next(a for a in result.answers if a.name == name)
    return any(any(c.isdigit() for c in words) for words in answer.directions)


def _cell(cell: float | str | None) -> str:
    if cell is None:
        return "—"
    if isinstance(cell, float):
        return sig(cell, 4) if math.isfinite(cell) else "—"
    return str(cell)


def summary_lines(result: Sweep) -> list[str]:
    """What was computed and how: points, paths and their times, regimes and where they
    change, points without an answer."""
    counts = result.counts()
    shape = " × ".join(str(size) for size in result.shape)
    grid = f" ({shape} grid)" if len(result.shape) > 1 else ""
    lines = [f"{_points(result.size)}{grid} of {result.file}"]
    if counts[CLOSED]:
        lines.append(
            f"closed form: {_points(counts[CLOSED])} (built in {result.build_seconds:.2f} s, "
            f"evaluated in {result.evaluate_seconds:.3f} s)"
        )
    if counts[PER_POINT]:
        why = "; ".join(result.reasons[:MAX_REASONS]) or "no closed form"
        lines.append(
            f"per point: {_points(counts[PER_POINT])}, a full solve each "
            f"({result.solve_seconds:.2f} s): {why}"
        )
    regimes = [r for r in dict.fromkeys(result.regimes.tolist()) if r]
    if regimes:
        tally = ", ".join(
            f"{regime}: {int(np.count_nonzero(result.regimes == regime))}" for regime in regimes
        )
        lines.append(f"regimes: {tally}")
    lines += _changes(result)
    if result.notes:
        first = min(result.notes)
        lines.append(
            f"{_points(len(result.notes))} without every answer; the first, point {first + 1}: "
            f"{result.notes[first]}"
        )
    return lines


def _points(count: int) -> str:
    return f"{count} point{'' if count == 1 else 's'}"


def _changes(result: Sweep) -> list[str]:
    """Where the regime changes along a one-given sweep (between which two values)."""
    if len(result.axes) != 1:
        return []
    axis = result.axes[0]
    x = result.givens[axis.name]
    out = []
    for i in np.flatnonzero(result.regimes[1:] != result.regimes[:-1])[:10].tolist():
        before, after = result.regimes[i] or "no assumption", result.regimes[i + 1]
        out.append(
            f"the regime changes between {axis.name} = {sig(float(x[i]), 4)} and "
            f"{sig(float(x[i + 1]), 4)}{' ' + axis.unit if axis.unit else ''}: {before} → "
            f"{after or 'no assumption'}"
        )
    return out


def sweep_renderables(result: Sweep) -> list[RenderableType]:
    """The table, then the summary, for ``Console.print``."""
    return [sweep_table(result), *(Text(line) for line in summary_lines(result))]
