"""Newton–Euler on every bar of a linkage: pin forces, guide forces, the driving couple.

Each bar is a free body (Hibbeler 17.5): ΣF_x = m (a_G)_x, ΣF_y = m (a_G)_y and
ΣM_G = I_G α, with a bar of mass ``m`` taken as uniform (G halfway between its two
points, I_G = m L²/12 unless a gyration is given) and a bar without mass in
equilibrium (a two-force member when nothing else acts on it). a_G comes from the
acceleration level: a_G = a_P + α × r_G/P − ω² r_G/P.

The forces between bodies are named after their joint: at a pin P joining bars, ``P_x``
and ``P_y`` act on the first bar that names P and their opposites on the second (with
three or more bars at P, ``P_x_BAR``, ``P_y_BAR`` act on each bar but the last, which
takes the opposite of their sum); at a fixed point the ground's reaction on the bar is
``P_x``, ``P_y``; a slider's smooth guide pushes with ``N_P`` along the guide's left
normal (k × the guide's direction); a pin in the slot of a moving bar pushes that bar
with ``N_P`` along its left normal and the pin with the opposite. A load's magnitude is
a given or an unknown (the couple that drives the linkage, a force needed). Gears in
mesh push on each other at their pitch point with the tooth force ``F_A_B`` along the
common tangent t = k × e (e from A's centre to B's), on A, and its opposite on B. With
a pressure angle φ the teeth push along the line of action: besides F along t, a radial
part |F| tan φ through the centres that pushes the gears apart (each toward its own
centre; a ring gear outward), written with the sense of F assumed (positive unless named
in ``reversed_teeth``) and checked after the solve; ideal teeth (no φ) push along t only.

A slider with a mass carries a block (a piston, a collar): a particle at its joint and
a free body of its own. The pin forces ``P_x``, ``P_y`` act on the bar and their
opposites on the block; the guide pushes the block; in a fixed guide ΣF along it = m a
and ΣF across it = 0, on a moving bar ΣF_x = m a_x, ΣF_y = m a_y.

>>> import sympy
>>> from dynsolve.linkage.model import Bar, Drive, Linkage, Load
>>> m = sympy.Symbol("m", positive=True)
>>> rod = Linkage("p.dyn", {"A": (0, 0)}, {}, {}, {"AB": Bar("AB", ("A", "B"), mass=m)},
...               {}, (Drive("omega", "AB", 0), Drive("alpha", "AB", 0)),
...               loads=(Load("couple", "M", "AB"),))
>>> from dynsolve.linkage.relations import relative_motion
>>> r = {"A": (0, 0), "B": (sympy.Integer(2), 0)}
>>> fast, slow = relative_motion(rod, r, "velocity"), relative_motion(rod, r, "acceleration")
>>> free = free_bodies(rod, r, fast, slow, sympy.Symbol("g"), set())
>>> [e.note for e in free.equations], sorted(s.name for s in free.unknowns)
(['ΣF_x = m (a_G)_x (AB)', 'ΣF_y = m (a_G)_y (AB)', 'ΣM_G = I_G α (AB)'], ['A_x', 'A_y', 'M'])
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import sympy

from dynsolve.errors import Position, SpecError
from dynsolve.linkage.model import Linkage
from dynsolve.linkage.relations import Level
from dynsolve.model.scene import Vec
from dynsolve.system import Equation
from dynsolve.units import Dim

FORCE, MOMENT = Dim.of("force"), Dim(2, 1, -2)
ZERO = sympy.Integer(0)


@dataclass(frozen=True)
class FreeBodies:
    """The linkage's Newton–Euler equations, their unknown forces, and each joint's force
    on the bar it is reported for (``force(P)``)."""

    equations: tuple[Equation, ...]
    unknowns: Mapping[sympy.Symbol, Dim]
    at_joint: Mapping[str, Vec]
    dims: Mapping[str, Dim]  # every load's dimension, given or unknown
    normals: Mapping[str, Vec]  # a guide force's name -> the way it pushes the pin


def has_kinetics(linkage: Linkage) -> bool:
    """Whether the linkage carries loads or masses (its forces are to be found)."""
    return (
        bool(linkage.loads)
        or any(b.mass is not None for b in linkage.bars.values())
        or bool(massive_sliders(linkage))
    )


def free_bodies(
    linkage: Linkage,
    r: Mapping[str, Vec],
    velocity: Level,
    acceleration: Level,
    g: sympy.Symbol,
    givens: set[str],
    released: int = 0,
    reversed_teeth: frozenset[str] = frozenset(),
) -> FreeBodies:
    """Newton–Euler for every bar at the positions ``r``, with the motion of the two
    levels; ``givens`` are the names whose magnitude is known; ``released`` bars' α are
    unknowns of the acceleration level that these equations decide; ``reversed_teeth``
    names the tooth forces taken negative for their radial push (pressure angle)."""
    forces: dict[str, list[tuple[Vec, str]]] = {b: [] for b in linkage.bars}  # (F, at)
    unknowns: dict[sympy.Symbol, Dim] = {}
    at_joint: dict[str, Vec] = {}
    normals: dict[str, Vec] = {}

    def unknown(name: str, dim: Dim) -> sympy.Symbol:
        if name in givens:
            raise SpecError(
                f"the given '{name}' has the name of a force of the linkage",
                Position(linkage.file, 1, 1),
                hint="rename the given (dynsolve names pin forces P_x, P_y, guide forces N_P)",
            )
        symbol = sympy.Symbol(name, real=True)
        unknowns[symbol] = dim
        return symbol

    blocks = massive_sliders(linkage)
    forces |= {block_key(p): [] for p in blocks}
    for point in linkage.joints:
        bars = [b.name for b in linkage.bars.values() if point in b.points]
        slider = linkage.sliders.get(point)
        if point in linkage.fixed and len(bars) > 1:
            for bar in bars:
                pair = (unknown(f"{point}_x_{bar}", FORCE), unknown(f"{point}_y_{bar}", FORCE))
                forces[bar].append((pair, point))
            at_joint[point] = forces[bars[0]][-1][0]
            continue
        bodies = bars + [block_key(point)] * (point in blocks)  # a block: the last body
        if point in linkage.fixed or len(bodies) == 2:
            pair = (unknown(f"{point}_x", FORCE), unknown(f"{point}_y", FORCE))
            forces[bodies[0]].append((pair, point))
            if len(bodies) == 2:
                forces[bodies[1]].append(((-pair[0], -pair[1]), point))
            at_joint[point] = pair
        elif len(bodies) > 2:
            total = (ZERO, ZERO)
            for bar in bodies[:-1]:
                pair = (unknown(f"{point}_x_{bar}", FORCE), unknown(f"{point}_y_{bar}", FORCE))
                forces[bar].append((pair, point))
                total = (total[0] + pair[0], total[1] + pair[1])
            forces[bodies[-1]].append(((-total[0], -total[1]), point))
        if slider is not None:
            axis = slider.axis if slider.axis is not None else _slot(linkage, r, slider.bar)
            normal = (-axis[1], axis[0])
            push = unknown(f"N_{point}", FORCE)
            normals[push.name] = normal
            on_pin = (push * normal[0], push * normal[1])
            forces[bodies[-1] if point in blocks else bars[0]].append((on_pin, point))
            if slider.bar:
                forces[slider.bar].append(((-on_pin[0], -on_pin[1]), point))
    teeth: dict[str, sympy.Expr] = {b: ZERO for b in linkage.bars}  # their moments about G
    for mesh in linkage.meshes:  # the tooth force along the common tangent (Hibbeler 17.5)
        one, two = (r[linkage.bars[b].points[0]] for b in (mesh.first, mesh.second))
        e, side = mesh.pitch((one, two), linkage.values, linkage.file)
        t = (-e[1], e[0])
        name = f"F_{mesh.first}_{mesh.second}"
        tooth = unknown(name, FORCE)
        normals[name] = t
        # F t at the pitch point r₁ e₁ from A's centre: moment r₁ e₁ × F t = r₁ F (ccw); on B,
        # −F t at r₂ e₂ from its centre: −r₂ F (e₂·e₁), so r₂ F (ccw) in external mesh
        forces[mesh.first].append(((tooth * t[0], tooth * t[1]), "G"))
        forces[mesh.second].append(((-tooth * t[0], -tooth * t[1]), "G"))
        if mesh.pressure is not None:  # the radial push |F| tan φ along the line of centres
            size = (-1 if name in reversed_teeth else 1) * tooth * sympy.tan(mesh.pressure)
            out = 1 if mesh.internal and mesh.ring_first(linkage.values, linkage.file) else -1
            radial = (out * size * e[0], out * size * e[1])  # on the first gear, through G
            forces[mesh.first].append((radial, "G"))
            forces[mesh.second].append(((-radial[0], -radial[1]), "G"))
        teeth[mesh.first] += mesh.radii[0] * tooth
        teeth[mesh.second] += -side * mesh.radii[1] * tooth
    for wheel in linkage.wheels.values():  # the ground's friction and normal push at K
        n = wheel.normal
        tangent = (n[1], -n[0])
        friction = unknown(f"F_{wheel.bar}", FORCE)
        normal = unknown(f"N_{wheel.bar}", FORCE)
        push = (friction * tangent[0] + normal * n[0], friction * tangent[1] + normal * n[1])
        forces[wheel.bar].append((push, "K"))
        normals[normal.name] = n
        normals[friction.name] = tangent
    couples: dict[str, sympy.Expr] = dict(teeth)  # a tooth force's moment, then the couples
    dims: dict[str, Dim] = {}
    for load in linkage.loads:
        if load.kind == "gravity":
            continue
        dim = MOMENT if load.kind == "couple" else FORCE
        dims[load.name] = dim
        size = sympy.Symbol(load.name, real=True) if load.name not in givens else None
        if size is not None:
            unknowns[size] = dim
        magnitude = size if size is not None else linkage.symbols[load.name]
        if load.kind == "couple":
            couples[load.bar] += load.sense * magnitude
        else:
            assert load.direction is not None
            vector = (magnitude * load.direction[0], magnitude * load.direction[1])
            body = load.bar if load.bar in linkage.bars else block_key(load.bar)
            forces[body].append((vector, load.point))
    gravity = next((load for load in linkage.loads if load.kind == "gravity"), None)
    equations: list[Equation] = []
    for bar in linkage.bars.values():
        first = bar.points[0]
        G, I_G = mass_centre(linkage, bar.name, r)
        where = dict(r) | {"G": G}  # a slot's push acts at the pin riding in it
        if bar.name in linkage.wheels:
            wheel = linkage.wheels[bar.name]
            where["K"] = (
                G[0] - wheel.radius * wheel.normal[0],
                G[1] - wheel.radius * wheel.normal[1],
            )
        m = bar.mass if bar.mass is not None else ZERO
        applied = list(forces[bar.name])
        if gravity is not None and m != 0:
            assert gravity.direction is not None
            applied.append(((m * g * gravity.direction[0], m * g * gravity.direction[1]), "G"))
        dx, dy = G[0] - r[first][0], G[1] - r[first][1]
        w, alpha = velocity.rotation[bar.name], acceleration.rotation[bar.name]
        a_P = acceleration.rate[first]
        a_G = (a_P[0] - alpha * dy - w**2 * dx, a_P[1] + alpha * dx - w**2 * dy)
        total = [sum((f[0][k] for f in applied), ZERO) for k in (0, 1)]
        moment = couples[bar.name] + sum(
            (
                (where[at][0] - G[0]) * F[1] - (where[at][1] - G[1]) * F[0]
                for F, at in applied
                if at != "G"
            ),
            ZERO,
        )
        for axis, lhs, rhs in (("x", total[0], m * a_G[0]), ("y", total[1], m * a_G[1])):
            note = f"ΣF_{axis} = m (a_G)_{axis} ({bar.name})"
            equations.append(Equation(lhs, rhs, note, bar.line, note))
        note = f"ΣM_G = I_G α ({bar.name})"
        equations.append(Equation(moment, I_G * alpha, note, bar.line, note))
    for point, m in blocks.items():  # a block (piston, collar): a particle at its joint
        applied = list(forces[block_key(point)])
        if gravity is not None:
            assert gravity.direction is not None
            applied.append(((m * g * gravity.direction[0], m * g * gravity.direction[1]), point))
        equations += _block_equations(linkage, point, m, applied, acceleration)
    _check_count(linkage, unknowns, equations, released)
    return FreeBodies(tuple(equations), unknowns, at_joint, dims, normals)


def massive_sliders(linkage: Linkage) -> dict[str, sympy.Expr]:
    """Each slider joint that carries a block with mass (a piston, a collar): its mass."""
    return {p: s.mass for p, s in linkage.sliders.items() if s.mass is not None}


def block_key(point: str) -> str:
    """The free body of the block at slider ``point`` (a name no bar can have)."""
    return f"block {point}"


def _block_equations(
    linkage: Linkage,
    point: str,
    m: sympy.Expr,
    applied: list[tuple[Vec, str]],
    acceleration: Level,
) -> list[Equation]:
    """Newton's law for the block at ``point`` (Hibbeler 17.2, a particle in translation):
    in a fixed guide, ΣF along it = m a and ΣF normal to it = 0 (the guide does not move);
    on a moving bar, ΣF_x = m a_x and ΣF_y = m a_y with a the joint's acceleration."""
    slider = linkage.sliders[point]
    line = slider.line
    total = [sum((F[k] for F, _ in applied), ZERO) for k in (0, 1)]
    if slider.axis is not None:
        e = slider.axis
        along = sympy.expand(total[0] * e[0] + total[1] * e[1])
        across = sympy.expand(-total[0] * e[1] + total[1] * e[0])
        notes = (
            f"ΣF along the guide = m a_{point} (block {point})",
            f"ΣF across the guide = 0 (block {point})",
        )
        return [
            Equation(along, m * acceleration.along[point], notes[0], line, notes[0]),
            Equation(across, ZERO, notes[1], line, notes[1]),
        ]
    a = acceleration.rate[point]
    notes = [f"ΣF_{axis} = m (a_{point})_{axis} (block {point})" for axis in "xy"]
    return [Equation(total[k], m * a[k], notes[k], line, notes[k]) for k in (0, 1)]


