"""Render a solution for the terminal with rich: the derivation a teacher would accept.

:func:`solution_renderable` builds rich renderables (the CLI prints them, in colour
when the terminal allows); :func:`render_text` renders the same to plain text.

>>> from dynsolve.results import Solution
>>> empty = Solution("f.dyn", "Empty", "", "SI", "equations", (), (), (), (), (), (), "solved")
>>> "Empty" in render_text(empty)
True
"""

from __future__ import annotations

import io

from rich.console import Console, Group, RenderableType
from rich.panel import Panel
from rich.table import Table
from rich.text import Text

from dynsolve.format import and_list, lines_phrase
from dynsolve.names import pretty
from dynsolve.results import Check, KeyComparison, Solution, Step

WIDTH = 100


def solution_renderable(solution: Solution) -> RenderableType:
    """The whole derivation as one rich renderable."""
    parts: list[RenderableType] = [_title(solution)]
    if solution.givens:
        parts += [_heading("Given"), _givens(solution)]
    parts += [_heading("Equations (units checked)"), _equations(solution)]
    if solution.steps:
        parts += [_heading("Solve order"), *(_step(s) for s in solution.steps)]
    parts += [_heading("Answers"), _answers(solution)]
    parts += [_heading("Checks"), _checks(solution.checks)]
    return Group(*parts)


def render_text(solution: Solution) -> str:
    """The derivation as plain text (no colour), as written by ``-o FILE``."""
    buffer = io.StringIO()
    console = Console(file=buffer, width=WIDTH, color_system=None, force_terminal=False)
    console.print(solution_renderable(solution))
    return buffer.getvalue()


def _heading(text: str) -> Text:
    return Text(f"\n{text}", style="bold cyan")


def _title(solution: Solution) -> Panel:
    subtitle = Text(f"{solution.file} · units {solution.system} · {solution.mode} mode")
    if solution.source:
        subtitle = Text(f"{solution.source}\n") + subtitle
    return Panel(subtitle, title=Text(solution.title, style="bold"), title_align="left")


def _table(*columns: str) -> Table:
    table = Table(box=None, padding=(0, 2, 0, 0), show_header=True, header_style="dim")
    for column in columns:
        table.add_column(column)
    return table


def _givens(solution: Solution) -> Table:
    table = _table("", "as written", "in SI", "")
    for g in solution.givens:
        table.add_row(
            Text(pretty(g.name), style="bold"), g.written, g.si, Text(g.description, style="dim")
        )
    return table


def _equations(solution: Solution) -> Table:
    table = _table("line", "equation", "units", "principle")
    for e in solution.equations:
        mark = Text("✓ ", style="green") if e.dimension_ok else Text("✗ ", style="red")
        kind = " (constraint)" if e.constraint else ""
        table.add_row(
            str(e.line), Text(e.text + kind), mark + Text(e.dimension), Text(e.note, style="dim")
        )
    return table


def _step(step: Step) -> RenderableType:
    unknowns = and_list([pretty(u) for u in step.unknowns])
    head = Text(f"{step.index}. {lines_phrase(step.lines)} {unknowns} ({step.method})")
    rows: list[RenderableType] = [head]
    for result in step.results:
        formula = f" = {result.formula.replace('**', '^')}" if result.formula else ""
        rows.append(
            Text(f"     {pretty(result.name)}{formula} = ") + Text(result.value, style="bold")
        )
    for discarded in step.discarded:
        rows.append(Text(f"     discarded {discarded}", style="yellow"))
    if step.note:
        rows.append(Text(f"     note: {step.note}", style="dim"))
    return Group(*rows)


def _answers(solution: Solution) -> Table:
    table = _table("", "value", "")
    for a in solution.answers:
        table.add_row(Text(pretty(a.name), style="bold"), Text(a.shown, style="bold"), a.direction)
    return table


def _checks(checks: tuple[Check, ...]) -> Table:
    table = _table("", "check", "detail")
    for c in checks:
        mark = Text("✓", style="green") if c.passed else Text("✗", style="bold red")
        table.add_row(mark, c.name, c.detail)
    return table


def failures_table(failures: list[tuple[str, KeyComparison | Check | str]]) -> Table:
    """The table ``dynsolve check`` prints: one row per failed check, per file."""
    table = Table(title="Failures", show_lines=False, header_style="bold")
    table.add_column("file")
    table.add_column("check")
    table.add_column("detail", overflow="fold")
    for file, failure in failures:
        if isinstance(failure, str):
            table.add_row(file, "input", failure)
        else:
            table.add_row(file, failure.name, failure.detail)
    return table
