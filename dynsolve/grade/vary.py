"""Resolve a spec's ``vary:`` lines into value ranges and draw one student's values from them.

Drawing is reproducible: each (seed, student, attempt) seeds its own ``random.Random``
with the text ``"dynsolve-variants:{seed}:{student}:{attempt}"`` (Python seeds a string
through SHA-512, the same on every platform and run), so a student's variant depends only
on the seed and their id, not on the roster's order or size.

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec('''
... given:
...   m = 50 kg
...   k = 200 N/m
... vary:
...   m = 40..60 kg step 5
...   k = ±10% sigfig 2
... equations:
...   F = m*g
... find: F
... ''', "p.dyn")
>>> plan = vary_plan(spec)
>>> [v.values() for v in plan][0]
('40', '45', '50', '55', '60')
>>> plan[1].low, plan[1].high, plan[1].unit
(Fraction(180, 1), Fraction(220, 1), 'N/m')
>>> draw(plan, seed=1, student="s01") == draw(plan, seed=1, student="s01")
True
"""

from __future__ import annotations

import random
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction

from dynsolve.errors import Position, UnitError
from dynsolve.quantities import resolve_quantity, resolve_unit
from dynsolve.spec.ast import Given, Spec, VaryStmt
from dynsolve.units import Dim