def mass_centre(linkage: Linkage, name: str, r: Mapping[str, Vec]) -> tuple[Vec, sympy.Expr]:
    """A bar's G and I_G: a wheel or gear at its centre (a uniform disk, m ρ²/2, unless
    a gyration is given), any other bar halfway between its two points (m L²/12)."""
    bar = linkage.bars[name]
    m = bar.mass if bar.mass is not None else ZERO
    first = bar.points[0]
    if linkage.round(name):
        radius = (
            linkage.wheels[name].radius
            if name in linkage.wheels
            else next(
                mesh.radii[0] if mesh.first == name else mesh.radii[1]
                for mesh in linkage.meshes
                if name in (mesh.first, mesh.second)
            )
        )
        k_sq = bar.gyration**2 if bar.gyration is not None else radius**2 / 2
        return r[first], m * k_sq
    second = bar.points[1]
    G = ((r[first][0] + r[second][0]) / 2, (r[first][1] + r[second][1]) / 2)
    length_sq = (r[second][0] - r[first][0]) ** 2 + (r[second][1] - r[first][1]) ** 2
    return G, m * (bar.gyration**2 if bar.gyration is not None else length_sq / 12)


def _slot(linkage: Linkage, r: Mapping[str, Vec], bar: str) -> Vec:
    first, second = linkage.bars[bar].points[:2]
    dx, dy = r[second][0] - r[first][0], r[second][1] - r[first][1]
    length = sympy.sqrt(dx**2 + dy**2)
    return (dx / length, dy / length)


