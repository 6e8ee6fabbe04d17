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
read from the numbers at the instant.

Where a bar's two normals are parallel, distinct lines, its IC is at infinity: the bar
translates at the instant (ω = 0, stated as a row with the reason) and every point of it
has the velocity of the joint it takes it from, v_C = v_B; a drive that turns such a bar,
or given speeds its points cannot share, is refused as inconsistent. A linkage whose
centres cannot all be located so (two normals on one line, where only the speeds' ratio
would place the IC; a gear; a collar on a moving bar; a symbolic geometry) is refused
with the reason, and the default relative-velocity method named.

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
from collections.abc import Callable, Mapping

import sympy

from dynsolve.errors import Position, SpecError
from dynsolve.linkage.model import LENGTH, Drive, Linkage
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
    centres, exact, rows, translating = _centres(linkage, r, values)
    unknowns: dict[sympy.Symbol, Dim] = {}
    rotation: dict[str, sympy.Expr] = {}
    for name in linkage.bars:
        drive = linkage.drive("omega", name)
        if name in translating:
            rotation[name] = _at_rest(linkage, name, translating[name], drive, values, rows)
        elif drive is not None:
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
    shared = _shared_velocities(
        linkage, r, translating, centres, rotation, distance, along, unknowns
    )
    for point in linkage.joints:
        if point in linkage.fixed:
            rate[point] = (ZERO, ZERO)
            continue
        bars = [b for b in linkage.bars if point in linkage.bars[b].points]
        where = linkage.where(point)
        turning_bars = [b for b in bars if b not in translating]
        if not turning_bars:  # every bar at the joint translates: it moves with them
            equations += _moving_with(linkage, point, bars, shared, rate, along, unknowns, values)
            continue
        first = turning_bars[0]
        turning = _turning(r[point], centres[first])  # k × r_P/IC: v_P = ω (k × r_P/IC)
        rate[point] = (rotation[first] * turning[0], rotation[first] * turning[1])
        if _size(turning, values) < PARALLEL:
            raise SpecError(
                f"joint {point} is at the instantaneous centre of {first}",
                where,
                hint="its velocity is zero there; solve without 'method ic'",
            )
        at_first = rotation[first] * distance(point, first)
        for other in bars:
            if other == first:
                continue
            if other in translating:
                speed, u, _, from_point = shared[other]
                if from_point == point:
                    continue  # the translation's velocity is this joint's
                sign = _sign(_dot(turning, u), values, where)
                law = (
                    f"v_{point} = ω_{first} r_{point}/IC({first}) = v_{from_point} "
                    f"({other} translates: IC at infinity)"
                )
                line = linkage.bars[other].line
                equation = Equation(at_first, sign * speed, law, line, law)
                equations.append(_consistent(equation, other, values, where))
                continue
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


Shared = tuple[sympy.Expr, Vec, Vec, str]  # speed along u, u, the velocity, from which joint


def _at_rest(
    linkage: Linkage,
    name: str,
    normals: tuple[str, str, Vec],
    drive: Drive | None,
    values: Mapping[sympy.Symbol, sympy.Expr],
    rows: list[GivenInfo],
) -> sympy.Expr:
    """ω of a bar whose IC is at infinity: 0, stated as a row with the reason; a drive
    that turns it contradicts the geometry and is refused."""
    P, Q, _ = normals
    reason = (
        f"the normals to v_{P} and v_{Q} are parallel: the IC of {name} is at infinity, "
        f"{name} translates (Hibbeler 16.6) and all its points move alike"
    )
    if drive is not None:
        value = real_value(sympy.Integer(0) + drive.value, values)
        if value != 0:
            raise SpecError(
                f"{name} is driven at ω = {value:.4g} rad/s, but {reason}: ω = 0",
                Position(linkage.file, drive.line, drive.column),
                hint="check the drive and the positions at the instant",
            )
        return drive.value
    symbol = sympy.Symbol(f"omega_{name}", real=True)
    note = f"ω of {name}: {reason}"
    rows.append(GivenInfo(f"omega_{name}", symbol, ZERO, OMEGA, None, note, ZERO, True))
    return symbol


