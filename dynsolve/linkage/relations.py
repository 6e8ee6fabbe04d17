"""The relative velocity and acceleration equations of a linkage at an instant.

For every bar, each of its points is related to its first point as the textbook writes
it (Hibbeler 16.5, 16.7):

    v_B = v_A + ω × r_B/A,        a_B = a_A + α × r_B/A − ω² r_B/A,

two component equations each. A fixed point does not move; a slider's velocity and
acceleration lie along its guide (one unknown each, signed along the guide); any other
joint has two unknown components; every bar not driven has an unknown ω and α. The
drives (``omega``/``alpha`` of a bar, ``velocity``/``acceleration`` of a joint) are the
given motion. The unknowns and equations must match one for one (else the linkage has
more, or fewer, degrees of freedom than drives), and the equations must not be singular,
which they are exactly at a toggle (dead-centre) position.

>>> import sympy
>>> from dynsolve.linkage.model import Bar, Drive, Linkage
>>> crank = Linkage("p.dyn", {"A": (0, 0)}, {}, {}, {"AB": Bar("AB", ("A", "B"))}, {},
...                 (Drive("omega", "AB", sympy.Integer(-10)),))
>>> level = relative_motion(crank, {"A": (0, 0), "B": (sympy.Integer(2), 0)}, "velocity")
>>> [(e.lhs, e.rhs) for e in level.equations]
[(v_Bx, 0), (v_By, -20)]
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import sympy

from dynsolve.errors import SpecError
from dynsolve.linkage.model import Drive, Linkage
from dynsolve.model.scene import Vec
from dynsolve.names import pretty
from dynsolve.system import Equation
from dynsolve.units import Dim

TOGGLE = 1e10  # a condition number past this is a toggle (singular) position
LEVELS = {
    # level: (rotation, its dimension, joint rate, its dimension, drive kinds)
    "velocity": ("omega", Dim(0, 0, -1), "v", Dim.of("velocity"), ("omega", "velocity")),
    "acceleration": (
        "alpha",
        Dim(0, 0, -2),
        "a",
        Dim.of("acceleration"),
        ("alpha", "acceleration"),
    ),
}
ZERO = sympy.Integer(0)


@dataclass(frozen=True)
class Level:
    """One level (velocities or accelerations) of the linkage's motion at the instant."""

    rotation: Mapping[str, sympy.Expr]  # bar -> ω (or α): an unknown or its drive
    rate: Mapping[str, Vec]  # joint -> its velocity (or acceleration) vector
    along: Mapping[str, sympy.Expr]  # slider joint -> its signed rate along the guide
    unknowns: Mapping[sympy.Symbol, Dim]
    equations: tuple[Equation, ...]
    relative: Mapping[str, sympy.Expr] = field(default_factory=dict)  # along a moving bar


