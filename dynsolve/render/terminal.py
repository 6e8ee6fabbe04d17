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
from rich.padding import Padding
from rich.panel import Panel
from rich.table import Table
from rich.text import Text

from dynsolve.format import and_list, lines_phrase, pretty_unit
from dynsolve.names import pretty
from dynsolve.results import (
    NOT_RUN,
    PASSED,
    Assumption,
    Check,
    EquationRow,
    FreeBody,
    KeyComparison,
    Solution,
    Step,
    Trial,
)

WIDTH = 100
STEP_INDENT = 5  # columns before a step's results


def solution_renderable(solution: Solution) -> RenderableType:
    """The whole derivation as one rich renderable.

    Scene mode adds the free-body diagrams (as tables) after Given, the assumptions after
    Answers:

    >>> from dynsolve.results import Assumption, ForceRow, FreeBody
    >>> pull = ForceRow("T", "tension", "A", 0.4, 0.0, "down", 0.0, -1.0, False, "")
    >>> drum = FreeBody("drum", "disk", (0.4,), "rotation about O", (pull,), ("I_G α",), "O")
    >>> scene = Solution("d.dyn", "Drum", "", "SI", "scene", (), (), (), (), (), (), "solved",
    ...                  free_body=(drum,), assumptions=(Assumption("cord T taut", True, ""),))
    >>> lines = [line.rstrip() for line in render_text(scene).splitlines()]
    >>> lines.index("Free-body diagrams") < lines.index("Answers") < lines.index("Assumptions")
    True
    >>> first = lines.index("drum (disk)")
    >>> print("\\n".join(lines[first : first + 5]))
    drum (disk)
    force  kind     at  direction  known  value
    T      tension  A   down       no
    motion: rotation about O · moments about O
    kinetic diagram: I_G α
    """
    parts: list[RenderableType] = [_title(solution)]
    parts += [Text(f"⚠ warning: {w}", style="yellow") for w in solution.warnings]
    if solution.givens:
        parts += [_heading("Given"), _givens(solution)]
    if solution.free_body:
        parts += [_heading("Free-body diagrams"), *(_free_body(b) for b in solution.free_body)]
    for trial in solution.trials:
        parts += [_heading(f"Trial: {trial.assumption} (assumed, then checked)"), _trial(trial)]
    parts += [_heading("Equations (units checked)"), _equations(solution)]
    if solution.second_moments:
        heading = _heading("A second moment point (a check, not used to solve)")
        parts += [heading, _equation_table(solution.second_moments)]
    if solution.energy:
        parts += [_heading("Work and energy, term by term"), _energy(solution)]
    if solution.steps:
        parts += [_heading("Solve order"), *(_step(s) for s in solution.steps)]
    parts += [_heading("Answers"), _answers(solution)]
    parts += [Text(f"remark: {r.text}", style="green") for r in solution.remarks]
    if solution.assumptions:
        parts += [_heading("Assumptions"), _assumptions(solution.assumptions)]
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
    """The title, source, file and facts inside the panel, where they fold (a panel's own
    title line would be cut at the terminal's width)."""
    text = Text(solution.title, style="bold") + Text("\n") if solution.title else Text()
    if solution.source:
        text += Text(f"{solution.source}\n")
    text += Text(f"{solution.file}\n")  # a long path folds on its own line, not the facts
    text += Text(f"units {solution.system} · {solution.mode} mode")
    text.overflow = "fold"
    return Panel(text)


def _table(*columns: str | Text) -> Table:
    table = Table(box=None, padding=(0, 2, 0, 0), show_header=True, header_style="dim")
    for column in columns:
        table.add_column(column, overflow="fold")  # never cut with "…": long names fold
    return table


def _givens(solution: Solution) -> Table:
    table = _table("", "as written", Text(f"in {solution.system}"), "")
    for g in solution.givens:
        table.add_row(
            Text(pretty(g.name), style="bold"),
            Text(g.written),
            Text(g.base),
            Text(g.description, style="dim"),
        )
    return table


def _energy(solution: Solution) -> Table:
    """T1, each U(1→2) and T2 with its formula and value (T1 + ΣU = T2)."""
    table = _table("term", "formula", "value", "")
    for term in solution.energy:
        table.add_row(
            Text(pretty(term.name), style="bold"),
            Text(term.formula),
            Text(term.value),
            Text(term.meaning, style="dim"),
        )
    return table


def _equations(solution: Solution) -> RenderableType:
    if not solution.equations:  # a kinematics-only scene: its values come from formulas
        return Text("No equations: every value asked follows from the givens.")
    return _equation_table(solution.equations)


