"""Render a :class:`~dynsolve.results.Solution` as one self-contained HTML page.

The same sections, in the same order, as the LaTeX sheet (:func:`dynsolve.render.sheet_plan`):
givens, the scene and the free-body and kinetic diagrams, assumptions, trials, each equation
with its unit check, the solve, the answers with units and sense, the checks. Equations are
MathML (the solution's LaTeX fragments converted by ``latex2mathml``; browsers render MathML
Core natively), the figures inline SVG drawn from the very TikZ the sheet draws
(:mod:`dynsolve.render.tikz_svg`). No script, no font, no stylesheet from elsewhere: the page
opens offline. Every piece of user text (title, source, names, notes) is an ElementTree text
node, so it is escaped; nothing is pasted in as markup but MathML and SVG built here.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from collections.abc import Callable, Sequence
from pathlib import PurePath

from latex2mathml.converter import convert

from dynsolve.format import pretty_unit
from dynsolve.names import latex_name
from dynsolve.render import Layout, sheet_plan
from dynsolve.render.latex import caption_pieces, free_body_picture, kinetic_math, safe_math
from dynsolve.render.numbering import EquationTags, sheet_tags
from dynsolve.render.tikz_svg import svg_pictures
from dynsolve.results import (
    AnswerRow,
    Assumption,
    Check,
    EnergyTerm,
    EquationRow,
    Formula,
    FreeBody,
    GivenRow,
    KeyComparison,
    LimitRemark,
    Remark,
    Solution,
    Step,
    Trial,
)

Item = str | ET.Element
MATHML = "http://www.w3.org/1998/Math/MathML"
TICK, CROSS = "\u2713", "\u2717"
STYLE = """
.dynsolve { font-family: 'Latin Modern Roman', 'CMU Serif', Cambria, 'Times New Roman', serif;
  font-size: 17px; line-height: 1.45; max-width: 50em; margin: 1.5em auto; padding: 0 1em;
  color: #111; background: #fff; }
.dynsolve h1 { font-size: 1.6em; margin-bottom: 0.2em; }
.dynsolve h2 { font-size: 1.25em; margin-top: 1.6em; border-bottom: 1px solid #ccc; }
.dynsolve h3 { font-size: 1.08em; margin: 1.1em 0 0.3em; }
.dynsolve .source { font-style: italic; font-size: 1.15em; margin-top: 0; }
.dynsolve .summary { font-size: 0.9em; color: #444; }
.dynsolve table { border-collapse: collapse; margin: 0.6em auto; }
.dynsolve th { border-top: 2px solid #333; border-bottom: 1px solid #333; text-align: left; }
.dynsolve tbody tr:last-child td { border-bottom: 2px solid #333; }
.dynsolve th, .dynsolve td { padding: 0.25em 0.8em; vertical-align: middle; }
.dynsolve .equation { margin: 0.9em 0; }
.dynsolve .caption { display: flex; justify-content: space-between; gap: 1em; }
.dynsolve .caption .principle { font-style: italic; }
.dynsolve .caption .units { font-size: 0.88em; color: #333; white-space: nowrap; }
.dynsolve .display { display: grid; grid-template-columns: 1fr auto; align-items: center;
  gap: 1em; overflow-x: auto; }
.dynsolve .tag { font-size: 0.88em; color: #555; white-space: nowrap; }
.dynsolve math[display=block] { margin: 0.4em 0; font-size: 1.08em; }
.dynsolve figure { margin: 0.8em 0; text-align: center; }
.dynsolve .diagrams { display: flex; align-items: center; justify-content: center;
  flex-wrap: wrap; gap: 1.2em; }
.dynsolve .equals { font-size: 1.6em; }
.dynsolve svg { max-width: 100%; height: auto; }
.dynsolve .facts { font-size: 0.95em; }
.dynsolve .note { font-size: 0.9em; color: #444; }
.dynsolve ul.marked { list-style: none; padding-left: 0.4em; }
.dynsolve .pass { color: #1a7f37; font-weight: bold; }
.dynsolve .fail { color: #c00; font-weight: bold; }
.dynsolve .warning { border-left: 4px solid #c60; padding-left: 0.6em; }
@media print { .dynsolve { font-size: 11pt; max-width: none; }
  .dynsolve .equation, .dynsolve figure, .dynsolve section.body { break-inside: avoid; }
  .dynsolve h1, .dynsolve h2, .dynsolve h3 { break-after: avoid; } }
"""


def render_html(solution: Solution, layout: Layout = "full", source: bool | None = None) -> str:
    """The solution as one self-contained HTML page; ``layout`` and ``source`` as for LaTeX
    (``full``, ``handout`` or ``key``; the spec's source line shown or not).

    >>> from dynsolve.results import AnswerRow, Solution
    >>> answer = AnswerRow("T", 105.86, "N", "106 N", "14715/139", "106\\\\,\\\\mathrm{N}", "")
    >>> page = render_html(Solution("d.dyn", "<script>x</script>", "", "SI", "equations",
    ...                             (), (), (), (answer,), (), (), "solved"))
    >>> page.startswith("<!DOCTYPE html>"), "<script>" in page, "&lt;script&gt;" in page
    (True, False, True)
    >>> "<mn>106</mn>" in page
    True
    """
    head = ET.Element("head")
    ET.SubElement(head, "meta", {"charset": "utf-8"})
    ET.SubElement(head, "meta", {"name": "viewport", "content": "width=device-width"})
    ET.SubElement(head, "title").text = _title_text(solution)
    ET.SubElement(head, "style").text = STYLE
    page = ET.Element("html", {"lang": "en"})
    page.append(head)
    body = ET.SubElement(page, "body")
    body.append(html_article(solution, layout, source))
    return "<!DOCTYPE html>\n" + ET.tostring(page, encoding="unicode", method="html") + "\n"


def html_fragment(solution: Solution, layout: Layout = "full") -> str:
    """The page's content without its ``<html>`` frame (its style kept): what Jupyter shows."""
    style = ET.Element("style")
    style.text = STYLE
    return "".join(
        ET.tostring(e, encoding="unicode", method="html")
        for e in (style, html_article(solution, layout))
    )


def html_article(
    solution: Solution, layout: Layout = "full", source: bool | None = None
) -> ET.Element:
    """The derivation as an ``<article class="dynsolve">`` element."""
    plan = sheet_plan(layout, source)
    cited = "source" in plan
    key = solution.key if "key" in plan else ()
    tags = sheet_tags(solution, numbered=layout == "handout")
    parts: dict[str, Callable[[], list[ET.Element]]] = {
        "title": lambda: _title(solution, cited=cited),
        "handout_title": lambda: _title(solution, handout=True, cited=cited),
        "warnings": lambda: [
            _el("p", {"class": "warning"}, _el("strong", None, "Warning: "), w)
            for w in solution.warnings
        ],
        "givens": lambda: _givens(solution.givens, solution.system),
        "free_body": lambda: _figures(solution),
        "assumptions": lambda: _assumptions(solution.assumptions),
        "trials": lambda: [
            e for t, ts in zip(solution.trials, tags.trials, strict=True) for e in _trial(t, ts)
        ],
        "equations": lambda: [
            *_equations(solution.equations, tags.final, title=_resolved("Equations", solution)),
            *_second_moments(solution.second_moments, tags.final),
        ],
        "energy": lambda: _energy(solution.energy),
        "steps": lambda: _solution(
            solution.steps, tags.final, title=_resolved("Solution", solution)
        ),
        "answers": lambda: [
            *_answers(solution.answers, key),
            *(_el("p", None, _el("em", None, "Remark: "), *_remark(r)) for r in solution.remarks),
        ],
        "checks": lambda: _checks(solution.checks),
    }
    article = ET.Element("article", {"class": "dynsolve"})
    article.extend(e for name in plan if name in parts for e in parts[name]())
    return article


# ---- building blocks


def _el(tag: str, attrs: dict[str, str] | None, *items: Item) -> ET.Element:
    """An element with ``items`` inside: strings as text (escaped when written), elements."""
    element = ET.Element(tag, attrs or {})
    _add(element, *items)
    return element


def _add(element: ET.Element, *items: Item) -> None:
    for item in items:
        if isinstance(item, str):
            if len(element):
                element[-1].tail = (element[-1].tail or "") + item
            else:
                element.text = (element.text or "") + item
        else:
            element.append(item)


_SINGLE_ROMAN = re.compile(r"\\mathrm\{([A-Za-z])\}")


def math(latex: str, display: bool = False) -> ET.Element:
    """LaTeX math (a solution's fragment) as a MathML ``<math>`` element; text in a
    ``<span>`` if the converter cannot read it.

    >>> [e.tag for e in math("I_{O} \\\\alpha").iter()]
    ['math', 'mrow', 'msub', 'mi', 'mrow', 'mi', 'mi']
    """
    fragment = safe_math(latex, siunitx=False).strip()
    fragment = _SINGLE_ROMAN.sub(r"\\text{\1}", fragment)  # "N" upright, as a unit
    try:
        element = ET.fromstring(convert(fragment, display="block" if display else "inline"))
    except Exception:  # the converter's own errors have no common base
        return _el("span", {"class": "math-text"}, latex)
    for node in element.iter():
        node.tag = node.tag.removeprefix(f"{{{MATHML}}}")
    _tighten(element)
    return element


_FUNCTIONS = frozenset({
    "sin", "cos", "tan", "cot", "sec", "csc", "asin", "acos", "atan", "arcsin", "arccos",
    "arctan", "sinh", "cosh", "tanh", "exp", "log", "ln",
})  # fmt: skip


def _tighten(element: ET.Element) -> None:
    """Operator spacing as in print: no space around the ``/`` of a unit (m/s²), none
    after a sign that starts a row or follows ``=`` (``= −11.3``), brackets around a
    single line not stretched (``cos(θ)``), a thin space before a function's name."""
    for row in element.iter():
        before = None
        for child in row:
            if child.tag == "mo" and (
                child.text == "/"
                or (
                    child.text in ("−", "-", "+")
                    and (before is None or (before.tag == "mo" and before.text in ("=", "(", ",")))
                )
            ):
                child.set("lspace", "0")
                child.set("rspace", "0")
            before = child
        for k, child in reversed(list(enumerate(row))):
            if k and child.tag == "mi" and child.text in _FUNCTIONS and row[k - 1].tag != "mo":
                row.insert(k, ET.Element("mspace", {"width": "0.167em"}))  # L cos θ, as TeX
        fences = [c for c in row if c.tag == "mo" and c.get("fence") == "true"]
        if fences and not any(e.tag in ("mfrac", "msqrt", "mroot") for e in row.iter()):
            for fence in fences:  # around one line: the font's own brackets, no gaps
                fence.set("stretchy", "false")
                fence.set("lspace", "0")
                fence.set("rspace", "0")


def _name(name: str) -> ET.Element:
    return math(latex_name(name))


def _math_or_empty(fragment: str) -> list[Item]:
    return [math(fragment)] if fragment.strip() else []


_NAME = re.compile(r"(?<![\w./])([A-Za-zα-ωΑ-Ω][A-Za-z0-9α-ω]*(?:_[A-Za-z0-9α-ω]+)+)(?![\w/])")


def _caption(text: str) -> list[Item]:
    """A caption or note: its symbols as MathML (``ΣF_x``, and every name with a subscript,
    ``a_Gx_block``, as the equations write it), the words as text."""
    out: list[Item] = []
    for is_math, piece in caption_pieces(text):
        if is_math:
            out.append(math(piece))
            continue
        for k, part in enumerate(_NAME.split(piece)):
            if part:
                out.append(math(latex_name(part)) if k % 2 else part)
    return out


def _mark(passed: bool) -> ET.Element:
    return _el("span", {"class": "pass" if passed else "fail"}, TICK if passed else CROSS)


def _table(header: Sequence[str], rows: Sequence[Sequence[Sequence[Item]]]) -> ET.Element:
    table = _el("table", None)
    head = ET.SubElement(ET.SubElement(table, "thead"), "tr")
    for cell in header:
        _add(head, _el("th", None, cell))
    body = ET.SubElement(table, "tbody")
    for row in rows:
        tr = ET.SubElement(body, "tr")
        for cell in row:
            _add(tr, _el("td", None, *cell))
    return table


# ---- title and givens


def _title_text(solution: Solution) -> str:
    return solution.title.strip() or PurePath(solution.file).name or "Problem"


def _title(solution: Solution, handout: bool = False, cited: bool = True) -> list[ET.Element]:
    """The title, the source line when ``cited``, and (not on the handout) the spec's file
    name, status and solver messages."""
    out = [_el("h1", None, _title_text(solution))]
    if cited and solution.source.strip():
        out.append(_el("p", {"class": "source"}, solution.source))
    if handout:  # the handout names no file, status or solver remarks
        return out
    spec = PurePath(solution.file).name
    out.append(
        _el(
            "p",
            {"class": "summary"},
            "Spec ",
            _el("code", None, spec),
            f"; units {solution.system}; status ",
            _el("strong", None, solution.status),
            ".",
        )
    )
    if solution.messages:
        out.append(_el("ul", None, *(_el("li", None, m) for m in solution.messages)))
    return out


def _prose(text: str) -> list[Item]:
    return _caption(text.replace("^2", "²").replace("^3", "³"))


def _givens(givens: Sequence[GivenRow], system: str) -> list[ET.Element]:
    out = [_el("h2", None, "Given")]
    if not givens:
        return [*out, _el("p", None, "No givens.")]
    derived = [g for g in givens if not g.symbolic and "=" in g.latex_value]
    rows = [
        [
            _math_or_empty(g.latex_name),
            _caption(g.written) if g.symbolic else _math_or_empty(g.latex_value),
            [pretty_unit(g.base)],
            _prose(g.description),
        ]
        for g in givens
        if g not in derived
    ]
    if rows:
        out.append(_table(["Symbol", "Value", f"{system} value", "Description"], rows))
    for g in derived:
        out.append(_el("p", None, *_prose(g.description), ":"))
        shown = math(f"{g.latex_name} = {g.latex_value}", display=True)
        if g.base:  # the value in base units, as text
            row = shown[0] if len(shown) else shown
            _add(row, _el("mo", None, "="), _el("mtext", None, pretty_unit(g.base)))
        out.append(shown)
    return out


# ---- figures


def _figures(solution: Solution) -> list[ET.Element]:
    """The scene, each body's free-body and kinetic diagrams, the linkage: inline SVG."""
    out: list[ET.Element] = []
    if solution.sketch is not None:
        from dynsolve.render.scene_figure import scene_picture

        pictures = _drawn(scene_picture(solution.sketch), "scene", "The scene")
        pictures = [p for p in pictures if len(p)]
        if pictures:  # a scene with nothing to draw (a path given by its equation) has none
            out.append(_el("h2", None, "The scene"))
            out.append(_el("figure", {"class": "scene"}, *pictures))
    if solution.free_body:
        out.append(_el("h2", None, "Free-body diagrams"))
        out += [_free_body(b, solution.system, k) for k, b in enumerate(solution.free_body)]
    if solution.linkage is not None:
        from dynsolve.render.linkage_figure import linkage_picture

        out.append(_el("h2", None, "The linkage at the instant"))
        pictures = _drawn(linkage_picture(solution.linkage), "linkage", "Linkage")
        out.append(_el("figure", {"class": "linkage"}, *pictures))
    return out


def _drawn(tikz: str, ident: str, *names: str) -> list[ET.Element]:
    """The TikZ pictures as SVG, each named for a screen reader (``aria-label``) in order;
    a picture the SVG back end cannot draw is said so on the page, in its place."""
    try:
        pictures = svg_pictures(tikz, ident)
    except ValueError as error:
        return [_el("p", {"class": "fail"}, f"{names[0]}: not drawn ({error}).")]
    for picture, name in zip(pictures, names, strict=False):
        picture.set("aria-label", name)
    return pictures


def _free_body(body: FreeBody, system: str, index: int) -> ET.Element:
    """One body: its free-body diagram = its kinetic diagram, then the facts."""
    shape = f" ({body.shape})" if body.shape.strip() else ""
    name = body.body or "?"
    pictures = _drawn(
        free_body_picture(body, system),
        f"body{index}",
        f"Free-body diagram of {name}",
        f"Kinetic diagram of {name}",
    )
    drawn: list[Item] = [pictures[0]]
    for picture in pictures[1:]:
        drawn += [_el("span", {"class": "equals"}, "="), picture]
    facts: list[Item] = [_el("strong", None, "Motion: "), *(_caption(body.motion) or ["?"]), "."]
    if body.moment_point.strip():
        facts += [_el("br", None), _el("strong", None, "Moments about: ")]
        facts += [*_caption(body.moment_point), "."]
    if body.kinetic:
        facts += [_el("br", None), _el("strong", None, "Kinetic diagram: ")]
        for k, term in enumerate(body.kinetic):
            term_math = kinetic_math(term)
            facts += [", "] * bool(k) + [math(term_math) if term_math is not None else term]
        facts.append(".")
    notes = []
    if any(not f.known for f in body.forces):
        notes.append("Unknown forces are dashed and red; known forces solid.")
    if body.kinetic:
        notes.append("The kinetic diagram (blue, right of =) shows the senses assumed.")
    return _el(
        "section",
        {"class": "body"},
        _el("h3", None, *_caption(body.body or "?"), shape),
        _el("figure", {"class": "diagrams"}, *drawn),
        _el("p", {"class": "facts"}, *facts),
        *([_el("p", {"class": "note"}, " ".join(notes))] if notes else []),
    )


# ---- assumptions, equations, energy


def _assumptions(assumptions: Sequence[Assumption]) -> list[ET.Element]:
    if not assumptions:
        return []
    items = []
    for a in assumptions:
        status = "holds" if a.holds else "fails"
        detail = pretty_unit(a.detail)
        tail: list[Item] = [": ", *_caption(detail)] if detail.strip() else []
        items.append(
            _el("li", None, _mark(a.holds), " ", _el("strong", None, *_caption(a.name or "?")),
                f" ({status})", *tail)
        )  # fmt: skip
    return [_el("h2", None, "Assumptions"), _el("ul", {"class": "marked"}, *items)]


def _equations(
    rows: Sequence[EquationRow], tags: EquationTags, level: str = "h2", title: str = "Equations"
) -> list[ET.Element]:
    out = [_el(level, None, title)]
    if not rows:
        return [*out, _el("p", None, "No equations.")]
    return out + [_equation(e, tags) for e in rows]


def _second_moments(
    rows: Sequence[EquationRow], tags: EquationTags, level: str = "h2"
) -> list[ET.Element]:
    if not rows:
        return []
    title = _el(level, None, "A second moment point (a check, not used to solve)")
    return [title, *(_equation(e, tags) for e in rows)]


_DIMENSION = re.compile(r"^(.*\S)\s+\[([^\[\]]*)\]$")


def _equation(row: EquationRow, tags: EquationTags) -> ET.Element:
    """The principle, the unit check on the right, then the equation displayed with its
    tag."""
    note = _caption(row.note)
    if row.constraint:
        note = ["Constraint", *([": ", *note] if note else [])]
    match = _DIMENSION.match(row.dimension.strip())
    text = f"{match.group(1)}, {pretty_unit(match.group(2))}" if match else row.dimension.strip()
    units: list[Item] = [f"[{text}] "] if text else []
    if row.dimension_ok:
        units.append(_mark(True))
    else:
        units = [_el("strong", None, "dimensions differ "), *units, _mark(False)]
    tag = _el("span", {"class": "tag"}, tags.tag(row))
    display: list[Item] = [math(row.latex or "?", display=True), tag]
    return _el(
        "div",
        {"class": "equation"},
        _el("div", {"class": "caption"}, _el("span", {"class": "principle"}, *note),
            _el("span", {"class": "units"}, *units)),
        _el("div", {"class": "display"}, *display),
    )  # fmt: skip


def _energy(terms: Sequence[EnergyTerm]) -> list[ET.Element]:
    if not terms:
        return []
    rows = [
        [[_name(t.name)], _math_or_empty(t.formula_latex), _math_or_empty(t.value_latex),
         _caption(t.meaning)]
        for t in terms
    ]  # fmt: skip
    title = _el("h2", None, "Work and energy: ", math(r"T_1 + \Sigma U_{1 \to 2} = T_2"),
                ", term by term")  # fmt: skip
    return [title, _table(["Term", "Formula", "Value", ""], rows)]


# ---- solve, trials


def _trial(trial: Trial, tags: EquationTags) -> list[ET.Element]:
    """A case assumed first: its equations and solve, then the check that rejected it."""
    return [
        _el("h2", None, "Trial: ", *_caption(trial.assumption), " (assumed, then checked)"),
        *_equations(trial.equations, tags, "h3"),
        *_solution(trial.steps, tags, "h3"),
        *_second_moments(trial.second_moments, tags, "h3"),
        _el("p", None, _el("strong", None, "Check: "), _mark(False), " ", *_caption(trial.verdict)),
        *(_el("p", None, _el("em", None, "Remark: "), *_caption(r)) for r in trial.remarks),
    ]


def _resolved(title: str, solution: Solution) -> str:
    """After a failed trial, the final solve's heading says it is the re-solve."""
    return f"{title} (re-solved)" if solution.trials else title


def _solution(
    steps: Sequence[Step], tags: EquationTags, level: str = "h2", title: str = "Solution"
) -> list[ET.Element]:
    out = [_el(level, None, title)]
    if not steps:
        return [*out, _el("p", None, "No solve steps.")]
    return out + [e for s in steps for e in _step(s, tags)]


def _step(step: Step, tags: EquationTags) -> list[ET.Element]:
    if step.heading:
        lead: list[Item] = _caption(step.heading)
    else:
        names: list[Item] = []
        for k, name in enumerate(step.unknowns):
            joint = "" if k == 0 else " and " if k == len(step.unknowns) - 1 else ", "
            names += [joint, _name(name)] if joint else [_name(name)]
        lead = [f"{tags.phrase(step.lines)} ", *names]
    out = [_el("p", None, _el("strong", None, f"Step {step.index}. "), *lead, f" ({step.method}):")]
    out += [_result(r) for r in step.results]
    if step.discarded:
        items = [_el("li", None, *_caption(pretty_unit(tags.untagged(d)))) for d in step.discarded]
        out += [_el("p", None, "Discarded roots:"), _el("ul", None, *items)]
    if step.note.strip():
        out.append(_el("p", {"class": "note"}, _el("em", None, *_caption(step.note))))
    return out


def _result(result: Formula) -> ET.Element:
    """``T = \\frac{...}{...} = numbers = 106 N`` as one displayed chain."""
    formula, value = result.formula_latex.strip(), result.value_latex.strip()
    numbers = result.substituted_latex.strip()
    parts = [p for p in (formula, numbers, value) if p]
    if len(parts) >= 2 and formula == value:
        parts = [formula]
    return math(" = ".join([latex_name(result.name), *(parts or ["?"])]), display=True)


# ---- answers, remarks, checks


def _answers(answers: Sequence[AnswerRow], key: Sequence[KeyComparison]) -> list[ET.Element]:
    out = [_el("h2", None, "Answers")]
    if not answers:
        return [*out, _el("p", None, "No answers.")]
    expected = {k.name: k for k in key}
    header = ["Quantity", "Value"] + (["Answer key", ""] if expected else [])
    rows = []
    for a in answers:
        value: list[Item] = [math(a.latex)] if a.latex.strip() else [_el("em", None, a.shown)]
        if a.direction:
            value.append(f" {a.direction}")
        row: list[list[Item]] = [[_name(a.name)], value]
        if expected:
            k = expected.get(a.name)
            row += [[pretty_unit(k.expected)], [_mark(k.passed)]] if k else [[], []]
        rows.append(row)
    return [*out, _table(header, rows)]


def _remark(remark: Remark | LimitRemark) -> list[Item]:
    """A remark's words with its names as MathML (placed where ``words`` puts them)."""
    maths: list[str] = []

    def slot(latex: str) -> str:
        maths.append(latex)
        return f"\x00{len(maths) - 1}\x00"

    if isinstance(remark, LimitRemark):
        value = (
            f"{slot(remark.value_latex)} {remark.direction}".strip() if remark.value_latex else ""
        )
        words = remark.words(
            slot(latex_name(remark.given)),
            slot(latex_name(remark.answer)),
            slot(remark.formula_latex),
            value,
            [slot(latex_name(n)) for n in remark.whatever],
        )
    else:
        words = remark.words(
            [slot(latex_name(n)) for n in remark.answers],
            [slot(latex_name(n)) for n in remark.masses],
        )
    pieces = words.split("\x00")
    return [math(maths[int(p)]) if k % 2 else p for k, p in enumerate(pieces) if p]


def _checks(checks: Sequence[Check]) -> list[ET.Element]:
    out = [_el("h2", None, "Checks")]
    if not checks:
        return [*out, _el("p", None, "No checks.")]
    failed = sum(not c.passed for c in checks)
    verdict: Item = f"All {len(checks)} checks passed."
    if failed:
        verdict = _el("strong", None, f"{failed} of {len(checks)} checks failed.")
    items = []
    for c in checks:
        detail = [": ", *_caption(pretty_unit(c.detail))] if c.detail.strip() else []
        status = "" if c.passed else " (failed)"
        items.append(_el("li", None, _mark(c.passed), " ", _el("strong", None, c.name),
                         status, *detail))  # fmt: skip
    return [*out, _el("p", None, verdict), _el("ul", {"class": "marked"}, *items)]
