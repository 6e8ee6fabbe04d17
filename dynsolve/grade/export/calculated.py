"""A problem's variants as Moodle ``calculated`` questions: one per part, whose dataset
items are the variants, so Moodle draws one variant per attempt.

Moodle's calculated question evaluates a formula of wildcards on a dataset item. Here
each varied given is a wildcard shown in the statement (``{m_d} kg``) and each part's
answer is a wildcard too (``{key_alpha}``), its items the expected answers dynsolve
computed: the answer formula is the wildcard itself, so Moodle never re-derives the
physics. Each dataset is private to its question (``status`` private); item k of every
dataset is variant k. A relative tolerance is Moodle's ``tolerancetype`` 1, ``decdig N``
the nominal (absolute) type 2 with 0.51·10^-N; ``sigfig`` and ``atol`` rules have no
calculated counterpart and are refused (the numerical questions carry them).
"""

from __future__ import annotations

from collections.abc import Sequence
from xml.etree import ElementTree

from dynsolve.grade.export.moodle import number, question_header, text, unit_options
from dynsolve.grade.export.statement import asked, statement, to_html
from dynsolve.grade.export.table import Part, Variant, VariantTable
from dynsolve.grade.export.target import ExportError
from dynsolve.grade.semantics import SIGFIG_SLACK

MAX_ITEMS = 100  # qtype_calculated's MAX_DATASET_ITEMS
RELATIVE, NOMINAL = "1", "2"  # qtype_calculated tolerance types
SIGNIFICANT = "2"  # correctanswerformat: the correct answer shown to N significant figures


def calculated_questions(table: VariantTable) -> list[ElementTree.Element]:
    """One calculated question per part (see the module docstring)."""
    rows = _unique(table.variants)
    if len(rows) > MAX_ITEMS:
        raise ExportError(
            f"{len(rows)} different variants: a Moodle calculated question holds at most "
            f"{MAX_ITEMS} dataset items",
            hint="leave out --calculated (one numerical question per student)",
        )
    varied = _varied_givens(table, rows)
    givens = [(g.name, _shown(g.name, varied, rows[0]), g.description) for g in table.givens]
    questions = []
    for part in table.parts:
        key = _key_name(part, table)
        html = to_html(statement("div", table.title, givens, [asked(part)]))
        question = question_header("calculated", f"{table.title}: {part.name}", html, part)
        options = {"synchronize": "0", "single": "0", "answernumbering": "abc",
                   "shuffleanswers": "0"}  # fmt: skip
        for tag, value in options.items():
            ElementTree.SubElement(question, tag).text = value
        _answer(question, part, key)
        unit_options(question, part)
        definitions = ElementTree.SubElement(question, "dataset_definitions")
        for name in varied:
            values = [float(row.givens[name].split()[0]) for row in rows]
            _dataset(definitions, name, values)
        _dataset(definitions, key, [row.answers[part.name].value for row in rows])
        questions.append(question)
    return questions


def _answer(question: ElementTree.Element, part: Part, key: str) -> None:
    rule = part.rule
    if rule.sigfig or rule.atol:
        raise ExportError(
            f"{part.name}: a {'sigfig' if rule.sigfig else 'atol'} rule has no Moodle "
            "calculated tolerance",
            hint="leave out --calculated (numerical questions carry every rule)",
        )
    kind, tolerance = RELATIVE, rule.rtol
    if rule.decdig:
        kind, tolerance = NOMINAL, SIGFIG_SLACK * 10.0**-rule.decdig
    answer = ElementTree.SubElement(question, "answer", fraction="100")
    text(answer, f"{{{key}}}")
    fields = {
        "tolerance": number(tolerance),
        "tolerancetype": kind,
        "correctanswerformat": SIGNIFICANT,
        "correctanswerlength": "3",
    }
    for tag, value in fields.items():
        ElementTree.SubElement(answer, tag).text = value
    text(ElementTree.SubElement(answer, "feedback", format="html"), "")


def _dataset(parent: ElementTree.Element, name: str, values: Sequence[float]) -> None:
    definition = ElementTree.SubElement(parent, "dataset_definition")
    text(ElementTree.SubElement(definition, "status"), "private")
    text(ElementTree.SubElement(definition, "name"), name)
    ElementTree.SubElement(definition, "type").text = "calculated"
    text(ElementTree.SubElement(definition, "distribution"), "uniform")
    text(ElementTree.SubElement(definition, "minimum"), number(min(values)))
    text(ElementTree.SubElement(definition, "maximum"), number(max(values)))
    text(ElementTree.SubElement(definition, "decimals"), "3")
    ElementTree.SubElement(definition, "itemcount").text = str(len(values))
    items = ElementTree.SubElement(definition, "dataset_items")
    for index, value in enumerate(values, start=1):
        item = ElementTree.SubElement(items, "dataset_item")
        ElementTree.SubElement(item, "number").text = str(index)
        ElementTree.SubElement(item, "value").text = number(value)
    ElementTree.SubElement(definition, "number_of_items").text = str(len(values))


def _shown(name: str, varied: dict[str, str], first: Variant) -> str:
    """A given in the statement: its wildcard and unit (``{m_d} kg``), or its value."""
    return f"{{{name}}} {varied[name]}".strip() if name in varied else first.givens[name]


def _unique(variants: Sequence[Variant]) -> list[Variant]:
    seen: dict[tuple[tuple[str, str], ...], Variant] = {}
    for variant in variants:
        seen.setdefault(tuple(sorted(variant.givens.items())), variant)
    return list(seen.values())


def _varied_givens(table: VariantTable, rows: Sequence[Variant]) -> dict[str, str]:
    """The givens whose value differs between variants → their unit (the same in every
    row: a wildcard holds a number)."""
    varied: dict[str, str] = {}
    for given in table.givens:
        texts = {row.givens[given.name] for row in rows}
        if len(texts) == 1:
            continue
        units = {t.partition(" ")[2].strip() for t in texts}
        if len(units) > 1:
            raise ExportError(
                f"{given.name} is given in {' and '.join(sorted(units))} by different variants",
                hint="export the SI and US customary variants separately",
            )
        varied[given.name] = units.pop()
    return varied


def _key_name(part: Part, table: VariantTable) -> str:
    """The answer's wildcard: ``key_NAME``, lengthened until no given has that name."""
    name = f"key_{part.name}"
    while any(g.name == name for g in table.givens):
        name += "_"
    return name
