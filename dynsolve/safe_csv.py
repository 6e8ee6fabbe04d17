"""CSV text a spreadsheet opens without running anything: every cell escaped (OWASP).

A spreadsheet treats a cell that begins with ``=``, ``+``, ``-``, ``@``, a tab or a
carriage return as a formula (``=HYPERLINK(…)``, ``+cmd|' /C calc'!A0``). As the OWASP
"CSV Injection" page recommends, such a cell gets a leading single quote, which makes it
text; leading spaces do not hide the trigger (`` =1+1`` is escaped too). A plain number
(``-4.52``, ``+1e-3``, ``-inf``) is left as it is, so numbers stay numbers. Quotes,
commas and line breaks inside a cell are quoted by the ``csv`` module.
:func:`unescape_cell` undoes the quote, for files dynsolve reads back (a variants file).

>>> csv_text([["student", "a"], ["=1+1", "-4.52"], ["s2", "-4.52 m/s^2"]]).splitlines()
['student,a', "'=1+1,-4.52", "s2,'-4.52 m/s^2"]
"""

from __future__ import annotations

import csv
import io
import re
from collections.abc import Iterable, Sequence

TRIGGERS = ("=", "+", "-", "@", "\t", "\r")
_FIRST = frozenset((*TRIGGERS, " "))  # a first character that needs a closer look
_NUMBER = re.compile(r"[+-]?(?:(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?|inf|nan)", re.IGNORECASE)


def escape_cell(cell: object) -> str:
    """``cell`` as text a spreadsheet shows and never evaluates.

    >>> [escape_cell(c) for c in ("=HYPERLINK(\\"x\\")", "@SUM(A1)", "-cmd|x", -4.52, "s01")]
    ['\\'=HYPERLINK("x")', "'@SUM(A1)", "'-cmd|x", '-4.52', 's01']
    >>> escape_cell("\\t=1+1"), escape_cell("  +1+1")
    ("'\\t=1+1", "'  +1+1")
    """
    text = cell if isinstance(cell, str) else str(cell)
    if not text or text[0] not in _FIRST:  # the common case: a letter or a digit first
        return text
    stripped = text.lstrip(" ")
    if not stripped or stripped[0] not in TRIGGERS or _NUMBER.fullmatch(stripped):
        return text
    return "'" + text


def unescape_cell(text: str) -> str:
    """A cell read back: the quote :func:`escape_cell` added is removed.

    >>> unescape_cell("'=1+1"), unescape_cell("'-5 m"), unescape_cell("'quoted'")
    ('=1+1', '-5 m', "'quoted'")
    """
    if text.startswith("'") and text[1:].lstrip(" ")[:1] in TRIGGERS:
        return text[1:]
    return text


def csv_text(rows: Iterable[Sequence[object]]) -> str:
    """The rows as CSV, every cell escaped with :func:`escape_cell`. Lines end in CRLF
    (RFC 4180): the writer quotes a cell holding a character of the line ending, so a
    carriage return inside a cell is quoted too (with ``\\n`` endings it would be written
    bare and end the row early in a spreadsheet).

    >>> csv_text([["a\\rb"]])
    '"a\\rb"\\r\\n'
    """
    buffer = io.StringIO(newline="")
    writer = csv.writer(buffer, lineterminator="\r\n")
    for row in rows:
        writer.writerow([escape_cell(cell) for cell in row])
    return buffer.getvalue()