@dataclass(frozen=True)
class Variation:
    """One given's allowed values: a stepped range, or a spread rounded to ``sigfig`` figures.

    ``low``, ``high`` and ``step`` are in ``unit`` (as written); ``step`` is zero for a spread.
    """

    name: str
    low: Fraction
    high: Fraction
    step: Fraction
    sigfig: int
    unit: str  # pint-parsable text, "" for a pure number
    dim: Dim
    line: int

    @property
    def count(self) -> int:
        """How many values a stepped range holds (0 for a spread)."""
        return int((self.high - self.low) // self.step) + 1 if self.step else 0

    def values(self) -> tuple[str, ...]:
        """Every value of a stepped range, as cell numbers (no unit).

        >>> Variation("x", Fraction(1), Fraction(2), Fraction(1, 4), 0, "m", Dim(1), 1).values()
        ('1', '1.25', '1.5', '1.75', '2')
        """
        return tuple(decimal_text(self.low + k * self.step) for k in range(self.count))

    def draw(self, rng: random.Random) -> str:
        """One value, as cell text with its unit (``45 kg``)."""
        if self.step:
            number = decimal_text(self.low + rng.randrange(self.count) * self.step)
        else:
            number = round_within(
                self.low + (self.high - self.low) * Fraction(rng.random()),
                self.sigfig,
                self.low,
                self.high,
            )
        return f"{number} {self.unit}".strip()


def vary_plan(spec: Spec) -> tuple[Variation, ...]:
    """Each ``vary`` line checked against its given (same dimension) and resolved."""
    givens = {g.name: g for g in spec.givens}
    return tuple(
        variation(stmt, givens[stmt.name], spec) for stmt in spec.vary if stmt.kind != "allow"
    )


def allows_changes(spec: Spec) -> bool:
    """Whether the ``vary`` section says ``allow changes`` (assumptions may differ)."""
    return any(stmt.kind == "allow" for stmt in spec.vary)


def variation(stmt: VaryStmt, given: Given, spec: Spec, file: str | None = None) -> Variation:
    """A ``vary`` line resolved against its ``given`` (a :class:`UnitError` when the range's
    unit is not of the given's dimension); ``file`` is where ``stmt`` was written (default:
    the spec), for the error's position."""
    assert given.quantity is not None  # the parser lets only valued givens vary
    file = file or spec.file
    _, dim = resolve_quantity(given.quantity, spec.system, spec.file)
    if stmt.kind == "percent":
        value = given.quantity.value
        spread = abs(value) * stmt.percent
        unit = given.quantity.unit.text if given.quantity.unit else ""
        if value == 0:
            raise UnitError(
                f"'{stmt.name}' is 0: a spread of ±{stmt.percent * 100}% of it is empty",
                Position(file, stmt.line, stmt.column),
                hint="give a range instead, e.g. 'x = -1..1 m step 0.5'",
            )
        return Variation(
            stmt.name, value - spread, value + spread, Fraction(0), stmt.sigfig, unit, dim,
            stmt.line,
        )  # fmt: skip
    unit_dim = resolve_unit(stmt.unit, file).dim if stmt.unit else Dim()
    if unit_dim != dim:
        column = stmt.unit.column if stmt.unit else stmt.column
        written = given.quantity.unit.text if given.quantity.unit else "no unit"
        raise UnitError(
            f"'{stmt.name}' is {dim.name} (given in {written}), but its range is {unit_dim.name}",
            Position(file, stmt.line, column),
            hint=f"write the range in a unit of {dim.name}, e.g. '{written}'",
        )
    return Variation(
        stmt.name, stmt.low, stmt.high, stmt.step, 0, stmt.unit.text if stmt.unit else "", dim,
        stmt.line,
    )  # fmt: skip


def rng_for(seed: int, student: str, attempt: int = 0) -> random.Random:
    """The generator for one student's ``attempt``-th draw (see the module docstring)."""
    return random.Random(f"dynsolve-variants:{seed}:{student}:{attempt}")


def draw(plan: Sequence[Variation], seed: int, student: str, attempt: int = 0) -> dict[str, str]:
    """One student's values: given name → cell text, in the order of the ``vary`` lines."""
    rng = rng_for(seed, student, attempt)
    return {v.name: v.draw(rng) for v in plan}


def round_within(value: Fraction, sigfig: int, low: Fraction, high: Fraction) -> str:
    """``value`` rounded to ``sigfig`` significant figures, kept inside ``[low, high]``
    (rounded inward by one unit in the last place when rounding crossed an end).

    >>> round_within(Fraction(10999, 100), 3, Fraction(90), Fraction(110))
    '110'
    >>> round_within(Fraction(1, 3), 2, Fraction(1, 3), Fraction(1, 2))
    '0.34'
    """
    if value == 0:
        return "0"
    exponent = _exponent(value) - sigfig + 1
    quantum = Fraction(10) ** exponent
    rounded = round(value / quantum) * quantum
    if rounded < low:
        rounded += quantum
    elif rounded > high:
        rounded -= quantum
    return decimal_text(rounded)


def _exponent(value: Fraction) -> int:
    """The power of ten of the leading digit of ``value`` (exact, no float log)."""
    size = abs(value)
    exponent = len(str(size.numerator)) - len(str(size.denominator))
    while Fraction(10) ** exponent > size:
        exponent -= 1
    while Fraction(10) ** (exponent + 1) <= size:
        exponent += 1
    return exponent


def decimal_text(value: Fraction) -> str:
    """A terminating decimal written plainly (``45``, ``0.125``, ``-2.5``), else 12 figures.

    >>> decimal_text(Fraction(90)), decimal_text(Fraction(-5, 2)), decimal_text(Fraction(1, 3))
    ('90', '-2.5', '0.333333333333')
    """
    number = Decimal(value.numerator) / Decimal(value.denominator)
    if Fraction(number) != value:
        number = Decimal(f"{float(value):.12g}")
    text = format(number.normalize(), "f")
    if len(text.replace("-", "").replace(".", "").strip("0")) > 15 or len(text) > 24:
        text = f"{float(value):.15g}"  # a very large or small number: e-notation
    return text


def cells_in_range(plan: Sequence[Variation], cells: Mapping[str, str]) -> bool:
    """Whether every drawn cell number lies in its variation's range (for tests and checks).

    >>> plan = (Variation("m", Fraction(40), Fraction(60), Fraction(5), 0, "kg", Dim(M=1), 1),)
    >>> cells_in_range(plan, {"m": "45 kg"}), cells_in_range(plan, {"m": "65 kg"})
    (True, False)
    """
    for variation in plan:
        number = Fraction(cells[variation.name].split()[0])
        if not variation.low <= number <= variation.high:
            return False
    return True
