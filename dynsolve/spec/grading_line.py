"""Parse one line of a spec's ``grading:`` section into a :class:`GradingRule`.

A line is ``[PART] KEY NUMBER [UNIT | %]``: ``rtol 1%``, ``atol 0.01 m/s``, ``sigfig 3``,
``decdig 2``, ``alpha weight 2``, ``partial 50%``; or ``[PART] FLAG``: ``signed`` (a bare
number is positive, so a clockwise part needs its sign or word) or ``magnitude`` (a bare
positive number is a magnitude, the default). The number is read by the same pattern as
the grammar's NUMBER (never evaluated); a unit goes through the unit grammar.

>>> rule = parse_grading_line("alpha rtol 2%", "p.dyn", 30, 2)
>>> rule.part, rule.key, rule.value
('alpha', 'rtol', Fraction(1, 50))
>>> flag = parse_grading_line("a signed", "p.dyn", 31, 2)
>>> flag.part, flag.key, flag.value
('a', 'signed', Fraction(1, 1))
"""

from __future__ import annotations

import re
from fractions import Fraction

from dynsolve.errors import Position, SpecError
from dynsolve.spec.ast import GradingRule

KEYS = ("rtol", "atol", "sigfig", "decdig", "weight", "partial")
FLAGS = {"signed": Fraction(1), "magnitude": Fraction(0)}  # the rule 'signed', on or off
PERCENT_KEYS = ("rtol", "partial")
INTEGER_KEYS = ("sigfig", "decdig")
MAX_DIGITS = 15  # a float holds about 15 significant figures
_LINE = re.compile(
    r"^(?:(?P<part>[A-Za-z][A-Za-z0-9_]*)\s+)?(?P<key>[A-Za-z]+)\s+"
    r"(?P<number>(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?)\s*(?P<rest>.*)$"
)
_FLAG = re.compile(r"^(?:(?P<part>[A-Za-z][A-Za-z0-9_]*)\s+)?(?P<flag>signed|magnitude)\s*$")
_HINT = "e.g. 'rtol 1%', 'atol 0.01 m/s', 'sigfig 3', 'alpha weight 2', 'partial 50%', 'signed'"


def parse_grading_line(text: str, file: str, line: int, offset: int) -> GradingRule:
    """One ``grading:`` line; errors point at ``file:line:column``."""
    from dynsolve.spec.parser import parse_unit_at

    flag = _FLAG.match(text)
    if flag is not None:
        column = offset + 1 + flag.start("flag")
        value = FLAGS[flag["flag"]]
        return GradingRule(flag["part"] or "", "signed", value, flag["flag"], None, line, column)
    match = _LINE.match(text)
    if match is None:
        raise SpecError("cannot read this grading rule", Position(file, line, offset + 1), _HINT)
    key = match["key"].lower()
    column = offset + 1 + match.start("key")
    if key not in KEYS:
        raise SpecError(
            f"unknown grading rule '{match['key']}'",
            Position(file, line, column),
            f"the rules are {', '.join((*KEYS, *FLAGS))}",
        )
    value = Fraction(match["number"])
    rest = match["rest"].strip()
    unit = None
    if rest == "%":
        if key not in PERCENT_KEYS:
            raise SpecError(
                f"'{key}' does not take a percentage",
                Position(file, line, offset + 1 + match.start("rest")),
                _HINT,
            )
        value /= 100
    elif rest:
        if key != "atol":
            raise SpecError(
                f"unexpected '{rest}' after {key} {match['number']}",
                Position(file, line, offset + 1 + match.start("rest")),
                "only atol takes a unit; rtol and partial take a percentage",
            )
        from dynsolve.quantities import resolve_unit

        unit = parse_unit_at(rest, file, line, offset + match.start("rest"))
        resolve_unit(unit, file)  # an unknown unit stops here, pointed at
    elif key in PERCENT_KEYS:
        raise SpecError(
            f"write {key} as a percentage",
            Position(file, line, offset + 1 + match.end("number")),
            f"e.g. '{key} {match['number']}%'",
        )
    _check_range(
        key, value, match["number"], Position(file, line, offset + 1 + match.start("number"))
    )
    return GradingRule(match["part"] or "", key, value, match["number"], unit, line, column)


def _check_range(key: str, value: Fraction, text: str, where: Position) -> None:
    if key in INTEGER_KEYS and (value.denominator != 1 or not 1 <= value <= MAX_DIGITS):
        raise SpecError(f"{key} {text}: give a whole number of digits", where, f"1 to {MAX_DIGITS}")
    if key == "partial" and value > 1:
        raise SpecError(f"partial {text}%: more than full credit", where, "0% to 100%")
    if key == "weight" and value > 1000:
        raise SpecError(f"weight {text} is too large", where, "a weight from 0 to 1000")