def relative_motion(
    linkage: Linkage,
    r: Mapping[str, Vec],
    level: str,
    omega: Mapping[str, sympy.Expr] | None = None,
    slots: Mapping[str, Vec] | None = None,
    sliding: Mapping[str, sympy.Expr] | None = None,
    released: int = 0,
) -> Level:
    """The equations of one level at the positions ``r``; ``slots`` maps each bar that a
    joint slides along to its direction (unit vector). The acceleration level needs the
    bars' ``omega`` and the joints' ``sliding`` speeds along their bars (from the velocity
    level); ``released`` bars have an α the loads decide (Newton–Euler supplies the
    equations this level lacks for them)."""
    rotation_name, rotation_dim, rate_name, rate_dim, drive_kinds = LEVELS[level]
    unknowns: dict[sympy.Symbol, Dim] = {}
    rotation: dict[str, sympy.Expr] = {}
    for bar in linkage.bars:
        drive = linkage.drive(drive_kinds[0], bar)
        if drive is not None:
            rotation[bar] = drive.value
        else:
            symbol = sympy.Symbol(f"{rotation_name}_{bar}", real=True)
            rotation[bar] = symbol
            unknowns[symbol] = rotation_dim
    rate: dict[str, Vec] = {}
    along: dict[str, sympy.Expr] = {}
    for point in linkage.joints:
        if point in linkage.fixed:
            rate[point] = (ZERO, ZERO)
            continue
        drive = linkage.drive(drive_kinds[1], point)
        slider = linkage.sliders.get(point)
        if slider is not None and slider.axis is not None:
            if drive is not None:
                along[point] = _along_guide(linkage, drive, slider.axis)
            else:
                along[point] = sympy.Symbol(f"{rate_name}_{point}", real=True)
                unknowns[along[point]] = rate_dim
            rate[point] = (along[point] * slider.axis[0], along[point] * slider.axis[1])
        elif drive is not None:
            assert drive.direction is not None
            rate[point] = (drive.value * drive.direction[0], drive.value * drive.direction[1])
        else:
            x = sympy.Symbol(f"{rate_name}_{point}x", real=True)
            y = sympy.Symbol(f"{rate_name}_{point}y", real=True)
            rate[point] = (x, y)
            unknowns |= {x: rate_dim, y: rate_dim}
    equations: list[Equation] = []
    for bar in linkage.bars.values():
        base = bar.points[0]
        w = rotation[bar.name]
        spin = (omega or {}).get(bar.name, ZERO) if level == "acceleration" else ZERO
        for point in bar.points[1:]:
            dx, dy = r[point][0] - r[base][0], r[point][1] - r[base][1]
            rhs = (
                rate[base][0] - w * dy - spin**2 * dx,
                rate[base][1] + w * dx - spin**2 * dy,
            )
            moving = "" if base in linkage.fixed else f"{rate_name}_{base} + "
            law = (
                f"{rate_name}_{point} = {moving}{pretty(rotation_name)}_{bar.name} "
                f"× r_{point}/{base}"
            )
            if level == "acceleration":
                law += f" − {pretty('omega')}_{bar.name}² r_{point}/{base}"
            for axis, lhs, right in zip("xy", rate[point], rhs, strict=True):
                if (lhs - right).free_symbols or lhs != right:
                    equations.append(
                        Equation(lhs, right, f"{law} ({axis})", bar.line, f"{law} ({axis})")
                    )
    relative: dict[str, sympy.Expr] = {}
    for slider in linkage.sliders.values():
        if not slider.bar:
            continue
        point, bar = slider.point, linkage.bars[slider.bar]
        base, e = bar.points[0], (slots or {})[slider.bar]
        relative[point] = sympy.Symbol(f"{rate_name}_rel_{point}", real=True)
        unknowns[relative[point]] = rate_dim
        w, u = rotation[bar.name], relative[point]
        dx, dy = r[point][0] - r[base][0], r[point][1] - r[base][1]
        rhs = [rate[base][0] - w * dy + u * e[0], rate[base][1] + w * dx + u * e[1]]
        moving = "" if base in linkage.fixed else f"{rate_name}_{base} + "
        law = f"{pretty(rotation_name)}_{bar.name} × r_{point}/{base}"
        if level == "acceleration":
            spin = (omega or {}).get(bar.name, ZERO)
            v_rel = (sliding or {})[point]
            rhs[0] += -(spin**2) * dx - 2 * spin * v_rel * e[1]
            rhs[1] += -(spin**2) * dy + 2 * spin * v_rel * e[0]
            law += (
                f" − {pretty('omega')}_{bar.name}² r_{point}/{base} + 2 {pretty('omega')}_"
                f"{bar.name} × v_rel + a_rel"
            )
        else:
            law += " + v_rel"
        law = f"{rate_name}_{point} = {moving}{law} (sliding along {bar.name})"
        for axis, lhs, right in zip("xy", rate[point], rhs, strict=True):
            equations.append(
                Equation(lhs, right, f"{law} ({axis})", slider.line, f"{law} ({axis})")
            )
    equations += _rolling(linkage, level, rotation, rate)
    equations += _meshing(linkage, level, r, rotation, rate)
    _check_count(linkage, level, unknowns, equations, released)
    return Level(rotation, rate, along, unknowns, tuple(equations), relative)


