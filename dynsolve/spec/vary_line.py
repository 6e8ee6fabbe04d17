"""Parse one line of a ``vary:`` section into a :class:`~dynsolve.spec.ast.VaryStmt`.

Two forms, both bounded and never evaluated: a range with a step
(``m = 40..60 kg step 5``) and a relative spread rounded to significant figures
(``k = ±10% sigfig 3``, also written ``+-10%``; ``sigfig`` defaults to 3).

>>> stmt = parse_vary_line("m = 40..60 kg step 5", "p.dyn", 7, 2)
>>> stmt.kind, stmt.low, stmt.high, stmt.step, stmt.unit.text, stmt.column
('range', Fraction(40, 1), Fraction(60, 1), Fraction(5, 1), 'kg', 3)
>>> stmt = parse_vary_line("k = +-10% sigfig 2", "p.dyn", 8, 2)
>>> stmt.kind, stmt.percent, stmt.sigfig
('percent', Fraction(1, 10), 2)
"""

from __future__ import annotations

import re
from fractions import Fraction

from dynsolve.errors import Position, SpecError
from dynsolve.spec.ast import VaryStmt

MAX_DIGITS = 40  # as for numbers in the rest of the spec
MAX_EXPONENT = 100
MAX_VALUES = 100_000  # values one range may hold: no 10^9-step ranges
MAX_SIGFIG = 10
MAX_PERCENT = Fraction(99)  # a spread of 100 % or more would reach zero

_NUMBER = r"(?:\d+(?:\.\d+)?|\.\d+)(?:[eE][+-]?\d+)?"
_NAME = re.compile(r"\s*([A-Za-z][A-Za-z0-9_]*)\s*=\s*")
_RANGE = re.compile(
    rf"(?P<low>-?{_NUMBER})\s*\.\.\s*(?P<high>-?{_NUMBER})(?P<unit>.*?)"
    rf"\s+step\s+(?P<step>{_NUMBER})\s*$"
)
_SPAN = re.compile(  # a range whose step may be left out (a sweep: ``--points`` sets it)
    rf"(?P<low>-?{_NUMBER})\s*\.\.\s*(?P<high>-?{_NUMBER})(?P<unit>.*?)"
    rf"(?:\s+step\s+(?P<step>{_NUMBER}))?\s*$"
)
_PERCENT = re.compile(
    rf"(?:\+-|±)\s*(?P<percent>{_NUMBER})\s*%\s*(?:sigfig\s+(?P<sigfig>\d+))?\s*$"
)
_ALLOW = re.compile(r"\s*allow\s+changes\s*")
_FORMS = "'NAME = LOW..HIGH UNIT step STEP' or 'NAME = ±P% sigfig N'"


def parse_vary_line(
    text: str, file: str, line: int, offset: int, step_optional: bool = False
) -> VaryStmt:
    """Parse ``text`` (a ``vary`` line without its comment); ``offset`` columns precede it.
    With ``step_optional`` a range may leave out its step (``step`` is then 0).

    >>> parse_vary_line("allow changes", "p.dyn", 9, 2).kind
    'allow'
    >>> parse_vary_line("m = 10..30 kg", "<range>", 1, 0, step_optional=True).step
    Fraction(0, 1)
    """
    if _ALLOW.fullmatch(text):
        return VaryStmt("", "allow", text=text.strip(), line=line, column=offset + 1)
    head = _NAME.match(text)
    if head is None:
        raise SpecError(
            "a vary line starts with a given's name and '='",
            Position(file, line, offset + 1),
            hint=f"write {_FORMS}",
        )
    name, start = head.group(1), head.end()
    rest = text[start:]
    column = offset + head.start(1) + 1
    ranged = (_SPAN if step_optional else _RANGE).match(rest)
    if ranged is not None:
        return _range(name, ranged, text, file, line, offset + start, column)
    spread = _PERCENT.match(rest)
    if spread is not None:
        return _percent(name, spread, text, file, line, offset + start, column)
    raise SpecError(
        f"cannot read the variation of '{name}'",
        Position(file, line, offset + start + 1),
        hint=f"write {_FORMS}, e.g. 'm = 40..60 kg step 5' or 'k = ±10% sigfig 3'",
    )


def _number(text: str, file: str, line: int, column: int) -> Fraction:
    mantissa, _, exponent = text.lower().lstrip("-").partition("e")
    where = Position(file, line, column)
    if len(mantissa.replace(".", "").lstrip("0")) > MAX_DIGITS:
        raise SpecError(f"number has more than {MAX_DIGITS} digits", where, "round it")
    if exponent and abs(int(exponent)) > MAX_EXPONENT:
        raise SpecError(
            f"exponent {exponent} is out of range (±{MAX_EXPONENT})",
            where,
            hint="choose units that keep numbers moderate",
        )
    return Fraction(text)


def _range(
    name: str, match: re.Match[str], text: str, file: str, line: int, base: int, column: int
) -> VaryStmt:
    def at(group: str) -> int:
        return base + match.start(group) + 1

    low = _number(match.group("low"), file, line, at("low"))
    high = _number(match.group("high"), file, line, at("high"))
    stepped = match.group("step") is not None
    step = _number(match.group("step"), file, line, at("step")) if stepped else Fraction(0)
    if high < low:
        raise SpecError(
            f"the range of '{name}' runs backwards ({match.group('low')} > {match.group('high')})",
            Position(file, line, at("low")),
            hint="write the smaller value first",
        )
    if stepped and step <= 0:
        raise SpecError(
            "the step of a range must be positive",
            Position(file, line, at("step")),
            hint="e.g. 'step 5'",
        )
    count = (high - low) // step + 1 if stepped else 0
    if count > MAX_VALUES:
        raise SpecError(
            f"the range of '{name}' holds {count} values; the limit is {MAX_VALUES}",
            Position(file, line, at("step")),
            hint="use a larger step",
        )
    unit = None
    unit_text = match.group("unit").strip()
    if unit_text:
        from dynsolve.spec.parser import parse_unit_at

        unit_column = base + match.start("unit") + 1
        unit_column += len(match.group("unit")) - len(match.group("unit").lstrip())
        unit = parse_unit_at(unit_text, file, line, unit_column - 1)
    return VaryStmt(
        name, "range", low=low, high=high, step=step, unit=unit, text=text.strip(),
        line=line, column=column,
    )  # fmt: skip


def _percent(
    name: str, match: re.Match[str], text: str, file: str, line: int, base: int, column: int
) -> VaryStmt:
    where = base + match.start("percent") + 1
    percent = _number(match.group("percent"), file, line, where)
    if not 0 < percent <= MAX_PERCENT:
        raise SpecError(
            f"a spread of {match.group('percent')}% is out of range (above 0, at most "
            f"{MAX_PERCENT}%)",
            Position(file, line, where),
            hint="e.g. '±10%'",
        )
    sigfig = 3
    if match.group("sigfig") is not None:
        figures = match.group("sigfig")
        if len(figures) > 3 or not 1 <= int(figures) <= MAX_SIGFIG:
            raise SpecError(
                f"sigfig {figures} is out of range (1 to {MAX_SIGFIG})",
                Position(file, line, base + match.start("sigfig") + 1),
                hint="e.g. 'sigfig 3'",
            )
        sigfig = int(figures)
    return VaryStmt(
        name, "percent", percent=percent / 100, sigfig=sigfig, text=text.strip(),
        line=line, column=column,
    )  # fmt: skip