def _equation_table(equations: tuple[EquationRow, ...]) -> Table:
    table = _table("line", "equation", "units", "principle")
    for e in equations:
        mark = Text("✓ ", style="green") if e.dimension_ok else Text("✗ ", style="red")
        kind = " (constraint)" if e.constraint else ""
        table.add_row(
            str(e.line), Text(e.text + kind), mark + Text(e.dimension), Text(e.note, style="dim")
        )
    return table


def _trial(trial: Trial) -> RenderableType:
    """A rejected trial: its equations, its solve, the failed check and the remarks."""
    rows: list[RenderableType] = [_equation_table(trial.equations)]
    rows += [_step(s) for s in trial.steps]
    if trial.second_moments:
        rows.append(Text("a second moment point (a check):", style="dim"))
        rows.append(_equation_table(trial.second_moments))
    rows.append(Text(f"✗ {trial.verdict}", style="bold red"))
    rows += [Text(f"remark: {r}", style="yellow") for r in trial.remarks]
    return Group(*rows)


def _step(step: Step) -> RenderableType:
    unknowns = and_list([pretty(u) for u in step.unknowns])
    lead = step.heading or f"{lines_phrase(step.lines)} {unknowns}"
    head = Text(f"{step.index}. {lead} ({step.method})")
    rows: list[RenderableType] = [head]
    for result in step.results:
        formula = f" = {result.formula.replace('**', '^')}" if result.formula else ""
        if result.substituted:
            formula += f" = {result.substituted}"
        rows.append(Text(f"{pretty(result.name)}{formula} = ") + Text(result.value, style="bold"))
    for discarded in step.discarded:
        rows.append(Text(f"discarded {discarded}", style="yellow"))
    if step.note:
        rows.append(Text(f"note: {step.note}", style="dim"))
    # wrapped lines keep the indent of their result, instead of falling back to column 0
    return Group(head, *(Padding(row, (0, 0, 0, STEP_INDENT)) for row in rows[1:]))


def _answers(solution: Solution) -> Table:
    table = _table("", "value", "")
    for a in solution.answers:
        table.add_row(
            Text(pretty(a.name), style="bold"), Text(a.shown, style="bold"), Text(a.direction)
        )
    return table


def _checks(checks: tuple[Check, ...]) -> Table:
    table = _table("", "check", "detail")
    for c in checks:
        table.add_row(_status_mark(c.status), Text(c.name), Text(c.shown_detail))
    return table


def _status_mark(status: str) -> Text:
    """✓ passed, ✗ failed, – not run (could not run or decide)."""
    if status == NOT_RUN:
        return Text("–", style="yellow")
    return Text("✓", style="green") if status == PASSED else Text("✗", style="bold red")


def _free_body(body: FreeBody) -> RenderableType:
    """A body's forces as a table, then its motion, moment point and kinetic terms."""
    shape = f" ({body.shape})" if body.shape else ""
    rows: list[RenderableType] = [Text(f"{body.body}{shape}", style="bold")]
    table = _table("force", "kind", "at", "direction", "known", "value")
    for f in body.forces:
        known = Text("yes") if f.known else Text("no", style="yellow")
        table.add_row(
            Text(pretty(f.name), style="bold"),
            Text(f.kind),
            Text(f.point),
            Text(f.direction),
            known,
            Text(pretty_unit(f.value)),
        )
    if body.forces:
        rows.append(table)
    about = f" · moments about {body.moment_point}" if body.moment_point else ""
    rows.append(Text(f"motion: {body.motion}{about}", style="dim"))
    if body.kinetic:
        terms = ", ".join(" ".join(pretty(w) for w in t.split()) for t in body.kinetic)
        rows.append(Text(f"kinetic diagram: {terms}", style="dim"))
    return Group(*rows, Text(""))


def _assumptions(assumptions: tuple[Assumption, ...]) -> Table:
    table = _table("", "assumption", "detail")
    for a in assumptions:
        table.add_row(_status_mark(a.status), Text(a.name), Text(pretty_unit(a.shown_detail)))
    return table


def failures_table(failures: list[tuple[str, KeyComparison | Check | str]]) -> Table:
    """The table ``dynsolve check`` prints: one row per failed check, per file."""
    table = Table(title="Failures", show_lines=False, header_style="bold")
    table.add_column("file")
    table.add_column("check")
    table.add_column("detail", overflow="fold")
    for file, failure in failures:  # spec text is not rich markup: "[kg]" stays as written
        if isinstance(failure, str):
            table.add_row(Text(file), "input", Text(failure))
        else:
            table.add_row(Text(file), Text(failure.name), Text(failure.detail))
    return table