def _check_count(
    linkage: Linkage,
    unknowns: Mapping[sympy.Symbol, Dim],
    equations: list[Equation],
    released: int = 0,
) -> None:
    """As many unknown forces as equations (three per bar), less one per ``released`` α:
    else the forces are not determined (a driving couple missing) or over-determined (a
    load given twice, or a driving load to find beside an α the loads decide)."""
    if len(unknowns) + released == len(equations):
        return
    named = ", ".join(s.name for s in unknowns)
    fewer = len(unknowns) + released < len(equations)
    if released and not fewer:
        raise SpecError(
            f"the linkage's motion is left to its loads (no 'alpha' for "
            f"{released} driven bar{'s' * (released > 1)}), but a load is also to be found: "
            f"{len(unknowns)} unknown forces and couples ({named}) and {released} α for "
            f"{len(equations)} equations",
            linkage.where(next(iter(linkage.bars))),
            hint="give the driven bar's α ('alpha AB: 0' for a constant ω) to find the load "
            "that drives it, or give every load to find the α",
        )
    what = (
        "cannot balance: a driving couple or force is missing"
        if fewer
        else "are not determined (statically indeterminate)"
    )
    raise SpecError(
        f"the linkage's forces {what}: {len(unknowns)} unknown forces and couples "
        f"({named}) for {len(equations)} equations (three per bar, two per block)",
        linkage.where(next(iter(linkage.bars))),
        hint="name the load that drives it as an unknown (e.g. 'couple M on AB: ccw' and find M)"
        if fewer
        else "give the magnitude of a load (a given), or remove a joint's freedom",
    )