def _shared_velocities(
    linkage: Linkage,
    r: Mapping[str, Vec],
    translating: Mapping[str, tuple[str, str, Vec]],
    centres: Mapping[str, Vec],
    rotation: Mapping[str, sympy.Expr],
    distance: Callable[[str, str], sympy.Expr],
    along: dict[str, sympy.Expr],
    unknowns: dict[sympy.Symbol, Dim],
) -> dict[str, Shared]:
    """The one velocity of each translating bar, from the first of its joints whose
    velocity is known otherwise: fixed (zero), on a turning bar (ω r_P/IC), driven, or a
    slider (its speed along the guide, an unknown)."""
    shared: dict[str, Shared] = {}
    for name in translating:
        points = linkage.bars[name].points
        for point in points:
            turning = [b for b in linkage.bars if point in linkage.bars[b].points and b in centres]
            if point in linkage.fixed:
                shared[name] = (ZERO, (ZERO, ZERO), (ZERO, ZERO), point)
            elif turning:
                u = _turning(r[point], centres[turning[0]])
                w = rotation[turning[0]]
                shared[name] = (w * distance(point, turning[0]), u, (w * u[0], w * u[1]), point)
            if name in shared:
                break
        for point in points if name not in shared else ():
            drive = linkage.drive("velocity", point)
            slider = linkage.sliders.get(point)
            if drive is not None and drive.direction is not None:
                u = drive.direction
                shared[name] = (drive.value, u, (drive.value * u[0], drive.value * u[1]), point)
            elif slider is not None and slider.axis is not None:
                along[point] = sympy.Symbol(f"v_{point}", real=True)
                unknowns[along[point]] = VELOCITY
                u = slider.axis
                shared[name] = (along[point], u, (along[point] * u[0], along[point] * u[1]), point)
            if name in shared:
                break
        if name not in shared:
            raise SpecError(
                f"{name} translates at the instant (its IC is at infinity), but none of its "
                "joints has a velocity known otherwise",
                linkage.where(name),
                hint="solve without 'method ic' (relative velocity)",
            )
    return shared


