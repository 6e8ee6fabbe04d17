"""The velocity level of a linkage by instantaneous centres (``method ic``, Hibbeler 16.6).

Each bar's instantaneous centre of zero velocity (IC) is located as the textbook does:
a bar pinned to the ground turns about the pin; a wheel rolling on fixed ground turns
about its contact point; any other bar about the point where the normals to two of its
points' velocities meet (a slider's velocity lies along its guide, a driven joint's
along its drive, a joint shared with a bar whose IC is known across the line from that
IC). Every point then moves at v = ω r/IC, perpendicular to r/IC, so a joint shared by
two bars gives ω₁ r_P/IC₁ = ω₂ r_P/IC₂, and a slider v_P = ω r_P/IC: one equation per
joint, in the bars' ω and the sliders' speeds.

The centres' coordinates and the distances r_P/IC become derived quantities with their
formulas and values; each equation's sign (both sides turning the same way or not) is
read from the numbers at the instant. A linkage whose centres cannot all be located so
(a bar with two parallel normals and no turning, a gear, a collar on a moving bar, a
symbolic geometry) is refused with the reason, and the default relative-velocity method
named.

>>> import sympy
>>> from dynsolve.linkage.model import Bar, Drive, Linkage, Slider
>>> x_B, y_B = sympy.Rational(3, 10), sympy.Rational(4, 10)
>>> crank = Linkage(
...     "p.dyn", {"A": (0, 0)}, {}, {},
...     {"AB": Bar("AB", ("A", "B")), "BC": Bar("BC", ("B", "C"))},
...     {"C": Slider("C", (sympy.Integer(1), sympy.Integer(0)))},
...     (Drive("omega", "AB", sympy.Integer(-10)),), method="ic")
>>> r = {"A": (0, 0), "B": (x_B, y_B), "C": (sympy.Rational(6, 10), 0)}
>>> level, rows = by_centres(crank, r, {})
>>> [(e.lhs, e.rhs) for e in level.equations]  # IC of BC at (0.6, 0.8): ω_BC = 10 ccw
[(-10*r_B_AB, -omega_BC*r_B_BC), (v_C, omega_BC*r_C_BC)]
>>> [(row.name, row.value) for row in rows]
[('x_IC_BC', 3/5), ('y_IC_BC', 4/5), ('r_B_AB', 1/2), ('r_B_BC', 1/2), ('r_C_BC', 4/5)]
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import sympy

from dynsolve.errors import Position, SpecError
from dynsolve.linkage.model import LENGTH, Linkage
from dynsolve.linkage.relations import Level
from dynsolve.model.scene import Vec
from dynsolve.modes.equation_mode import GivenInfo
from dynsolve.names import pretty
from dynsolve.numbers import abs_resolved, real_value, tidy
from dynsolve.system import Equation
from dynsolve.units import Dim

ZERO = sympy.Integer(0)
OMEGA = Dim(0, 0, -1)
VELOCITY = Dim.of("velocity")
PARALLEL = 1e-12  # |n₁ × n₂| below this (unit normals): the normals do not meet


def by_centres(
    linkage: Linkage, r: Mapping[str, Vec], knowns: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Level, list[GivenInfo]]:
    """The velocity level written with instantaneous centres, and the derived rows (each
    IC's coordinates, each r_P/IC) it names; ``knowns`` holds the numbers at the instant."""
    _refuse_what_it_cannot_take(linkage)
    values: dict[sympy.Symbol, sympy.Expr] = {**knowns, **dict(linkage.values)}
    centres, exact, rows = _centres(linkage, r, values)
    unknowns: dict[sympy.Symbol, Dim] = {}
    rotation: dict[str, sympy.Expr] = {}
    for name in linkage.bars:
        drive = linkage.drive("omega", name)
        if drive is not None:
            rotation[name] = drive.value
        else:
            rotation[name] = sympy.Symbol(f"omega_{name}", real=True)
            unknowns[rotation[name]] = OMEGA
    distances: dict[tuple[str, str], sympy.Expr] = {}

    def distance(point: str, bar: str) -> sympy.Expr:
        """r_P/IC of ``bar``, named the first time it is used."""
        if (point, bar) not in distances:
            rho = _minus(r[point], exact[bar])  # the IC's own formula: r_A/IC = x_B
            formula = abs_resolved(sympy.sqrt(rho[0] ** 2 + rho[1] ** 2), values)
            distances[(point, bar)] = _named(
                f"r_{point}_{bar}", formula, values, rows, f"{point} to the IC of {bar}"
            )
        return distances[(point, bar)]

    rate: dict[str, Vec] = {}
    along: dict[str, sympy.Expr] = {}
    equations: list[Equation] = []
    for point in linkage.joints:
        if point in linkage.fixed:
            rate[point] = (ZERO, ZERO)
            continue
        bars = [b for b in linkage.bars if point in linkage.bars[b].points]
        first, where = bars[0], linkage.where(point)
        turning = _turning(r[point], centres[first])  # k × r_P/IC: v_P = ω (k × r_P/IC)
        rate[point] = (rotation[first] * turning[0], rotation[first] * turning[1])
        if _size(turning, values) < PARALLEL:
            raise SpecError(
                f"joint {point} is at the instantaneous centre of {first}",
                where,
                hint="its velocity is zero there; solve without 'method ic'",
            )
        at_first = rotation[first] * distance(point, first)
        for other in bars[1:]:
            sign = _sign(_dot(turning, _turning(r[point], centres[other])), values, where)
            law = f"v_{point} = ω_{first} r_{point}/IC({first}) = ω_{other} r_{point}/IC({other})"
            line = linkage.bars[other].line
            equations.append(
                Equation(at_first, sign * rotation[other] * distance(point, other), law, line, law)
            )
        slider = linkage.sliders.get(point)
        drive = linkage.drive("velocity", point)
        if slider is not None and slider.axis is not None:
            sign = _sign(_dot(turning, slider.axis), values, where)
            if drive is not None:
                assert drive.direction is not None
                same = _sign(_dot(drive.direction, slider.axis), values, where)
                along[point] = drive.value * same
            else:
                along[point] = sympy.Symbol(f"v_{point}", real=True)
                unknowns[along[point]] = VELOCITY
            rate[point] = (along[point] * slider.axis[0], along[point] * slider.axis[1])
            law = f"v_{point} = ω_{first} r_{point}/IC({first}) (along the guide of {point})"
            equations.append(Equation(along[point], sign * at_first, law, slider.line, law))
        elif drive is not None:
            assert drive.direction is not None
            sign = _sign(_dot(turning, drive.direction), values, where)
            law = f"v_{point} = ω_{first} r_{point}/IC({first}) (given)"
            equations.append(Equation(drive.value, sign * at_first, law, drive.line, law))
    if len(equations) != len(unknowns):
        raise SpecError(
            f"by instantaneous centres the linkage gives {len(equations)} equations for "
            f"{len(unknowns)} unknowns",
            Position(linkage.file, 1, 1),
            hint="check its drives (one per degree of freedom), or solve without 'method ic'",
        )
    return Level(rotation, rate, along, unknowns, tuple(equations)), rows


def _refuse_what_it_cannot_take(linkage: Linkage) -> None:
    """Gears in mesh and collars on moving bars have no IC construction here."""
    if linkage.meshes:
        raise SpecError(
            "'method ic' does not take gears in mesh",
            Position(linkage.file, linkage.meshes[0].line, linkage.meshes[0].column),
            hint="solve without 'method ic' (relative velocity)",
        )
    for slider in linkage.sliders.values():
        if slider.bar:
            raise SpecError(
                f"'method ic' does not take joint {slider.point} sliding along the moving "
                f"bar {slider.bar}",
                Position(linkage.file, slider.line, slider.column),
                hint="solve without 'method ic' (relative velocity with v_rel)",
            )


def _centres(
    linkage: Linkage, r: Mapping[str, Vec], values: dict[sympy.Symbol, sympy.Expr]
) -> tuple[dict[str, Vec], dict[str, Vec], list[GivenInfo]]:
    """Each bar's IC: its fixed point, its wheel's contact with the ground, or where the
    normals to two of its points' velocities meet; located bar by bar until none is left.
    The centres by name (x_IC_BC), by formula, and the rows that name them."""
    centres: dict[str, Vec] = {}
    exact: dict[str, Vec] = {}
    rows: list[GivenInfo] = []
    for name, bar in linkage.bars.items():
        fixed = [p for p in bar.points if p in linkage.fixed]
        if fixed:
            centres[name] = exact[name] = r[fixed[0]]
        elif name in linkage.wheels:
            wheel = linkage.wheels[name]
            hub = r[bar.points[0]]
            contact = (
                tidy(hub[0] - wheel.radius * wheel.normal[0], light=False),
                tidy(hub[1] - wheel.radius * wheel.normal[1], light=False),
            )
            exact[name] = contact
            centres[name] = _located(name, contact, values, rows, "its contact with the ground")
    progress = True
    while progress:
        progress = False
        for name, bar in linkage.bars.items():
            if name in centres:
                continue
            lines = [(p, n) for p in bar.points if (n := _normal(linkage, p, name, r, centres))]
            if len(lines) < 2:
                continue
            (P, n1), (Q, n2) = lines[0], lines[1]
            across = n1[0] * n2[1] - n1[1] * n2[0]
            size = real_value(across, values)
            scale = (_size(n1, values) or 1.0) * (_size(n2, values) or 1.0)
            if size is None or abs(size) < PARALLEL * scale:
                raise SpecError(
                    f"the normals to the velocities of {P} and {Q} on {name} do not meet: "
                    f"{name} translates at the instant, or its IC is not fixed by them",
                    linkage.where(name),
                    hint="solve without 'method ic' (relative velocity)",
                )
            d = _minus(r[Q], r[P])
            s = (d[0] * n2[1] - d[1] * n2[0]) / across
            meet = (tidy(r[P][0] + s * n1[0], light=False), tidy(r[P][1] + s * n1[1], light=False))
            how = f"where the normals to v_{P} and v_{Q} meet"
            exact[name] = meet
            centres[name] = _located(name, meet, values, rows, how)
            progress = True
    missing = [name for name in linkage.bars if name not in centres]
    if missing:
        raise SpecError(
            f"the instantaneous centre of {missing[0]} cannot be located from two of its "
            "points' velocity directions",
            linkage.where(missing[0]),
            hint="solve without 'method ic' (relative velocity)",
        )
    return centres, exact, rows


def _normal(
    linkage: Linkage, point: str, bar: str, r: Mapping[str, Vec], centres: Mapping[str, Vec]
) -> Vec | None:
    """The normal to ``point``'s velocity direction, where that direction is known: along
    a slider's guide, a driven velocity, or across the line to another bar's IC."""
    slider = linkage.sliders.get(point)
    if slider is not None and slider.axis is not None:
        return (-slider.axis[1], slider.axis[0])
    drive = linkage.drive("velocity", point)
    if drive is not None and drive.direction is not None:
        return (-drive.direction[1], drive.direction[0])
    for other, centre in centres.items():
        if other != bar and point in linkage.bars[other].points:
            return _minus(r[point], centre)
    return None


def _located(
    bar: str, point: Vec, values: dict, rows: list[GivenInfo], how: str
) -> tuple[sympy.Expr, sympy.Expr]:
    """The IC of ``bar`` with each coordinate named (x_IC_BAR) unless a plain number."""
    return (
        _named(f"x_IC_{bar}", point[0], values, rows, f"x of the IC of {bar}, {how}", True),
        _named(f"y_IC_{bar}", point[1], values, rows, f"y of the IC of {bar}, {how}", True),
    )


def _named(
    name: str,
    formula: sympy.Expr,
    values: dict,
    rows: list[GivenInfo],
    note: str,
    shown: bool = False,
) -> sympy.Expr:
    """``formula`` as a derived length shown with its value, named even where it is a
    single given or number (the derivation states each IC and r_P/IC, as the textbook
    does); its value joins ``values`` for the signs read later. ``shown``: listed even where no
    equation names it (an IC's coordinates, which the distances use)."""
    formula = sympy.Integer(0) + formula
    symbol = sympy.Symbol(name, real=True)
    value = formula.xreplace(values).xreplace(values)
    rows.append(GivenInfo(name, symbol, value, LENGTH, None, note, formula, shown))
    values[symbol] = value
    return symbol


def _minus(a: Vec, b: Vec) -> Vec:
    return (a[0] - b[0], a[1] - b[1])


def _turning(point: Vec, centre: Vec) -> Vec:
    """k × r_P/IC."""
    rho = _minus(point, centre)
    return (-rho[1], rho[0])


def _dot(a: Vec, b: Vec) -> sympy.Expr:
    return a[0] * b[0] + a[1] * b[1]


def _size(v: Vec, values: Mapping) -> float:
    numbers = [real_value(sympy.Integer(0) + c, values) for c in v]
    if any(n is None for n in numbers):
        return math.nan
    return math.hypot(*numbers)  # type: ignore[arg-type]


def _sign(expr: sympy.Expr, values: Mapping, where: Position) -> int:
    """+1 or −1 from the numbers at the instant (the two sides turn the same way or not)."""
    value = real_value(sympy.Integer(0) + expr, values)
    if value is None or value == 0:
        raise SpecError(
            f"'method ic' needs the geometry in numbers at the instant ({pretty(str(expr))[:60]})",
            where,
            hint="give the lengths and angles values, or solve without 'method ic'",
        )
    return 1 if value > 0 else -1
