"""Errors as a reader sees them: where, the message and hint, the source line with a caret.

>>> from dynsolve.errors import ErrorReport
>>> report = ErrorReport("unknown unit 'kgs'", "did you mean 'kg'?", "d.dyn", 2, 9, "  m = 2 kgs")
>>> print(error_text(report))
error: d.dyn:2:9: unknown unit 'kgs' (hint: did you mean 'kg'?)
   |
 2 |   m = 2 kgs
   |         ^^^
"""

from __future__ import annotations

import json
import re
from collections.abc import Sequence

from dynsolve.errors import ErrorReport

_TOKEN = re.compile(r"[A-Za-z_α-ωΑ-Ω0-9.]+|\S")  # the word or symbol the caret underlines


def error_text(report: ErrorReport) -> str:
    """The error as compilers print it: ``file:line:column: message (hint: …)`` (the form
    editors jump to), then the source line with a caret under the column."""
    lines = [f"error: {report.text}"]
    if report.source and 0 < report.column <= len(report.source) + 1:
        number = str(report.line)
        pad = " " * len(number)
        source = report.source.expandtabs(1)
        token = _TOKEN.match(source, report.column - 1)
        width = len(token.group()) if token else 1
        lines += [
            f" {pad} |",
            f" {number} | {source}",
            f" {pad} | {' ' * (report.column - 1)}{'^' * width}",
        ]
    return "\n".join(lines)


def errors_json(reports: Sequence[ErrorReport]) -> str:
    """``{"error": first, "errors": [all]}``: what ``--format json`` prints for bad input.

    >>> data = json.loads(errors_json([ErrorReport("bad", "fix", "a.dyn", 1, 2)]))
    >>> data["error"], len(data["errors"])
    ({'file': 'a.dyn', 'line': 1, 'column': 2, 'message': 'bad', 'hint': 'fix'}, 1)
    """
    items = [report.as_dict() for report in reports]
    return json.dumps({"error": items[0] if items else None, "errors": items})