def _rolling(
    linkage: Linkage, level: str, rotation: Mapping[str, sympy.Expr], rate: Mapping[str, Vec]
) -> list[Equation]:
    """A wheel rolling on fixed ground touches it at K = O − ρ n with v_K = 0 and
    a_K = ω² ρ n: v_O = ω × r_O/K and a_O = α × r_O/K (Hibbeler 16.5: v_O = ω r, a_O = α r)."""
    rotation_name, _, rate_name, _, _ = LEVELS[level]
    equations = []
    for wheel in linkage.wheels.values():
        centre = linkage.bars[wheel.bar].points[0]
        w, n, rho = rotation[wheel.bar], wheel.normal, wheel.radius
        rhs = (-w * rho * n[1], w * rho * n[0])
        law = f"{rate_name}_{centre} = {pretty(rotation_name)}_{wheel.bar} × r_{centre}/K (rolls)"
        for axis, lhs, right in zip("xy", rate[centre], rhs, strict=True):
            if (lhs - right).free_symbols or lhs != right:
                equations.append(
                    Equation(lhs, right, f"{law} ({axis})", wheel.line, f"{law} ({axis})")
                )
    return equations


def _meshing(
    linkage: Linkage,
    level: str,
    r: Mapping[str, Vec],
    rotation: Mapping[str, sympy.Expr],
    rate: Mapping[str, Vec],
) -> list[Equation]:
    """Gears in mesh: at the pitch point P the two gears' points share their velocity (and
    acceleration) along the common tangent t = k × e₁, e₁ from centre 1 toward P:
    v_O1·t + ω_1 r_1 = v_O2·t − ω_2 r_2 in external mesh, + ω_2 r_2 in internal mesh (a
    ring gear turns the same way at P) — α in place of ω for accelerations."""
    rotation_name, _, rate_name, _, _ = LEVELS[level]
    equations = []
    for mesh in linkage.meshes:
        one, two = (linkage.bars[b].points[0] for b in (mesh.first, mesh.second))
        e, side = mesh.pitch((r[one], r[two]), linkage.values, linkage.file)
        t = (-e[1], e[0])  # the common tangent k × e₁ (the centres' distance checked)
        lhs = rate[one][0] * t[0] + rate[one][1] * t[1] + rotation[mesh.first] * mesh.radii[0]
        rhs = (
            rate[two][0] * t[0] + rate[two][1] * t[1] + side * rotation[mesh.second] * mesh.radii[1]
        )
        w = pretty(rotation_name)
        sign, kind = ("+", "internal mesh") if side > 0 else ("−", "mesh")
        law = (
            f"({rate_name}_P)_t on {mesh.first} = ({rate_name}_P)_t on {mesh.second}: "
            f"{rate_name}_{one}·t + {w}_{mesh.first} r = {rate_name}_{two}·t {sign} "
            f"{w}_{mesh.second} r ({kind})"
        )
        equations.append(Equation(lhs, rhs, law, mesh.line, law))
    return equations


def _along_guide(linkage: Linkage, drive: Drive, axis: Vec) -> sympy.Expr:
    """A slider's given rate as a signed value along its guide; it must lie along it."""
    assert drive.direction is not None
    cross = drive.direction[0] * axis[1] - drive.direction[1] * axis[0]
    dot = drive.direction[0] * axis[0] + drive.direction[1] * axis[1]
    numbers = [
        sympy.N((sympy.Integer(0) + c).xreplace(dict(linkage.values)), 15) for c in (cross, dot)
    ]
    if all(n.is_number for n in numbers) and abs(float(numbers[0])) > 1e-9:
        raise SpecError(
            f"the {drive.kind} of slider {drive.name} must lie along its guide",
            linkage.where(drive.name),
            hint="give it along the slider's direction (or its opposite)",
        )
    return drive.value * dot


