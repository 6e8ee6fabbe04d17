"""CSV text whose every cell is safe from formula injection (OWASP's CSV injection rule).

A spreadsheet runs a cell that starts with ``=``, ``+``, ``-``, ``@``, a tab or a
carriage return as a formula; such a cell is written with a leading single quote, which
spreadsheets show as text. A plain negative number (``-4.52``, ``-1e3``) stays a number.

>>> safe_cell("=HYPERLINK(\\"http://x\\")"), safe_cell("-4.52"), safe_cell("s001")
('\\'=HYPERLINK("http://x")', '-4.52', 's001')
>>> csv_text([["student", "score"], ["@SUM(A1)", "-1.5e2"]]).splitlines()
['student,score', "'@SUM(A1),-1.5e2"]
"""

from __future__ import annotations

import csv
import io
import re
from collections.abc import Iterable, Sequence

TRIGGERS = ("=", "+", "-", "@", "\t", "\r")
_NEGATIVE_NUMBER = re.compile(r"-(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?")


def safe_cell(text: str) -> str:
    """``text`` with a leading ``'`` when a spreadsheet would read it as a formula."""
    if text.startswith(TRIGGERS) and not _NEGATIVE_NUMBER.fullmatch(text):
        return "'" + text
    return text


def unescape_cell(text: str) -> str:
    """The cell as it was before :func:`safe_cell` (reading back a file dynsolve wrote).

    >>> unescape_cell(safe_cell("=1+1")), unescape_cell("'quoted")
    ('=1+1', "'quoted")
    """
    if text.startswith("'") and text[1:].startswith(TRIGGERS):
        return text[1:]
    return text


def csv_text(rows: Iterable[Sequence[str]]) -> str:
    """The rows as CSV, every cell made safe. Lines end in CRLF (RFC 4180): Python's
    writer quotes a cell holding a character of the line ending, so a carriage return
    inside a cell is quoted too (with ``\\n`` endings it would be written bare and end
    the row early in a spreadsheet)."""
    out = io.StringIO(newline="")
    writer = csv.writer(out, lineterminator="\r\n")
    for row in rows:
        writer.writerow([safe_cell(cell) for cell in row])
    return out.getvalue()
