"""Render the outcome of ``dynsolve check`` over many files as JSON or JUnit XML.

Each file is one :class:`FileOutcome`: passed, failed (with the failed checks) or
malformed (with the error texts). JUnit XML maps a file to a ``testcase``, a failed
check to a ``failure`` and a malformed spec to an ``error``, as CI servers expect.

>>> outcome = FileOutcome("a.dyn", "passed", ())
>>> import json
>>> json.loads(check_json([outcome]))["summary"]
{'passed': 1, 'failed': 0, 'malformed': 0}
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass
from xml.etree import ElementTree

STATUSES = ("passed", "failed", "malformed")


@dataclass(frozen=True)
class FileOutcome:
    """One spec's result: status and, unless it passed, (check name, detail) pairs."""

    file: str
    status: str  # "passed", "failed" or "malformed"
    problems: tuple[tuple[str, str], ...]


def summary(outcomes: Sequence[FileOutcome]) -> dict[str, int]:
    """How many files passed, failed and were malformed.

    >>> summary([FileOutcome("a", "failed", (("key", "off"),))])
    {'passed': 0, 'failed': 1, 'malformed': 0}
    """
    return {status: sum(o.status == status for o in outcomes) for status in STATUSES}


def check_json(outcomes: Sequence[FileOutcome]) -> str:
    """The JSON document: a summary and one entry per file (passing files included).

    >>> doc = json.loads(check_json([FileOutcome("b.dyn", "failed", (("W", "got 1 N"),))]))
    >>> doc["files"][0]["problems"]
    [{'check': 'W', 'detail': 'got 1 N'}]
    """
    files = [
        {
            "file": o.file,
            "status": o.status,
            "problems": [{"check": name, "detail": detail} for name, detail in o.problems],
        }
        for o in outcomes
    ]
    return json.dumps({"summary": summary(outcomes), "files": files}, indent=2)


def check_junit(outcomes: Sequence[FileOutcome]) -> str:
    """JUnit XML: one testsuite ``dynsolve check``, one testcase per file.

    >>> xml = check_junit([FileOutcome("a.dyn", "malformed", (("input", "bad <unit>"),))])
    >>> 'errors="1"' in xml and "bad &lt;unit&gt;" in xml
    True
    """
    counts = summary(outcomes)
    suite = ElementTree.Element(
        "testsuite",
        name="dynsolve check",
        tests=str(len(outcomes)),
        failures=str(counts["failed"]),
        errors=str(counts["malformed"]),
    )
    for outcome in outcomes:
        case = ElementTree.SubElement(
            suite, "testcase", classname="dynsolve.check", name=outcome.file
        )
        if outcome.status == "passed":
            continue
        tag = "failure" if outcome.status == "failed" else "error"
        text = "\n".join(f"{name}: {detail}" for name, detail in outcome.problems)
        first = outcome.problems[0][1] if outcome.problems else outcome.status
        element = ElementTree.SubElement(case, tag, message=first)
        element.text = text
    body = ElementTree.tostring(suite, encoding="unicode")
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + body + "\n"
