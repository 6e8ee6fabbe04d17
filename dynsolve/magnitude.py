"""Bound the size of numbers before sympy builds them: interval estimates, in log10 where large.

Spec text can ask for numbers no machine holds (``10^10^10``, ``exp(exp(exp(exp(10))))``,
a squaring chain across equations). Before a power, product, sum or exponential is
built or evaluated, :func:`bound` estimates the interval its real value lies in from
the intervals of its parts (a symbol without a value is unbounded) and raises
:class:`OutOfRange` when the result could leave ``10^±MAX_LOG10``, when a power of
an unknown has a known exponent beyond ``±MAX_POWER``, or when an exact rational
would need more than ``MAX_EXACT_DIGITS`` digits. Every estimate is a few float
operations on logarithms, so the check itself never overflows or takes long.

>>> import sympy
>>> x = sympy.Symbol("x")
>>> bound(sympy.Integer(2) ** 10 * x, {}).high
inf
>>> try:
...     bound(sympy.Pow(10, sympy.Pow(10, 10, evaluate=False), evaluate=False), {})
... except OutOfRange as error:
...     print(error.message)
a value of about 1.0e10000000000 is out of range (limit 1e±300)
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import mpmath
import sympy

from dynsolve.errors import Position, SpecError

MAX_LOG10 = 300  # float64 holds 10^±308; the margin keeps products of two checked values finite
MAX_POWER = 64  # a power of an unknown: the parser's limit on a literal exponent
MAX_EXACT_DIGITS = 1000  # an exact rational's numerator plus denominator (Python prints 4300)
_LOG10_E = math.log10(math.e)
_HINT = "choose units that keep numbers moderate, or split the expression and check it"


class OutOfRange(SpecError):
    """A value would leave dynsolve's number range; ``located`` adds the spec file."""

    def __init__(self, message: str, line: int = 0, column: int = 0, hint: str = _HINT) -> None:
        super().__init__(message, Position("", line, column) if line else None, hint)
        self.line, self.column = line, column

    def at(self, line: int, column: int) -> OutOfRange:
        """This error placed at a line and column (the first placement wins)."""
        return self if self.line else OutOfRange(self.message, line, column, self.hint)

    def located(self, file: str, columns: Mapping[int, int] | None = None) -> SpecError:
        """The same error as a :class:`SpecError` naming ``file``; an error placed on a
        line only (column 0) takes its column from ``columns`` (line → column).

        >>> str(OutOfRange("too big", 3, 7, hint="h").located("a.dyn"))
        'a.dyn:3:7: too big (hint: h)'
        >>> str(OutOfRange("too big", 4, 0, hint="h").located("a.dyn", {4: 3}))
        'a.dyn:4:3: too big (hint: h)'
        """
        column = self.column or (columns or {}).get(self.line, 1)
        where = Position(file, self.line, column) if self.line else None
        return SpecError(self.message, where, self.hint)


@dataclass(frozen=True)
class Bound:
    """The real value lies in ``[low, high]``; ``digits`` sizes an exact rational (else 0)."""

    low: float
    high: float
    digits: float = 0.0

    @property
    def known(self) -> bool:
        return math.isfinite(self.low) and math.isfinite(self.high)

    @property
    def largest(self) -> float:
        return max(abs(self.low), abs(self.high))

    @property
    def smallest(self) -> float:
        """The least magnitude in the interval: 0 when it holds zero."""
        return 0.0 if self.low <= 0 <= self.high else min(abs(self.low), abs(self.high))


UNKNOWN = Bound(-math.inf, math.inf)
_ZERO = Bound(0.0, 0.0)


def value_bound(value: sympy.Expr | float | int) -> Bound:
    """The bound of a known value (a solved unknown or a given).

    >>> value_bound(sympy.Rational(1, 3))
    Bound(low=0.3333333333333333, high=0.3333333333333333, digits=2.0)
    """
    return bound(sympy.Integer(0) + value, {}) if not isinstance(value, float) else _float(value)


