"""Givens that are probably not what the writer meant, named in notes shown with the checks.

Two habits of hand calculation that a spec silently turns into wrong numbers: an angle
written as a bare number (``theta = 30`` read by ``sin`` as 30 rad) and a mass written
in pounds (``m = 40 lb``: lb is a force in dynsolve, as in the textbooks).

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec("given:\\n  theta = 30\\n  m = 40 lb\\nequations:\\n"
...                   "  F = m*sin(theta)\\nfind: F", "s.dyn")
>>> for name, detail in suspicious_notes(spec):
...     print(name, "|", detail.split(";")[0])
bare angle | theta = 30 (line 2) has no unit, so sin(theta) reads it as 30 rad (1719°)
lb is a force | m = 40 lb (line 3) is a force (pound-force) but its name is a mass's
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterator

from dynsolve.errors import DynsolveError
from dynsolve.quantities import resolve_unit
from dynsolve.spec.ast import Call, Direction, Given, Prop, Spec, children
from dynsolve.spec.parser import iter_names
from dynsolve.units import Dim

TRIG = frozenset({"sin", "cos", "tan", "cot", "sec", "csc"})
MASS_NAME = re.compile(r"^(m|M|mass)(_\w*|\d+)?$")
FORCE = Dim(1, 1, -2)


def suspicious_notes(spec: Spec) -> tuple[tuple[str, str], ...]:
    """A note for each bare number read as an angle, each force unit on a mass's name, and
    each name of the equations that looks like a misspelling of another."""
    typos = tuple(("misspelled name?", typo) for typo in likely_typos(spec))
    return (*_bare_angles(spec), *_pounds_as_mass(spec), *typos)


def likely_typos(spec: Spec) -> list[str]:
    """Names written once in the equations that are one slip (two letters swapped, one
    left out or added, before any subscript) from another name of the spec.

    >>> from dynsolve.spec.parser import parse_spec
    >>> likely_typos(parse_spec("equations:\\n  M = I*alpha\\n  a = alpah*r\\nfind: a", "t.dyn"))
    ["'alpah' (line 3) and 'alpha' (line 2) differ by one slip: is one of them misspelt?"]
    >>> text = "given:\\n  omega = 2 rad/s\\nequations:\\n  v = omga*r\\nfind: v"
    >>> likely_typos(parse_spec(text, "t.dyn"))
    ["'omga' (line 4) looks like a misspelling of 'omega'"]
    >>> likely_typos(parse_spec("equations:\\n  x = theta_1 + theta_2\\nfind: x", "t.dyn"))
    []
    """
    lines: dict[str, list[int]] = {}
    for statement in (*spec.equations, *spec.kinematics):
        for side in (statement.lhs, statement.rhs):
            for name in iter_names(side):
                lines.setdefault(name.text, []).append(statement.line)
    others = set(lines) | {g.name for g in spec.givens} | {f.name for f in spec.finds}
    found = []
    for name, where in lines.items():
        if len(where) != 1:
            continue
        for other in sorted(others - {name}):
            if not _one_slip(name, other):
                continue
            if other in lines and len(lines[other]) == 1:  # both written once: which is it?
                if other > name:
                    found.append(
                        f"'{name}' (line {where[0]}) and '{other}' (line {lines[other][0]}) "
                        "differ by one slip: is one of them misspelt?"
                    )
            else:
                found.append(f"'{name}' (line {where[0]}) looks like a misspelling of '{other}'")
            break
    return found


def _one_slip(a: str, b: str) -> bool:
    """Same subscript, and stems of four letters or more one swap, omission or addition apart."""
    stem_a, _, sub_a = a.partition("_")
    stem_b, _, sub_b = b.partition("_")
    if sub_a != sub_b or min(len(stem_a), len(stem_b)) < 4 or stem_a == stem_b:
        return False
    if len(stem_a) == len(stem_b):
        diff = [i for i, (x, y) in enumerate(zip(stem_a, stem_b, strict=True)) if x != y]
        return len(diff) == 2 and diff[1] == diff[0] + 1 and stem_a[diff[0]] == stem_b[diff[1]]
    short, long = sorted((stem_a, stem_b), key=len)
    return len(long) == len(short) + 1 and any(
        long[:i] + long[i + 1 :] == short for i in range(len(long))
    )


def _bare_angles(spec: Spec) -> Iterator[tuple[str, str]]:
    bare = {g.name: g for g in spec.givens if g.quantity is not None and g.quantity.unit is None}
    if not bare:  # no given without a unit: no walk of the whole spec
        return
    seen: set[str] = set()
    for reader, expr in _angle_uses(spec):
        for name in iter_names(expr):
            given = bare.get(name.text)
            if given is None or given.name in seen or given.quantity is None:
                continue
            seen.add(given.name)
            value = float(given.quantity.value)
            degrees = f"{math.degrees(value):.4g}"
            yield (
                "bare angle",
                f"{given.name} = {given.quantity.text} (line {given.line}) has no unit, so "
                f"{reader} reads it as {given.quantity.text} rad "
                f"({degrees}°); write '{given.quantity.text} deg' for degrees, or "
                f"'{given.quantity.text} rad' if radians are meant",
            )


def _angle_uses(spec: Spec) -> Iterator[tuple[str, object]]:
    """Where the spec reads an expression as an angle: the argument of sin/cos/tan, and a
    scene direction or property ``angle EXPR`` (a contact's normal, a force, a travel)."""
    stack: list[object] = [spec]
    while stack:
        item = stack.pop()
        if isinstance(item, Call) and item.function in TRIG:
            yield from ((f"{item.function}({arg})", arg) for arg in item.args)
        elif isinstance(item, Direction) and item.kind == "angle" and item.angle is not None:
            yield f"'angle {item.angle}'", item.angle
        elif isinstance(item, Prop) and item.key == "angle":
            yield from ((f"'angle {value}'", value) for value in item.values)
        stack.extend(children(item))


def _pounds_as_mass(spec: Spec) -> Iterator[tuple[str, str]]:
    for given in spec.givens:
        if not MASS_NAME.match(given.name) or not _is_force(given, spec.file):
            continue
        assert given.quantity is not None and given.quantity.unit is not None
        yield (
            "lb is a force",
            f"{given.name} = {given.quantity.text} {given.quantity.unit.text} "
            f"(line {given.line}) is a force "
            "(pound-force) but its name is a mass's; for a mass write W/g with W in lb, "
            "or use slug or lbm",
        )


def _is_force(given: Given, file: str) -> bool:
    if given.quantity is None or given.quantity.unit is None:
        return False
    try:
        return resolve_unit(given.quantity.unit, file).dim == FORCE
    except DynsolveError:
        return False  # reported where the givens are resolved
