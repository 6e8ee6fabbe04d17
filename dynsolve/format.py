"""Number and unit formatting shared by the renderers: 3 significant figures, pretty units.

>>> sig(11.2919), sig(-0.000123456), sig(144.715), sig(0.0), sig(float("inf"))
('11.3', '-1.23e-4', '145', '0', 'not a finite number')
>>> pretty_unit("kg*m^2/s^2"), latex_unit("m/s^2")
('kg·m²/s²', '\\\\mathrm{m/s^{2}}')
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence

NOT_FINITE = "not a finite number"
_POWER = re.compile(r"\^(?:\((-?\d+/\d+)\)|(-?\d+))")
_SUPERSCRIPT = str.maketrans("0123456789-/()", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻ᐟ⁽⁾")


def sig(value: float, figures: int = 3) -> str:
    """``value`` to ``figures`` significant figures, plain or in e-notation when extreme."""
    if not math.isfinite(value):
        return NOT_FINITE  # never 'inf' or 'nan': such an answer is also a failed check
    if value == 0:
        return "0"
    exponent = math.floor(math.log10(abs(value)))
    if -3 <= exponent < 6:
        decimals = max(figures - 1 - exponent, 0)
        text = f"{value:.{decimals}f}"
        return "0" if float(text) == 0 else text
    mantissa = f"{value / 10**exponent:.{figures - 1}f}"
    if abs(float(mantissa)) >= 10:  # rounding carried into a new digit
        exponent += 1
        mantissa = f"{value / 10**exponent:.{figures - 1}f}"
    return f"{mantissa}e{exponent}"


def pretty_unit(unit: str) -> str:
    """A unit for the terminal: ``*`` as ``·`` and powers as superscripts."""
    text = unit.replace("**", "^").replace("*", "·")
    return _POWER.sub(lambda m: (m.group(1) or m.group(2)).translate(_SUPERSCRIPT), text)


def latex_unit(unit: str) -> str:
    """A unit as upright LaTeX math: ``N*m`` → ``\\mathrm{N\\cdot m}``."""
    if not unit:
        return ""
    text = unit.replace("**", "^").replace("*", "\\cdot ")
    text = _POWER.sub(lambda m: "^{" + (m.group(1) or m.group(2)) + "}", text)
    return f"\\mathrm{{{text}}}"


def quantity(value: float, unit: str, figures: int = 3, trim: bool = False) -> str:
    """``value`` with its unit, for the terminal: ``-5.91 rad/s²``.

    ``trim`` drops trailing zeros (``60.00`` → ``60``), for values that are exact.

    >>> quantity(4.5156, "m/s^2"), quantity(60.0, "kg", 4, trim=True)
    ('4.52 m/s²', '60 kg')
    """
    shown = sig(value, figures)
    if shown == NOT_FINITE:
        return shown
    if trim and "." in shown and "e" not in shown:
        shown = shown.rstrip("0").rstrip(".")
    return f"{shown} {pretty_unit(unit)}" if unit else shown


def latex_number(value: float, figures: int = 3) -> str:
    """A number as LaTeX: ``1.23e-4`` → ``1.23\\times10^{-4}``.

    >>> latex_number(-0.000123456)
    '-1.23\\\\times 10^{-4}'
    >>> latex_number(float("inf"))
    '\\\\text{not a finite number}'
    """
    text = sig(value, figures)
    if text == NOT_FINITE:  # an infinite or undefined value: said, not split at its "e"s
        return f"\\text{{{NOT_FINITE}}}"
    if "e" in text:
        mantissa, exponent = text.split("e")
        return f"{mantissa}\\times 10^{{{exponent}}}"
    return text


def lines_phrase(lines: Sequence[int], dash: str = "–") -> str:
    """How a derivation step names its equations.

    >>> lines_phrase([10]), lines_phrase([11, 12, 13]), lines_phrase([4, 9], "--")
    ('Equation (line 10) gives', 'Equations (lines 11–13) give', 'Equations (lines 4, 9) give')
    """
    if not lines:
        return "The solver gives"
    if len(lines) == 1:
        return f"Equation (line {lines[0]}) gives"
    ordered = sorted(lines)
    if ordered == list(range(ordered[0], ordered[-1] + 1)):
        return f"Equations (lines {ordered[0]}{dash}{ordered[-1]}) give"
    return f"Equations (lines {', '.join(str(n) for n in lines)}) give"


def and_list(items: Sequence[str]) -> str:
    """``a, b and c``.

    >>> and_list(["T", "α", "a"])
    'T, α and a'
    """
    if len(items) <= 1:
        return "".join(items)
    return ", ".join(items[:-1]) + " and " + items[-1]