def _moving_with(
    linkage: Linkage,
    point: str,
    bars: list[str],
    shared: Mapping[str, Shared],
    rate: dict[str, Vec],
    along: dict[str, sympy.Expr],
    unknowns: dict[sympy.Symbol, Dim],
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> list[Equation]:
    """A joint on translating bars only: it moves with the first (v_P = v of the joint
    that bar's velocity comes from); its guide or its drive gives one equation."""
    speed, u, vector, source = shared[bars[0]]
    rate[point] = vector
    where = linkage.where(point)
    equations: list[Equation] = []
    text = f"v_{point} = v_{source} ({bars[0]} translates: IC at infinity)"
    for other in bars[1:]:
        other_speed, other_u, _, other_source = shared[other]
        if other_source != source:
            sign = _sign(_dot(u, other_u), values, where)
            law = f"v_{source} = v_{other_source} ({bars[0]} and {other} translate)"
            equation = Equation(speed, sign * other_speed, law, linkage.bars[other].line, law)
            equations.append(_consistent(equation, other, values, where))
    if source == point:
        return equations  # the bar's velocity is this joint's own (its slider or drive)
    slider = linkage.sliders.get(point)
    drive = linkage.drive("velocity", point)
    if slider is not None and slider.axis is not None:
        sign = _sign(_dot(u, slider.axis), values, where)
        if drive is not None:
            assert drive.direction is not None
            along[point] = drive.value * _sign(_dot(drive.direction, slider.axis), values, where)
        else:
            along[point] = sympy.Symbol(f"v_{point}", real=True)
            unknowns[along[point]] = VELOCITY
        rate[point] = (along[point] * slider.axis[0], along[point] * slider.axis[1])
        law = f"{text} (along the guide of {point})"
        equation = Equation(along[point], sign * speed, law, slider.line, law)
        equations.append(_consistent(equation, bars[0], values, where))
    elif drive is not None:
        assert drive.direction is not None
        sign = _sign(_dot(u, drive.direction), values, where)
        law = f"{text} (given)"
        equation = Equation(drive.value, sign * speed, law, drive.line, law)
        equations.append(_consistent(equation, bars[0], values, where))
    return equations


def _consistent(
    equation: Equation, bar: str, values: Mapping[sympy.Symbol, sympy.Expr], where: Position
) -> Equation:
    """A translation's equation v_P = v_Q: where both sides are already known numbers
    they must agree, else the linkage cannot move so (refused with the two speeds)."""
    sides = [real_value(sympy.Integer(0) + side, values) for side in (equation.lhs, equation.rhs)]
    lhs, rhs = sides
    if lhs is None or rhs is None or math.isclose(lhs, rhs, rel_tol=1e-9, abs_tol=1e-12):
        return equation
    raise SpecError(
        f"{bar} translates at the instant (the normals to its points' velocities are "
        f"parallel, so its IC is at infinity), so its points move alike; but its given "
        f"motion gives them the speeds {abs(lhs):.4g} and {abs(rhs):.4g} "
        f"({equation.note}): inconsistent",
        where,
        hint="check the drives and the positions at the instant",
    )


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
) -> tuple[dict[str, Vec], dict[str, Vec], list[GivenInfo], dict[str, tuple[str, str, Vec]]]:
    """Each bar's IC: its fixed point, its wheel's contact with the ground, or where the
    normals to two of its points' velocities meet; located bar by bar until none is left.
    The centres by name (x_IC_BC), by formula, the rows that name them, and the bars whose
    two normals are distinct parallel lines (IC at infinity: they translate), each with
    the two points and the normal."""
    translating: dict[str, tuple[str, str, Vec]] = {}
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
                tidy(hub[0] - wheel.radius * wheel.normal[0]),
                tidy(hub[1] - wheel.radius * wheel.normal[1]),
            )
            exact[name] = contact
            centres[name] = _located(name, contact, values, rows, "its contact with the ground")
    progress = True
    while progress:
        progress = False
        for name, bar in linkage.bars.items():
            if name in centres or name in translating:
                continue
            lines = [
                (p, n)
                for p in bar.points
                if (n := _normal(linkage, p, name, r, centres, translating))
            ]
            if len(lines) < 2:
                continue
            (P, n1), (Q, n2) = lines[0], lines[1]
            across = n1[0] * n2[1] - n1[1] * n2[0]
            size = real_value(across, values)
            scale = (_size(n1, values) or 1.0) * (_size(n2, values) or 1.0)
            d = _minus(r[Q], r[P])
            lengths = (_size(n1, values), _size(n2, values))
            if size is not None and abs(size) < PARALLEL * scale and min(lengths) > PARALLEL:
                if _apart(d, n1, values):  # two parallel lines: the IC is at infinity
                    translating[name] = (P, Q, n1)
                    progress = True
                    continue
                raise SpecError(
                    f"the normals to the velocities of {P} and {Q} on {name} are one line: "
                    f"the IC of {name} lies on it at a place only the ratio of the speeds "
                    "fixes, which the directions alone do not give",
                    linkage.where(name),
                    hint="solve without 'method ic' (relative velocity)",
                )
            if size is None or abs(size) < PARALLEL * scale:
                raise SpecError(
                    f"the normals to the velocities of {P} and {Q} on {name} do not meet: "
                    f"its IC is not fixed by them",
                    linkage.where(name),
                    hint="solve without 'method ic' (relative velocity)",
                )
            s = (d[0] * n2[1] - d[1] * n2[0]) / across
            meet = (tidy(r[P][0] + s * n1[0]), tidy(r[P][1] + s * n1[1]))
            how = f"where the normals to v_{P} and v_{Q} meet"
            exact[name] = meet
            centres[name] = _located(name, meet, values, rows, how)
            progress = True
    missing = [name for name in linkage.bars if name not in centres and name not in translating]
    if missing:
        raise SpecError(
            f"the instantaneous centre of {missing[0]} cannot be located from two of its "
            "points' velocity directions",
            linkage.where(missing[0]),
            hint="solve without 'method ic' (relative velocity)",
        )
    return centres, exact, rows, translating


def _apart(d: Vec, n: Vec, values: Mapping) -> bool:
    """Whether the lines along ``n`` through two points ``d`` apart are distinct (d × n ≠ 0)."""
    across = real_value(d[0] * n[1] - d[1] * n[0], values)
    return across is not None and abs(across) > PARALLEL * _size(d, values) * _size(n, values)


def _normal(
    linkage: Linkage,
    point: str,
    bar: str,
    r: Mapping[str, Vec],
    centres: Mapping[str, Vec],
    translating: Mapping[str, tuple[str, str, Vec]],
) -> Vec | None:
    """The normal to ``point``'s velocity direction, where that direction is known: along
    a slider's guide, a driven velocity, across the line to another bar's IC, or that of
    another bar that translates."""
    slider = linkage.sliders.get(point)
    if slider is not None and slider.axis is not None:
        return (-slider.axis[1], slider.axis[0])
    drive = linkage.drive("velocity", point)
    if drive is not None and drive.direction is not None:
        return (-drive.direction[1], drive.direction[0])
    for other, centre in centres.items():
        if other != bar and point in linkage.bars[other].points:
            return _minus(r[point], centre)
    for other, (_, _, normal) in translating.items():
        if other != bar and point in linkage.bars[other].points:
            return normal
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