def bound(expr: sympy.Basic, known: Mapping[sympy.Symbol, Bound]) -> Bound:
    """The interval of ``expr`` with ``known`` symbols bounded; raises :class:`OutOfRange`.

    >>> bound(sympy.Integer(3) * sympy.pi, {})
    Bound(low=9.42477796076938, high=9.42477796076938, digits=0.0)
    """
    if isinstance(expr, sympy.Symbol):
        return known.get(expr, UNKNOWN)
    if isinstance(expr, sympy.Rational):
        return _rational(expr)
    if isinstance(expr, sympy.Float) and expr.is_finite and expr != 0:
        # its size by its logarithm: float() of 1e36683 is inf, and "10^inf" says nothing
        _check_log(float(mpmath.log10(abs(mpmath.mpf(expr._mpf_)))), True)
    if isinstance(expr, sympy.Number | sympy.NumberSymbol):
        return _float(float(expr)) if expr.is_finite else UNKNOWN
    if expr is sympy.I:
        return Bound(-1.0, 1.0)
    parts = [bound(a, known) for a in expr.args]
    if isinstance(expr, sympy.Add):
        return _sum(parts)
    if isinstance(expr, sympy.Mul):
        result = parts[0]
        for part in parts[1:]:
            result = _product(result, part)
        return result
    if isinstance(expr, sympy.Pow):
        return _power(parts[0], parts[1], expr.args[1])
    if isinstance(expr, sympy.exp):
        return _exponential(parts[0])
    if isinstance(expr, sympy.sin | sympy.cos):
        return Bound(-1.0, 1.0)
    if isinstance(expr, sympy.asin | sympy.acos | sympy.atan | sympy.atan2):
        return Bound(-math.pi, math.pi)
    if isinstance(expr, sympy.Abs):
        return Bound(parts[0].smallest, parts[0].largest)
    return UNKNOWN  # tan, log, functions of time...: their parts were still checked


def check_operation(
    function: str, args: list[sympy.Expr], known: Mapping[sympy.Symbol, Bound] | None = None
) -> None:
    """Raise :class:`OutOfRange` if ``function`` (``+ * ^`` or exp) of ``args`` would be too big.

    Called before the result is built, so ``10^10^10`` never reaches sympy;
    ``known`` bounds symbols whose values will be put in later.

    >>> check_operation("^", [sympy.Integer(2), sympy.Integer(64)])
    >>> try:
    ...     check_operation("exp", [sympy.Integer(1000)])
    ... except OutOfRange as error:
    ...     print(error.message)
    a value of about 2.0e434 is out of range (limit 1e±300)
    """
    parts = [bound(a, known or {}) for a in args]
    if function == "+":
        _sum(parts)
    elif function == "*":
        _product(parts[0], parts[1])
    elif function == "/":
        _product(parts[0], _power(parts[1], Bound(-1.0, -1.0), sympy.Integer(-1)))
    elif function == "^":
        _power(parts[0], parts[1], args[1])
    elif function == "exp":
        _exponential(parts[0])


def _float(value: float) -> Bound:
    _check_log(math.log10(abs(value)) if value else -math.inf, value != 0)
    return Bound(value, value)


def _rational(value: sympy.Rational) -> Bound:
    p, q = int(value.p), int(value.q)
    digits = _digits(p) + _digits(q)
    _check_digits(digits)
    if p == 0:
        return _ZERO
    log = math.log10(abs(p)) - math.log10(q)  # math.log10 takes ints of any size
    _check_log(log, True)
    number = p / q
    return Bound(number, number, digits)


def _digits(n: int) -> float:
    return float(len(str(abs(n)))) if abs(n) < 10**18 else abs(n).bit_length() * 0.30103


