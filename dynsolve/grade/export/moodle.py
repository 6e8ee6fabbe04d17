"""A problem's variants as a Moodle XML quiz: one ``numerical`` question per student and
part, with the part's unit and the tolerance its grading rule allows.

The file follows the Moodle XML format as Moodle's ``qformat_xml`` reads it: a ``<quiz>``
of ``<question>`` elements, first a ``category`` pseudo-question naming where the
questions go, then per question ``<name><text>``, ``<questiontext format="html">``, one
``<answer fraction="100">`` with its ``<text>`` and ``<tolerance>`` (absolute, ±), and
``<units>`` (``<unit>`` with ``<multiplier>`` 1 and ``<unit_name>``). Units are optional
for the student (``unitgradingtype`` 0): a bare number is read in the stated unit. Every
text is an ElementTree node, so student ids and spec text are escaped, never spliced.

>>> from dynsolve.grade.export.table import Answer, GivenLine, Part, Variant, VariantTable
>>> from dynsolve.grade.semantics import Rule
>>> table = VariantTable("Block", (GivenLine("m", "mass"),), (Part("a", "m/s^2", Rule(), False),),
...     (Variant("s1", {"m": "4 kg"}, {"a": Answer(2.5, "", 0.025)}),))
>>> quiz = ElementTree.fromstring(moodle_xml(table))
>>> [q.get("type") for q in quiz], quiz.find("question[2]/answer/tolerance").text
(['category', 'numerical'], '0.025')
"""

from __future__ import annotations

from collections.abc import Sequence
from xml.etree import ElementTree

from dynsolve.grade.export.statement import asked, statement, to_html
from dynsolve.grade.export.table import Part, Variant, VariantTable
from dynsolve.quantities import unit_info
from dynsolve.units import natural_unit

PENALTY = "0.3333333"  # Moodle's default penalty for each wrong try (interactive modes)
MAX_NAME = 255  # Moodle's question name column


def moodle_xml(
    table: VariantTable,
    category: str = "",
    questions: Sequence[ElementTree.Element] | None = None,
) -> bytes:
    """The quiz as UTF-8 XML bytes; ``category`` defaults to ``dynsolve/TITLE``. The
    questions are one numerical question per student and part unless ``questions`` are
    given (the calculated ones of :mod:`dynsolve.grade.export.calculated`)."""
    quiz = ElementTree.Element("quiz")
    header = ElementTree.SubElement(quiz, "question", type="category")
    path = category or f"dynsolve/{table.title}"
    text(ElementTree.SubElement(header, "category"), f"$course$/top/{path}")
    if questions is None:
        questions = [_numerical(table, v, p) for v in table.variants for p in table.parts]
    quiz.extend(questions)
    ElementTree.indent(quiz)
    return ElementTree.tostring(quiz, encoding="utf-8", xml_declaration=True) + b"\n"


def _numerical(table: VariantTable, variant: Variant, part: Part) -> ElementTree.Element:
    answer = variant.answers[part.name]
    question = question_header(
        "numerical",
        f"{table.title}: {variant.student}: {part.name}",
        question_html(table, variant, part),
        part,
    )
    key = ElementTree.SubElement(question, "answer", fraction="100", format="moodle_auto_format")
    text(key, number(answer.value))
    ElementTree.SubElement(key, "tolerance").text = number(answer.tolerance)
    text(ElementTree.SubElement(key, "feedback", format="html"), "")
    unit_options(question, part)
    return question


def question_header(kind: str, name: str, html: str, part: Part) -> ElementTree.Element:
    """A ``<question>`` with the fields every type shares: name, HTML question text,
    general feedback, default grade (the part's weight), penalty, hidden. No idnumber:
    Moodle wants it unique in a category, and two quizzes may share one."""
    question = ElementTree.Element("question", type=kind)
    text(ElementTree.SubElement(question, "name"), name[:MAX_NAME])
    text(ElementTree.SubElement(question, "questiontext", format="html"), html)
    text(ElementTree.SubElement(question, "generalfeedback", format="html"), "")
    ElementTree.SubElement(question, "defaultgrade").text = f"{part.rule.weight:g}"
    ElementTree.SubElement(question, "penalty").text = PENALTY
    ElementTree.SubElement(question, "hidden").text = "0"
    return question


def unit_options(question: ElementTree.Element, part: Part) -> None:
    """The part's units and how they are graded: optional for the student
    (``unitgradingtype`` 0, a bare number is read in the part's unit), typed in a box
    (``showunits`` 0, qtype_numerical::UNITINPUT; 3, UNITNONE, without a unit)."""
    if part.unit:
        units = ElementTree.SubElement(question, "units")
        for name, multiplier in accepted_units(part):
            unit = ElementTree.SubElement(units, "unit")
            ElementTree.SubElement(unit, "multiplier").text = number(multiplier)
            ElementTree.SubElement(unit, "unit_name").text = name
    for tag, value in (("unitgradingtype", "0"), ("unitpenalty", "0.1000000"),
                       ("showunits", "0" if part.unit else "3"), ("unitsleft", "0")):  # fmt: skip
        ElementTree.SubElement(question, tag).text = value


def accepted_units(part: Part) -> list[tuple[str, float]]:
    """The units a student may answer in, with Moodle's multiplier (the value in that
    unit is the value in the part's unit times it): the part's unit (1), then the unit
    of the same dimension in the other system (SI or US customary) when it differs.

    >>> from dynsolve.grade.semantics import Rule
    >>> [(u, round(m, 5)) for u, m in accepted_units(Part("T", "N", Rule(), False))]
    [('N', 1.0), ('lb', 0.22481)]
    """
    info = unit_info(part.unit)
    out = [(part.unit, 1.0)]
    for system in ("SI", "FPS"):
        other = natural_unit(info.dim, system, part.name)
        if other and all(other != name for name, _ in out):
            out.append((other, info.factor / unit_info(other).factor))
    return out


def question_html(table: VariantTable, variant: Variant, part: Part) -> str:
    """The question's statement (HTML): title, the variant's givens, the part asked for."""
    givens = [(g.name, variant.givens[g.name], g.description) for g in table.givens]
    return to_html(statement("div", table.title, givens, [asked(part)]))


def number(value: float) -> str:
    """A number as Moodle reads it: 12 significant figures, no thousands separator.

    >>> number(11.569347660759632), number(0.0051), number(-2.0)
    ('11.5693476608', '0.0051', '-2')
    """
    return f"{value:.12g}"


def text(parent: ElementTree.Element, content: str) -> None:
    """A ``<text>`` child holding ``content`` (escaped by ElementTree)."""
    ElementTree.SubElement(parent, "text").text = content
