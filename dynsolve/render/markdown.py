"""Render a :class:`~dynsolve.results.Solution` as GitHub-flavoured Markdown.

Sections and wording follow the LaTeX renderer: title, Given, Free-body diagrams and
Assumptions (scene mode only), Equations, Solution, Answers, Checks; a free-body diagram
is a table of the body's forces here. Math goes in ``$...$`` (inline) and ``$$...$$``
(display) using the solution's LaTeX fragments; plain text goes through
:func:`escape_markdown`.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from pathlib import PurePath

from dynsolve.format import and_list, pretty_unit
from dynsolve.names import latex_name
from dynsolve.render import Layout, sheet_plan
from dynsolve.render.numbering import BY_LINE, EquationTags, sheet_tags
from dynsolve.results import (
    NOT_RUN,
    PASSED,
    AnswerRow,
    Assumption,
    Check,
    EnergyTerm,
    EquationRow,
    ForceRow,
    Formula,
    FreeBody,
    GivenRow,
    KeyComparison,
    Solution,
    Step,
    Trial,
    check_counts,
)

_SPECIAL = re.compile(r"([\\`*_\[\]<>|$~#&])")
_LEADING_MARKER = re.compile(r"^(\d+)([.)])(?=\s|$)|^([-+])(?=\s|$)")
_SPACE = re.compile(r"\s+")
_IDENTIFIER = re.compile(r"[A-Za-z][A-Za-z0-9_]*")


def escape_markdown(text: str) -> str:
    """Plain text safe inside a Markdown paragraph, heading or table cell.

    Markdown punctuation is backslash-escaped, a leading list marker too, and line
    breaks become spaces; Unicode is kept as it is.

    >>> print(escape_markdown("ΣF_y = m a_y | *note* $5"))
    ΣF\\_y = m a\\_y \\| \\*note\\* \\$5
    >>> print(escape_markdown("- 3 rad/s\\n1. x"), escape_markdown("-0.5 N"))
    \\- 3 rad/s 1. x -0.5 N
    """
    text = _SPACE.sub(" ", text).strip()
    text = _SPECIAL.sub(r"\\\1", text)
    return _LEADING_MARKER.sub(_escape_marker, text, count=1)


def _escape_marker(match: re.Match[str]) -> str:
    if match.group(3):
        return "\\" + match.group(3)
    return f"{match.group(1)}\\{match.group(2)}"


def render_markdown(solution: Solution, layout: Layout = "full", source: bool | None = None) -> str:
    """The solution as a GitHub-flavoured Markdown document; ``layout`` and ``source`` as
    for LaTeX (``full``, ``handout`` or ``key``; the spec's source line shown or not).

    >>> from dynsolve.results import AnswerRow, Solution
    >>> answer = AnswerRow("T", 105.86, "N", "106 N", "14715/139", "106\\\\,\\\\mathrm{N}", "")
    >>> doc = render_markdown(Solution("d.dyn", "Drum & block", "Hibbeler 17.11", "SI",
    ...                                "equations", (), (), (), (answer,), (), (), "solved"))
    >>> doc.splitlines()[0]
    '# Drum \\\\& block'
    >>> "| $T$ | $106\\\\,\\\\mathrm{N}$ |" in doc
    True

    In scene mode each body's forces are a table:

    >>> from dynsolve.results import ForceRow, FreeBody
    >>> pull = ForceRow("T", "tension", "A", 0.4, 0.0, "down", 0.0, -1.0, False, "")
    >>> drum = FreeBody("drum", "disk", (0.4,), "rotation about O", (pull,), ("I_G α",), "O")
    >>> doc = render_markdown(Solution("d.dyn", "Drum", "", "SI", "scene", (), (), (), (), (),
    ...                                (), "solved", free_body=(drum,)))
    >>> "| $T$ | tension | A | down | **no** |  |" in doc
    True
    >>> "- Kinetic diagram: $I_{G} \\\\, α$" in doc
    True
    """
    plan = sheet_plan(layout, source)
    key = solution.key if "key" in plan else ()
    cited = "source" in plan
    tags = sheet_tags(solution, numbered=layout == "handout")
    parts: dict[str, Callable[[], list[str]]] = {
        "title": lambda: [_title(solution, cited=cited)],  # its warnings included
        "handout_title": lambda: [_title(solution, handout=True, cited=cited)],
        "givens": lambda: [_givens_section(solution.givens, solution.system)],
        "free_body": lambda: _free_body_section(solution.free_body),
        "assumptions": lambda: _assumptions_section(solution.assumptions),
        "trials": lambda: [
            _trial_section(t, ts) for t, ts in zip(solution.trials, tags.trials, strict=True)
        ],
        "equations": lambda: [
            _equations_section(solution.equations, tags.final),
            *_second_moments_section(solution.second_moments, tags.final),
        ],
        "energy": lambda: _energy_section(solution.energy),
        "steps": lambda: [_solution_section(solution.steps, tags.final)],
        "answers": lambda: (
            [_answers_section(solution.answers, key)]
            + ["\n".join(f"- *Remark:* {escape_markdown(r.text)}" for r in solution.remarks)]
            * bool(solution.remarks)
        ),
        "checks": lambda: [_checks_section(solution.checks)],
    }
    sections = [section for name in plan if name in parts for section in parts[name]()]
    return "\n\n".join(sections) + "\n"


# ---- pieces


def _math(fragment: str) -> str:
    """Inline math, or nothing for an empty fragment."""
    fragment = _SPACE.sub(" ", fragment).strip()
    return f"${fragment}$" if fragment else ""


def _display(fragment: str) -> str:
    return f"$${_SPACE.sub(' ', fragment).strip()}$$"


def _name(name: str) -> str:
    return _math(latex_name(name))


def _cell_math(fragment: str) -> str:
    """Inline math for a table cell: GFM splits cells at every unescaped pipe, even in math."""
    return _math(fragment).replace("|", "\\|")


def _table(header: Sequence[str], align: Sequence[str], rows: Sequence[Sequence[str]]) -> str:
    lines = ["| " + " | ".join(header) + " |", "| " + " | ".join(align) + " |"]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines)


def _mark(passed: bool) -> str:
    return "✓" if passed else "✗"


def _status_mark(status: str) -> str:
    """✓ passed, ✗ failed, – not run (could not run or decide)."""
    return "–" if status == NOT_RUN else _mark(status == PASSED)


# ---- sections


def _title(solution: Solution, handout: bool = False, cited: bool = True) -> str:
    """The title, the source line when ``cited``, and (not on the handout) the spec's file
    name, status and solver messages."""
    title = solution.title.strip() or PurePath(solution.file).name or "Problem"
    lines = [f"# {escape_markdown(title)}", ""]
    if cited and solution.source.strip():
        lines += [f"*{escape_markdown(solution.source)}*", ""]
    if handout:  # the handout names no file, status or solver remarks
        warnings = [f"- **Warning:** {escape_markdown(w)}" for w in solution.warnings]
        return "\n".join(lines + warnings).rstrip()
    spec = PurePath(solution.file).name
    facts = [f"Spec `{spec.replace('`', '')}`", f"units {escape_markdown(solution.system)}"]
    facts.append(f"status **{escape_markdown(solution.status)}**")
    lines.append(" · ".join(facts))
    if solution.messages:
        lines += ["", *(f"- {escape_markdown(m)}" for m in solution.messages)]
    if solution.warnings:
        lines += ["", *(f"- **Warning:** {escape_markdown(w)}" for w in solution.warnings)]
    return "\n".join(lines)


def _givens_section(givens: Sequence[GivenRow], system: str) -> str:
    if not givens:
        return "## Given\n\nNo givens."
    rows = [_given_cells(g) for g in givens]
    header = ["Symbol", "Value", f"{escape_markdown(system)} value", "Description"]
    return "## Given\n\n" + _table(header, [":--"] * 4, rows)


def _given_cells(given: GivenRow) -> list[str]:
    value = escape_markdown(given.written) if given.symbolic else _cell_math(given.latex_value)
    base = escape_markdown(given.base)
    return [_cell_math(given.latex_name), value, base, escape_markdown(given.description)]


def _equations_section(equations: Sequence[EquationRow], tags: EquationTags = BY_LINE) -> str:
    if not equations:
        return "## Equations\n\nNo equations."
    rows = [_equation_cells(e, tags) for e in equations]
    header = ["Line" if tags.numbers is None else "No.", "Equation", "Principle", "Dimensions"]
    return "## Equations\n\n" + _table(header, ["--:", ":--", ":--", ":--"], rows)


def _second_moments_section(rows: Sequence[EquationRow], tags: EquationTags = BY_LINE) -> list[str]:
    """The other moment point's equation (a check, not used to solve); nothing without one."""
    if not rows:
        return []
    title = "## A second moment point (a check, not used to solve)"
    return [_equations_section(rows, tags).replace("## Equations", title, 1)]


def _equation_cells(row: EquationRow, tags: EquationTags = BY_LINE) -> list[str]:
    note = escape_markdown(row.note)
    if row.constraint:
        note = "constraint" + (f": {note}" if note else "")
    number = str(row.line) if tags.numbers is None else tags.tag(row).strip("()")
    return [number, _cell_math(row.latex) or "?", note, _dimension(row)]


_DIMENSION = re.compile(r"^(.*\S)\s+\[([^\[\]]*)\]$")


def _dimension(row: EquationRow) -> str:
    """``force, N ✓`` from ``force [N]``, or a marked mismatch."""
    match = _DIMENSION.match(row.dimension.strip())
    text = f"{match.group(1)}, {pretty_unit(match.group(2))}" if match else row.dimension.strip()
    shown = escape_markdown(text)
    return f"{shown} ✓" if row.dimension_ok else f"**dimensions differ**: {shown} ✗"


def _trial_section(trial: Trial, tags: EquationTags = BY_LINE) -> str:
    """A case assumed first: its equations and solve, then the check that rejected it."""
    equations = _equations_section(trial.equations, tags).replace("## Equations", "### Equations")
    steps = _solution_section(trial.steps, tags).replace("## Solution", "### Solution")
    verdict = f"**Check:** ✗ {escape_markdown(trial.verdict)}"
    remarks = [f"*Remark:* {escape_markdown(r)}" for r in trial.remarks]
    title = f"## Trial: {escape_markdown(trial.assumption)} (assumed, then checked)"
    moments = [
        m.replace("## ", "### ", 1) for m in _second_moments_section(trial.second_moments, tags)
    ]
    return "\n\n".join([title, equations, steps, *moments, verdict, *remarks])


def _energy_section(terms: Sequence[EnergyTerm]) -> list[str]:
    """T1, each U(1→2) and T2 with formula and value (nothing without a travel)."""
    if not terms:
        return []
    rows = [
        [
            _cell_math(latex_name(t.name)),
            _cell_math(t.formula_latex),
            _cell_math(t.value_latex),
            escape_markdown(t.meaning),
        ]
        for t in terms
    ]
    header = ["Term", "Formula", "Value", ""]
    title = "## Work and energy: T1 + ΣU(1→2) = T2, term by term"
    return [f"{title}\n\n" + _table(header, [":--"] * 4, rows)]


def _solution_section(steps: Sequence[Step], tags: EquationTags = BY_LINE) -> str:
    if not steps:
        return "## Solution\n\nNo solve steps."
    return "\n\n".join(["## Solution", *(_step(s, tags) for s in steps)])


def _step(step: Step, tags: EquationTags = BY_LINE) -> str:
    names = and_list([_name(n) for n in step.unknowns])
    lead = f"**Step {step.index}.** " + (
        escape_markdown(step.heading) if step.heading else f"{tags.phrase(step.lines)} {names}"
    )
    blocks = [f"{lead} ({escape_markdown(step.method)}):"]
    blocks += [_display(_result(r)) for r in step.results]
    if step.discarded:
        items = "\n".join(
            f"- {escape_markdown(pretty_unit(tags.untagged(d)))}" for d in step.discarded
        )
        blocks.append(f"Discarded roots:\n\n{items}")
    if step.note.strip():
        blocks.append(f"*{escape_markdown(step.note)}*")
    return "\n\n".join(blocks)


def _result(result: Formula) -> str:
    """``T = \\frac{...}{...} = 106\\,\\mathrm{N}``; the value alone when no formula."""
    formula, value = result.formula_latex.strip(), result.value_latex.strip()
    numbers = result.substituted_latex.strip()
    parts = [p for p in (formula, numbers, value) if p]
    if len(parts) >= 2 and formula == value:
        parts = [formula]
    return f"{latex_name(result.name)} = " + " = ".join(parts or ["?"])


def _answers_section(answers: Sequence[AnswerRow], key: Sequence[KeyComparison]) -> str:
    if not answers:
        return "## Answers\n\nNo answers."
    expected = {k.name: k for k in key}
    header = ["Quantity", "Value"] + (["Answer key", ""] if expected else [])
    rows = [_answer_cells(a, expected.get(a.name), bool(expected)) for a in answers]
    return "## Answers\n\n" + _table(header, [":--"] * len(header), rows)


def _answer_cells(answer: AnswerRow, key: KeyComparison | None, keyed: bool) -> list[str]:
    value = _cell_math(answer.latex) or f"*{escape_markdown(answer.shown)}*"
    if answer.direction:
        value += f" {escape_markdown(answer.direction)}"
    cells = [_cell_math(latex_name(answer.name)), value]
    if keyed:
        cells += (
            [escape_markdown(pretty_unit(key.expected)), _mark(key.passed)] if key else ["", ""]
        )
    return cells


def _checks_section(checks: Sequence[Check]) -> str:
    if not checks:
        return "## Checks\n\nNo checks."
    _, failed, not_run = check_counts(checks)
    verdict = f"All {len(checks)} checks passed."
    if not_run:
        verdict = f"{len(checks) - not_run} of {len(checks)} checks passed; {not_run} not run."
    if failed:
        verdict = f"**{failed} of {len(checks)} checks failed.**"
        verdict += f" {not_run} not run." if not_run else ""
    rows = [[_status_mark(c.status), escape_markdown(c.name), _check_detail(c)] for c in checks]
    return f"## Checks\n\n{verdict}\n\n" + _table(
        ["", "Check", "Detail"], [":-:", ":--", ":--"], rows
    )


def _check_detail(check: Check | Assumption) -> str:
    return escape_markdown(pretty_unit(check.shown_detail))


# ---- scene mode


def _free_body_section(bodies: Sequence[FreeBody]) -> list[str]:
    """The "Free-body diagrams" section, or nothing in equation mode."""
    if not bodies:
        return []
    return ["\n\n".join(["## Free-body diagrams", *(_free_body(b) for b in bodies)])]


def _free_body(body: FreeBody) -> str:
    """A body: its forces as a table, then the motion, moment point and kinetic terms."""
    shape = f" ({escape_markdown(body.shape)})" if body.shape.strip() else ""
    blocks = [f"### {escape_markdown(body.body) or '?'}{shape}"]
    if body.forces:
        header = ["Force", "Kind", "Point", "Direction", "Known", "Value"]
        rows = [_force_cells(f) for f in body.forces]
        blocks.append(_table(header, [":--"] * len(header), rows))
    else:
        blocks.append("No forces.")
    facts = [f"- Motion: {escape_markdown(body.motion) or '?'}"]
    if body.moment_point.strip():
        facts.append(f"- Moments about: {escape_markdown(body.moment_point)}")
    if body.kinetic:
        facts.append("- Kinetic diagram: " + ", ".join(_kinetic_term(t) for t in body.kinetic))
    blocks.append("\n".join(facts))
    return "\n\n".join(blocks)


def _force_cells(force: ForceRow) -> list[str]:
    name = _force_name(force.name)
    known = "yes" if force.known else "**no**"
    text = [escape_markdown(t) for t in (force.kind, force.point, force.direction)]
    return [name, *text, known, escape_markdown(pretty_unit(force.value))]


def _force_name(name: str) -> str:
    """A spec name as math; anything else as escaped text."""
    if _IDENTIFIER.fullmatch(name):
        return _cell_math(latex_name(name))
    return escape_markdown(name) or "?"


def _kinetic_term(term: str) -> str:
    """``m a_Gx`` as ``$m \\, a_{Gx}$`` when every word is a name or Greek; else as text."""
    words = term.split()
    if words and all(_IDENTIFIER.fullmatch(w) or _greek(w) for w in words):
        parts = [latex_name(w) if _IDENTIFIER.fullmatch(w) else w for w in words]
        return _math(" \\, ".join(parts))
    return escape_markdown(term)


def _greek(word: str) -> bool:
    return all("\u0391" <= char <= "\u03c9" and char.isalpha() for char in word)


def _assumptions_section(assumptions: Sequence[Assumption]) -> list[str]:
    """The "Assumptions" table: each assumption made to solve, and whether it held."""
    if not assumptions:
        return []
    rows = [
        [_status_mark(a.status), escape_markdown(a.name) or "?", _check_detail(a)]
        for a in assumptions
    ]
    table = _table(["", "Assumption", "Detail"], [":-:", ":--", ":--"], rows)
    return [f"## Assumptions\n\n{table}"]