def _check_log(log: float, nonzero: bool) -> None:
    if log > MAX_LOG10:
        raise OutOfRange(f"a value of about {_shown(log)} is out of range (limit 1e±{MAX_LOG10})")
    if nonzero and log < -MAX_LOG10:
        raise OutOfRange(
            f"a value of about {_shown(log)} is too small (limit 1e±{MAX_LOG10}); "
            "it would round to 0"
        )


def _check_digits(digits: float) -> None:
    if digits > MAX_EXACT_DIGITS:
        raise OutOfRange(
            f"an exact value would need about {_shown(digits)} digits (limit {MAX_EXACT_DIGITS})",
            hint="round the numbers to fewer digits",
        )


def _shown(log: float) -> str:
    """A number given by its log10, in e-notation: 3.0 → ``1.0e3``."""
    if abs(log) >= 1e15:  # the mantissa is lost in the log's rounding
        return f"10^{log:.3g}"
    exponent = math.floor(log)
    return f"{10 ** (log - exponent):.1f}e{exponent}"


def _sum(parts: list[Bound]) -> Bound:
    if not all(p.known for p in parts):
        return UNKNOWN
    low, high = sum(p.low for p in parts), sum(p.high for p in parts)
    largest = max(abs(low), abs(high))
    _check_log(math.log10(largest) if largest else -math.inf, False)
    digits = sum(p.digits for p in parts) if all(p.digits for p in parts) else 0.0
    _check_digits(digits)
    return Bound(low, high, digits)


def _log_range(part: Bound) -> tuple[float, float]:
    """log10 of the least and largest magnitude (-inf for zero)."""
    smallest, largest = part.smallest, part.largest
    return (math.log10(smallest) if smallest else -math.inf), (
        math.log10(largest) if largest else -math.inf
    )


def _product(a: Bound, b: Bound) -> Bound:
    if a == _ZERO or b == _ZERO:
        return _ZERO
    if not (a.known and b.known):
        return UNKNOWN
    (a_low, a_high), (b_low, b_high) = _log_range(a), _log_range(b)
    _check_log(a_high + b_high, a_low + b_low > -math.inf)
    ends = [x * y for x in (a.low, a.high) for y in (b.low, b.high)]
    digits = a.digits + b.digits if a.digits and b.digits else 0.0
    _check_digits(digits)
    return Bound(min(ends), max(ends), digits)


def _power(base: Bound, exponent: Bound, exponent_expr: sympy.Basic) -> Bound:
    if not exponent.known:
        return UNKNOWN
    if not base.known:
        if exponent.largest > MAX_POWER:
            raise OutOfRange(
                f"exponent {_number(exponent)} is too large (limit ±{MAX_POWER})",
                hint="dynamics needs small powers; check the expression",
            )
        return UNKNOWN
    if base == _ZERO:
        return _ZERO if exponent.low > 0 else UNKNOWN
    log_low, log_high = _log_range(base)
    if log_low == -math.inf and exponent.low < 0:
        return UNKNOWN  # a negative power of (possibly) zero: sympy's zoo, checked later
    ends = [e * log for e in (exponent.low, exponent.high) for log in (log_low, log_high)]
    ends = [0.0 if math.isnan(x) else x for x in ends]  # 0 * -inf: the power is 1
    high, low = max(ends), min(ends)
    _check_log(high, log_low > -math.inf)
    digits = 0.0
    if base.digits and isinstance(exponent_expr, sympy.Integer):
        digits = abs(int(exponent_expr)) * base.digits
        _check_digits(digits)
    if base.low > 0:
        return Bound(10.0**low, 10.0**high, digits)
    return Bound(-(10.0**high), 10.0**high, digits)


def _exponential(argument: Bound) -> Bound:
    if not argument.known:
        return Bound(0.0, math.inf)
    low, high = argument.low * _LOG10_E, argument.high * _LOG10_E
    _check_log(high, True)
    return Bound(10.0**low, 10.0**high)


def _number(part: Bound) -> str:
    value = part.largest if part.high >= -part.low else -part.largest
    return f"{value:.3g}" if abs(value) >= 1e6 or value != int(value) else str(int(value))
