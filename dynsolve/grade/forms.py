"""Rewrite an answer as students type it into the form the answers grammar reads.

Only spelling changes here, never arithmetic: Unicode minus and superscripts, ``m/s2``,
``m s^-2``, a trailing period, ``1.06 x 10^2``, a decimal comma, and direction phrases
(``clockwise``, ``to the left``, ``downwards``) made the grammar's words (``cw``,
``left``, ``down``). A number whose comma or point could be a thousands separator is
refused with the reason, never guessed. The result still goes through the grammar.

>>> normalise("4,52 m·s⁻² downwards", decimal_comma=True)
Written(text='4.52 m·s^-2 down', plus=False)
>>> normalise("−11.3 rad/s2.").text
'-11.3 rad/s^2'
>>> normalise("1,060 N").text  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
ValueError: '1,060' could be 1060 or 1.060 (a thousands separator or a ...): write 1060 or 1.060
>>> normalise("5.08 +- 0.01 m/s^2").text
Traceback (most recent call last):
...
ValueError: '5.08 +- 0.01 m/s^2' has a tolerance: give one value
"""

from __future__ import annotations

import re
from dataclasses import dataclass

# Direction phrases, longest first; each maps to the grammar's word.
DIRECTION_WORDS: dict[str, str] = {
    "counterclockwise": "ccw",
    "counter-clockwise": "ccw",
    "counter clockwise": "ccw",
    "anticlockwise": "ccw",
    "anti-clockwise": "ccw",
    "anti clockwise": "ccw",
    "clockwise": "cw",
    "ccw": "ccw",
    "cw": "cw",
    "downwards": "down",
    "downward": "down",
    "down": "down",
    "upwards": "up",
    "upward": "up",
    "up": "up",
    "to the left": "left",
    "leftwards": "left",
    "leftward": "left",
    "left": "left",
    "to the right": "right",
    "rightwards": "right",
    "rightward": "right",
    "right": "right",
}
_PHRASES = "|".join(re.escape(p).replace(r"\ ", r"\s+") for p in DIRECTION_WORDS)
_DIRECTION = re.compile(rf"(?<![A-Za-z_-])({_PHRASES})\s*$", re.IGNORECASE)
_SUPERSCRIPTS = {"⁰": "0", "¹": "1", "²": "2", "³": "3", "⁴": "4", "⁵": "5"}
_SUPERSCRIPTS |= {"⁶": "6", "⁷": "7", "⁸": "8", "⁹": "9", "⁻": "-"}
_SUPER = re.compile("[⁻" + "".join(_SUPERSCRIPTS) + "]+")
_CHARACTERS = str.maketrans(
    {
        "\u2212": "-",  # minus sign
        "\u2013": "-",  # en dash, as word processors turn a hyphen
        "\u00a0": " ",
        "\u2009": " ",
        "\u202f": " ",
        "\u2007": " ",
        "\u22c5": "·",  # dot operator
        "\u2219": "·",  # bullet operator
        "\u00d7": "x",  # multiplication sign (only before a power of ten)
    }
)
_NUMBER = re.compile(r"^([-+]?)\s*(\d[\d,.]*|[.,]\d+)(?:\s*[eE]\s*([-+]?\d+))?")
_TIMES_TEN = re.compile(r"^\s*[x*·]\s*10\s*\^\s*\(?\s*([-+]?\d+)\s*\)?")
_GLUED_POWER = re.compile(r"(?<![A-Za-z0-9_^.])([A-Za-z]+)(\d+)(?![\d.])")
_TOLERANCE = re.compile(r"±|\+\s*/?\s*-")  # 4.52 ± 0.01, 4.52 +- 0.01, 4.52 +/- 0.01
_JUXTAPOSED = re.compile(r"(?<=[A-Za-z0-9)])\s+(?=[A-Za-z(])")


@dataclass(frozen=True)
class Written:
    """An answer in the grammar's form; ``plus`` when the student wrote a leading ``+``."""

    text: str
    plus: bool


def normalise(text: str, decimal_comma: bool = False) -> Written:
    """``text`` in the answers grammar's spelling; ``ValueError`` says why it cannot be.

    ``decimal_comma``: the file writes decimals with a comma (``4,52``), so ``1,060`` is
    1.060 and ``1.060`` is ambiguous; otherwise the reverse."""
    text = text.translate(_CHARACTERS).strip()
    text = _SUPER.sub(lambda m: "^" + "".join(_SUPERSCRIPTS[c] for c in m[0]), text)
    text = text.replace("°", " deg ").strip()
    if _TOLERANCE.search(text, 1):
        raise ValueError(f"'{text}' has a tolerance: give one value")
    if text.endswith(".") and len(text) > 1:
        text = text[:-1].rstrip()
    direction = ""
    found = _DIRECTION.search(text)
    if found and found.start() > 0:
        direction = DIRECTION_WORDS[re.sub(r"\s+", " ", found[1].lower())]
        text = text[: found.start()].rstrip()
    number = _NUMBER.match(text)
    if number is None:
        return Written(" ".join(p for p in (text, direction) if p), False)
    sign, digits, exponent = number[1], _decimal(number[2], decimal_comma), number[3]
    rest = text[number.end() :]
    power = _TIMES_TEN.match(rest)
    if power and exponent is None:
        exponent, rest = power[1], rest[power.end() :]
    value = f"{'-' if sign == '-' else ''}{digits}" + (f"e{exponent}" if exponent else "")
    unit = normalise_unit(rest.strip())
    written = " ".join(p for p in (value, unit, direction) if p)
    return Written(written, sign == "+")


def _decimal(digits: str, decimal_comma: bool) -> str:
    """The number with a decimal point, or ``ValueError`` for a separator that is unclear."""
    mark, other = (",", ".") if decimal_comma else (".", ",")
    if mark in digits and other in digits:
        raise ValueError(f"'{digits}' has a thousands separator: write it without one")
    if other in digits:
        if re.fullmatch(r"[1-9]\d{0,2}(?:[.,]\d{3})+", digits):
            plain, alternative = digits.replace(other, ""), digits.replace(other, ".")
            raise ValueError(
                f"'{digits}' could be {plain} or {alternative} (a thousands separator or a "
                f"decimal {'point' if other == '.' else 'comma'}): write {plain} or {alternative}"
            )
        if digits.count(other) > 1:
            raise ValueError(f"'{digits}' has a thousands separator: write it without one")
        digits = digits.replace(other, ".")
    elif mark == ",":
        if digits.count(",") > 1:
            raise ValueError(f"'{digits}' has more than one decimal comma")
        digits = digits.replace(",", ".")
    return digits


def normalise_unit(text: str) -> str:
    """A unit as typed (``m/s2``, ``m s^-2``, ``s²``) in the grammar's spelling.

    >>> normalise_unit("m/s2"), normalise_unit("kg m²")
    ('m/s^2', 'kg·m^2')
    """
    if not text:
        return ""
    text = _SUPER.sub(lambda m: "^" + "".join(_SUPERSCRIPTS[c] for c in m[0]), text)
    if text[0].isdigit() and not text.startswith("1/"):
        raise ValueError(f"a number inside the unit ('{text}'): write the number without spaces")
    text = _GLUED_POWER.sub(r"\1^\2", text)
    return _JUXTAPOSED.sub("·", text)