def _check_count(
    linkage: Linkage,
    level: str,
    unknowns: Mapping[sympy.Symbol, Dim],
    equations: list[Equation],
    released: int = 0,
) -> None:
    """As many equations as unknowns: a degree of freedom per drive (or per bar whose α
    the loads decide, ``released``), no more, no fewer."""
    if len(unknowns) == len(equations) + released:
        return
    kinds = LEVELS[level][4]
    drives = [d for d in linkage.drives if d.kind in kinds]
    freedom = len(unknowns) - len(equations) + len(drives) - released
    named = ", ".join(pretty(s.name) for s in unknowns)
    if freedom <= 0:
        what = "is a rigid structure: it cannot move" if freedom <= 0 else ""
        hint = (
            "remove a bar or a drive, or free a joint (a slider instead of a fixed point)"
            if drives
            else "check the bars: a linkage that moves needs a loop with four or more bars"
        )
        raise SpecError(
            f"the linkage {what} (its {level} equations, {len(equations)}, outnumber its "
            f"unknowns {named or '(none)'}"
            + (f", with {len(drives)} drive{'s' * (len(drives) > 1)})" if drives else ")"),
            linkage.where(next(iter(linkage.bars))),
            hint=hint,
        )
    if len(drives) == freedom:  # the count of drives is right: a joint or bar is left over
        return
    example = "'omega AB: w cw'" if level == "velocity" else "'alpha AB: 0' (ω constant)"
    raise SpecError(
        f"the linkage has {freedom} degree{'s' * (freedom != 1)} of freedom, but its "
        f"{_plural(level)} are given by {len(drives)} drive{'s' * (len(drives) != 1)}: "
        f"{len(unknowns)} unknowns ({named}) for {len(equations)} equations",
        linkage.where(next(iter(linkage.bars))),
        hint=f"give one drive per degree of freedom, e.g. {example}"
        if len(drives) < freedom
        else "drop a drive: the others already fix the motion",
    )


def _plural(level: str) -> str:
    return "velocities" if level == "velocity" else f"{level}s"


def condition(level: Level, values: Mapping[sympy.Symbol, sympy.Expr], size: float) -> float | None:
    """The condition number of a level's equations in its unknowns, each rotation taken
    as ω times the linkage's ``size`` (so every column is a speed); None when the
    geometry is symbolic."""
    import numpy

    unknowns = list(level.unknowns)
    if not unknowns or len(level.equations) != len(unknowns):
        return None
    column = {symbol: i for i, symbol in enumerate(unknowns)}
    zero = dict.fromkeys(unknowns, ZERO)
    rotations = (LEVELS["velocity"][1], LEVELS["acceleration"][1])
    matrix = numpy.zeros((len(unknowns), len(unknowns)))
    for i, equation in enumerate(level.equations):  # each row holds a few unknowns
        residual = (equation.lhs - equation.rhs).xreplace(dict(values))
        for symbol in residual.free_symbols & set(column):
            coefficient = sympy.N(sympy.diff(residual, symbol).xreplace(zero), 20)
            if not coefficient.is_number:
                return None
            scale = size if level.unknowns[symbol] in rotations else 1.0
            matrix[i, column[symbol]] = float(coefficient) / scale
    singular = numpy.linalg.svd(matrix, compute_uv=False)
    return math.inf if singular[-1] == 0 else float(singular[0] / singular[-1])


def in_line(
    linkage: Linkage, r: Mapping[str, Vec], values: Mapping[sympy.Symbol, sympy.Expr]
) -> list[str]:
    """Pairs of two-point bars meeting at a joint and lying in one line (a toggle)."""
    direction: dict[str, tuple[float, float]] = {}
    for bar in linkage.bars.values():
        if len(bar.points) != 2:
            continue
        first, second = (r[p] for p in bar.points)
        try:
            dx = float(sympy.N((second[0] - first[0]).xreplace(dict(values)), 20))
            dy = float(sympy.N((second[1] - first[1]).xreplace(dict(values)), 20))
        except TypeError:
            continue
        length = math.hypot(dx, dy)
        if length > 0:
            direction[bar.name] = (dx / length, dy / length)
    found = []
    names = list(direction)
    for i, one in enumerate(names):
        for other in names[i + 1 :]:
            shared = set(linkage.bars[one].points) & set(linkage.bars[other].points)
            u, w = direction[one], direction[other]
            if shared and abs(u[0] * w[1] - u[1] * w[0]) < 1e-6:
                found.append(f"{one} and {other} lie in one line at {shared.pop()}")
    return found
