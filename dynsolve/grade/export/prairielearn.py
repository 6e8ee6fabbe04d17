"""A problem's variants as a PrairieLearn question folder that needs no dynsolve on the
course server: ``info.json``, ``question.html`` and a ``server.py`` whose ``generate``
draws one row of the pre-computed variant table embedded in it.

- ``info.json``: ``uuid``, ``title``, ``topic``, ``tags``, ``type`` ``"v3"`` (the fields
  PrairieLearn's question schema requires are uuid, type, title and topic).
- ``question.html``: the statement in ``<pl-question-panel>`` (givens from
  ``{{params.NAME}}``; a ``{`` of the spec's text is written ``&#123;``, never a template
  tag), then one ``<pl-number-input>`` per part with ``answers-name``, ``label``,
  ``suffix`` (the unit) and the part's rule: ``comparison="relabs"`` with ``rtol`` and
  ``atol``, or ``comparison="sigfig"``/``"decdig"`` with ``digits``; ``weight``.
- ``server.py``: the table is a Python string literal (``repr`` of its JSON), so no text
  of the spec or the variants file can become code. It lives in ``server.py``, which
  students cannot download (``clientFilesQuestion/`` is public), and PrairieLearn seeds
  ``random`` per variant, so a variant's row is stable across reloads.
"""

from __future__ import annotations

import json
import uuid as uuids
from collections.abc import Mapping
from pathlib import Path
from xml.etree import ElementTree

from dynsolve.files import read_capped
from dynsolve.grade.export.moodle import number
from dynsolve.grade.export.statement import asked, statement, to_html
from dynsolve.grade.export.table import Part, VariantTable
from dynsolve.grade.export.target import ExportError
from dynsolve.names import latex_name
from dynsolve.quantities import unit_info

MAX_INFO_BYTES = 1 << 20

SERVER = '''"""PrairieLearn server code written by dynsolve (dynsolve export prairielearn).

Each variant is one row of a table dynsolve computed and checked: the givens shown to
the student (params) and the answers (correct_answers). Regenerate it rather than edit.
"""

import json
import random

VARIANTS = json.loads({table})


def generate(data):
    """Pick one pre-computed variant (PrairieLearn seeds random per variant)."""
    row = random.choice(VARIANTS)
    data["params"].update(row["params"])
    data["correct_answers"].update(row["correct_answers"])
'''


def question_files(
    table: VariantTable, topic: str, tags: tuple[str, ...] = (), uuid: str = ""
) -> dict[str, str]:
    """The folder's files (name → text); a new random UUID unless ``uuid`` is given."""
    info = {
        "uuid": uuid or str(uuids.uuid4()),
        "title": table.title,
        "topic": topic,
        "tags": ["dynsolve", *tags],
        "type": "v3",
    }
    return {
        "info.json": json.dumps(info, indent=2, ensure_ascii=False) + "\n",
        "question.html": question_html(table),
        "server.py": SERVER.format(table=repr(table_json(table))),
    }


def table_json(table: VariantTable) -> str:
    """The variant rows as JSON: each with ``params`` (given texts) and ``correct_answers``
    (numbers in the parts' units); identical rows once, no student ids."""
    rows: dict[str, dict[str, object]] = {}
    for variant in table.variants:
        row = {
            "params": dict(variant.givens),
            "correct_answers": {n: a.value for n, a in variant.answers.items()},
        }
        rows.setdefault(json.dumps(row, sort_keys=True), row)
    return json.dumps(list(rows.values()), separators=(",", ":"), ensure_ascii=False)


def question_html(table: VariantTable) -> str:
    """The statement panel and one ``pl-number-input`` per part."""
    givens = [(g.name, "{{params." + g.name + "}}", g.description) for g in table.givens]
    panel = statement("pl-question-panel", table.title, givens, [asked(p) for p in table.parts])
    blocks = [panel]
    for part in table.parts:
        paragraph = ElementTree.Element("p")
        ElementTree.SubElement(paragraph, "pl-number-input", number_attributes(part))
        blocks.append(paragraph)
    for block in blocks:
        ElementTree.indent(block)
    return "\n".join(to_html(block) for block in blocks) + "\n"


def number_attributes(part: Part) -> Mapping[str, str]:
    """The ``pl-number-input`` attributes that grade ``part`` as its rule says."""
    rule = part.rule
    attributes = {"answers-name": part.name, "label": f"${latex_name(part.name)} =$"}
    if part.unit:
        attributes["suffix"] = part.unit
    if rule.sigfig or rule.decdig:
        attributes["comparison"] = "sigfig" if rule.sigfig else "decdig"
        attributes["digits"] = str(rule.sigfig or rule.decdig)
    else:
        attributes["comparison"] = "relabs"
        attributes["rtol"] = number(rule.rtol)
        attributes["atol"] = number(rule.atol / unit_info(part.unit).factor)
    if rule.weight != 1:
        if rule.weight != int(rule.weight):
            raise ExportError(
                f"{part.name} weight {rule.weight:g}: PrairieLearn weights are whole numbers",
                hint="use whole-number weights in the grading: section",
            )
        attributes["weight"] = str(int(rule.weight))
    return attributes


def existing_uuid(folder: Path) -> str:
    """The UUID of a question already in ``folder`` (kept when it is written again, so
    PrairieLearn sees the same question), or "" when there is none."""
    try:
        info = json.loads(read_capped(folder / "info.json", MAX_INFO_BYTES))
        return str(uuids.UUID(str(info.get("uuid", ""))))
    except (OSError, ValueError, AttributeError):  # absent, unreadable, not a question
        return ""