def power_balance(
    linkage: Linkage,
    r: Mapping[str, Vec],
    velocity: Level,
    acceleration: Level,
    g: sympy.Symbol,
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> tuple[float, float] | None:
    """The power equation, a check independent of the pin forces: the loads' power
    (couples M ω, forces F·v, gravity m g·v_G) against the rate of change of the kinetic
    energy, Σ (m v_G·a_G + I_G ω α). None when a value is symbolic or unsolved.

    Pin and guide forces drop out (equal and opposite at a pin; normal to the motion at
    a smooth guide or slot), so an error in them or in a_G shows here."""
    gravity = next((load for load in linkage.loads if load.kind == "gravity"), None)
    supplied: sympy.Expr = ZERO
    stored: sympy.Expr = ZERO
    for bar in linkage.bars.values():
        first = bar.points[0]
        G, I_G = mass_centre(linkage, bar.name, r)
        h = (G[0] - r[first][0], G[1] - r[first][1])
        w, alpha = velocity.rotation[bar.name], acceleration.rotation[bar.name]
        v_P, a_P = velocity.rate[first], acceleration.rate[first]
        v_G = (v_P[0] - w * h[1], v_P[1] + w * h[0])
        a_G = (a_P[0] - alpha * h[1] - w**2 * h[0], a_P[1] + alpha * h[0] - w**2 * h[1])
        m = bar.mass if bar.mass is not None else ZERO
        stored += m * (v_G[0] * a_G[0] + v_G[1] * a_G[1]) + I_G * w * alpha
        if gravity is not None and m != 0:
            assert gravity.direction is not None
            supplied += m * g * (gravity.direction[0] * v_G[0] + gravity.direction[1] * v_G[1])
        for load in linkage.loads:
            if load.bar != bar.name:
                continue
            size = sympy.Symbol(load.name, real=True)
            size = size if size in values else linkage.symbols.get(load.name, size)
            if load.kind == "couple":
                supplied += load.sense * size * w
            else:
                assert load.direction is not None
                v = v_G if load.point == "G" else velocity.rate[load.point]
                supplied += size * (load.direction[0] * v[0] + load.direction[1] * v[1])
    for point, m in massive_sliders(linkage).items():  # each block: ½ m v² and its loads
        v, a = velocity.rate[point], acceleration.rate[point]
        stored += m * (v[0] * a[0] + v[1] * a[1])
        pushes = [(m * g, gravity.direction)] if gravity is not None else []
        for load in linkage.loads:
            if load.kind == "force" and load.bar == point and point not in linkage.bars:
                size = sympy.Symbol(load.name, real=True)
                size = size if size in values else linkage.symbols.get(load.name, size)
                pushes.append((size, load.direction))
        for size, direction in pushes:
            assert direction is not None
            supplied += size * (direction[0] * v[0] + direction[1] * v[1])
    numbers = []
    for side in (supplied, stored):
        value = (sympy.Integer(0) + side).xreplace(dict(values))
        value = value.xreplace(dict(values))  # derived quantities hold givens
        if value.free_symbols:
            return None
        numbers.append(float(sympy.N(value, 20)))
    return numbers[0], numbers[1]
