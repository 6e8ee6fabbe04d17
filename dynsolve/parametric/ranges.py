"""Read a sweep's ranges (``m_b=10..30 kg``, ``step``, ``±10%``) into the points to evaluate.

A range is written in the ``vary:`` grammar (:mod:`dynsolve.spec.vary_line`), its step
optional: without one, ``points`` values are spread evenly from end to end. Its unit is
checked against the given's dimension (:func:`dynsolve.grade.vary.variation`). Errors point
into the range's own text (``<range 1>:1:COLUMN``).

>>> from dynsolve.spec.parser import parse_spec
>>> text = "given:\\n  m = 2 kg\\n  F = 10 N\\nequations:\\n  F = m*a\\nfind: a"
>>> spec = parse_spec(text, "p.dyn")
>>> axis = parse_range("m=1..3 kg", 1, spec, points=5)
>>> axis.name, axis.unit, axis.values.tolist()
('m', 'kg', [1.0, 1.5, 2.0, 2.5, 3.0])
>>> parse_range("m = 1000..3000 g step 500", 1, spec).values.tolist()
[1000.0, 1500.0, 2000.0, 2500.0, 3000.0]
"""

from __future__ import annotations

import difflib
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from dynsolve.errors import Position, SpecError
from dynsolve.grade.vary import variation
from dynsolve.quantities import unit_info
from dynsolve.spec.ast import Given, Spec
from dynsolve.spec.vary_line import parse_vary_line
from dynsolve.units import to_base

DEFAULT_POINTS = 51  # points of a range written without a step
MAX_POINTS = 1_000_000  # points of a whole sweep (every range's points multiplied)


@dataclass(frozen=True)
class Axis:
    """One swept given: its values in ``unit`` (as written in its range, or the spec's unit
    for values from Python): a range's values, or for values from Python one per point."""

    name: str
    unit: str  # pint-parsable text, "" for a pure number
    values: np.ndarray
    factor: float  # the size of ``unit`` in the problem's base units (SI or FPS)


def label(index: int) -> str:
    """The file name errors in the ``index``-th range (from 1) point into."""
    return f"<range {index}>"


def parse_range(text: str, index: int, spec: Spec, points: int | None = None) -> Axis:
    """The ``index``-th range (from 1) of a sweep of ``spec``; ``points`` spreads a range
    written without a step (:data:`DEFAULT_POINTS` when None), and may not go with one."""
    file = label(index)
    stmt = parse_vary_line(text, file, 1, 0, step_optional=True)
    where = Position(file, 1, stmt.column or 1)
    if stmt.kind == "allow":
        raise SpecError(
            "'allow changes' is a line of a vary: section, not a range",
            where,
            hint="write NAME=LOW..HIGH UNIT, e.g. 'm_b=10..30 kg'",
        )
    given = valued_given(spec, stmt.name, where)
    resolved = variation(stmt, given, spec, file)
    if stmt.kind == "percent" and "sigfig" in text:
        raise SpecError(
            "'sigfig' rounds the values a vary: section draws; a sweep's points are evenly spaced",
            where,
            hint=f"leave it out: '{stmt.name}=±{float(stmt.percent * 100):g}%'",
        )
    if resolved.step and points is not None:
        raise SpecError(
            f"the range of '{stmt.name}' has a step and --points is given too",
            where,
            hint="give one of them",
        )
    if resolved.high == resolved.low or (resolved.step and resolved.count < 2):
        raise SpecError(
            f"the range of '{stmt.name}' is empty: it holds a single value",
            where,
            hint="give two different ends and a step smaller than the span",
        )
    if resolved.step:
        steps = range(resolved.count)  # exact: 0.1 steps land on 0.3, not 0.30000000000000004
        values = np.asarray([float(resolved.low + k * resolved.step) for k in steps])
    else:
        values = np.linspace(float(resolved.low), float(resolved.high), points or DEFAULT_POINTS)
    return Axis(stmt.name, resolved.unit, values, unit_factor(resolved.unit, spec))


def valued_given(spec: Spec, name: str, where: Position | None) -> Given:
    """The given ``name`` of ``spec``, which must have a value (a symbolic one cannot vary)."""
    givens = {g.name: g for g in spec.givens}
    given = givens.get(name)
    if given is None:
        close = difflib.get_close_matches(name, list(givens), n=1)
        names = ", ".join(g.name for g in spec.givens if g.quantity is not None)
        raise SpecError(
            f"'{name}' is not a given of {spec.file}",
            where,
            hint=f"did you mean '{close[0]}'?" if close else f"the givens are: {names}",
        )
    if given.quantity is None:
        raise SpecError(
            f"'{name}' has no value in {spec.file} (a symbolic given)",
            where,
            hint="give it a value in the spec to sweep it",
        )
    return given


def unit_factor(unit: str, spec: Spec) -> float:
    """The size of ``unit`` in ``spec``'s base units (``g`` in an SI problem: 0.001)."""
    return float(to_base(Fraction(1), unit_info(unit), spec.system))


def grid(axes: Sequence[Axis]) -> tuple[tuple[np.ndarray, ...], tuple[int, ...]]:
    """Every combination of the axes' values (the first axis outermost), one flat array per
    axis, and the grid's shape; a :class:`SpecError` past :data:`MAX_POINTS` points.

    >>> a = Axis("a", "", np.array([1.0, 2.0]), 1.0)
    >>> b = Axis("b", "", np.array([10.0, 20.0, 30.0]), 1.0)
    >>> columns, shape = grid([a, b])
    >>> columns[0].tolist(), columns[1].tolist(), shape
    ([1.0, 1.0, 1.0, 2.0, 2.0, 2.0], [10.0, 20.0, 30.0, 10.0, 20.0, 30.0], (2, 3))
    """
    shape = tuple(len(axis.values) for axis in axes)
    total = 1
    for size in shape:
        total *= size
    if total > MAX_POINTS:
        sizes = " × ".join(str(size) for size in shape)
        raise SpecError(
            f"the sweep has {sizes} = {total} points; the limit is {MAX_POINTS}",
            Position(label(1), 1, 1),
            hint="use fewer --points or larger steps",
        )
    meshes = np.meshgrid(*(axis.values for axis in axes), indexing="ij")
    return tuple(mesh.ravel() for mesh in meshes), shape


def axis_of_values(name: str, values: object, unit: str | None, spec: Spec) -> Axis:
    """A swept given from values passed in Python: numbers in ``unit`` (pint's text, as
    ``str(quantity.units)``), or, with ``unit`` None, in the unit the spec gives it in.
    The values are flattened (:class:`Axis` holds one per point).

    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("given:\\n  m = 2 kg\\nequations:\\n  W = m*g\\nfind: W", "p.dyn")
    >>> axis_of_values("m", [500.0, 1500.0], "gram", spec).values.tolist()
    [0.5, 1.5]
    >>> axis_of_values("m", [1, 3], None, spec).unit
    'kg'
    """
    import pint

    from dynsolve.errors import UnitError
    from dynsolve.units import registry

    given = valued_given(spec, name, None)
    assert given.quantity is not None
    written = given.quantity.unit.text if given.quantity.unit else ""
    array = np.asarray(values, dtype=float).ravel()
    if array.size == 0:
        raise SpecError(f"the values of '{name}' are empty", hint="pass at least one value")
    if not np.all(np.isfinite(array)):
        raise SpecError(f"the values of '{name}' are not all finite", hint="drop NaN and inf")
    if unit is not None:
        ureg = registry()
        try:
            factor = ureg.Quantity(1.0, unit).to(written or "dimensionless").magnitude
        except (pint.errors.DimensionalityError, pint.errors.UndefinedUnitError) as error:
            raise UnitError(
                f"'{name}' is given in {written or 'no unit'}; its values are in {unit} "
                f"({type(error).__name__})",
                hint=f"pass a quantity in a unit of the same dimension, e.g. '{written}'",
            ) from None
        array = array * float(factor)
    return Axis(name, written, array, unit_factor(written, spec))
