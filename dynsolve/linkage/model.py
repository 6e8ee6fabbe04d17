"""The linkage of a scene: its bars, fixed and moving joints, sliders and drives.

Read from the scene lines ``point``, ``bar``, ``joint``, ``slider``, ``omega``, ``alpha``,
``velocity``, ``acceleration`` and ``branch`` (docs/scene-mode.md, *Linkages*). A point
named in a bar is a pin joining every bar that names it; a fixed ``point`` is a pin to
the ground. Positions are sympy expressions of the givens.

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec('''
... given:
...   L = 0.2 m
...   theta = 45 deg
... scene:
...   point A: (0, 0)
...   bar AB: A to B, length L, angle theta
...   omega AB: 0 cw
... find: w = omega(AB)
... ''', "p.dyn")
>>> linkage = read_linkage(spec)
>>> linkage.bars["AB"].points, linkage.fixed["A"]
(('A', 'B'), (0, 0))
"""

from __future__ import annotations

import difflib
from collections.abc import Mapping
from dataclasses import dataclass, field, replace

import sympy

from dynsolve.errors import Position, SpecError
from dynsolve.model.physical import NOT_NEGATIVE, POSITIVE
from dynsolve.model.scene import SceneReader, Vec, scene_reader
from dynsolve.modes.equation_mode import givens_of
from dynsolve.spec.ast import Prop, SceneStmt, Spec
from dynsolve.units import Dim

LENGTH = Dim.of("length")
UP: Vec = (sympy.Integer(0), sympy.Integer(1))
RATES = {
    "omega": Dim(0, 0, -1),
    "alpha": Dim(0, 0, -2),
    "velocity": Dim.of("velocity"),
    "acceleration": Dim.of("acceleration"),
}
LINKAGE_LINES = frozenset(
    {"point", "bar", "joint", "slider", "omega", "alpha", "velocity", "acceleration", "branch"}
    | {"method"}
    | {"gravity", "couple", "force", "wheel", "mesh"}
)


@dataclass(frozen=True)
class Bar:
    """A rigid link through ``points`` (in order); ``angle`` is the direction from the
    first point to the second (ccw from +x), ``length`` their distance."""

    name: str
    points: tuple[str, ...]
    length: sympy.Expr | None = None
    angle: sympy.Expr | None = None
    line: int = 0
    column: int = 0
    mass: sympy.Expr | None = None  # a uniform bar: G halfway between its two points
    gyration: sympy.Expr | None = None  # about G; default L/√12 (a slender rod)


@dataclass(frozen=True)
class Slider:
    """A joint that slides in a fixed straight guide along ``axis`` through ``through``
    (a fixed point or given joint; empty: through the joint's own given position), or,
    when ``bar`` is set, along that moving bar (a pin in its slot, a collar on it).
    With a ``mass``, the joint carries a block of that mass (a piston, a collar): a
    particle at the joint, its own free body."""

    point: str
    axis: Vec | None
    through: str = ""
    line: int = 0
    column: int = 0
    bar: str = ""
    mass: sympy.Expr | None = None


@dataclass(frozen=True)
class Drive:
    """A given motion: ``omega``/``alpha`` of a bar (ccw-signed value) or the
    ``velocity``/``acceleration`` of a joint (magnitude ``value`` along ``direction``)."""

    kind: str
    name: str
    value: sympy.Expr
    direction: Vec | None = None
    line: int = 0
    column: int = 0


@dataclass(frozen=True)
class Load:
    """A load on a bar: gravity on every bar with mass, a ``couple`` (``sense`` +1 ccw,
    −1 cw) or a ``force`` at a point of the bar along ``direction``; ``name`` is its
    magnitude, a given or an unknown to find."""

    kind: str
    name: str
    bar: str = ""
    point: str = ""
    direction: Vec | None = None
    sense: int = 1
    line: int = 0
    column: int = 0


@dataclass(frozen=True)
class Wheel:
    """A bar that is a wheel centred on its first point, rolling without slipping on
    fixed ground: it touches it at ``radius`` from the centre, against ``normal``."""

    bar: str
    radius: sympy.Expr
    normal: Vec
    line: int = 0
    column: int = 0


@dataclass(frozen=True)
class Mesh:
    """Two gears (bars centred on their first points) in mesh: their pitch circles, of
    radii ``radii``, roll on each other where they touch, outside each other (external)
    or the smaller inside the larger, a ring gear (``internal``)."""

    first: str
    second: str
    radii: tuple[sympy.Expr, sympy.Expr]
    line: int = 0
    column: int = 0
    internal: bool = False
    pressure: sympy.Expr | None = None  # the pressure angle φ; None: ideal teeth (φ = 0)

    @property
    def tooth(self) -> str:
        """The name of the tooth force's tangential component, ``F_A_B``."""
        return f"F_{self.first}_{self.second}"

    def pitch(
        self, centres: tuple[Vec, Vec], values: Mapping[sympy.Symbol, sympy.Expr], file: str = ""
    ) -> tuple[Vec, int]:
        """The unit vector e₁ from the first gear's centre toward the pitch point, and
        e₂·e₁ (−1 external: the point is between the centres; +1 internal: beyond the
        smaller gear, seen from the ring's centre).

        >>> import sympy
        >>> two = Mesh("A", "B", (sympy.Integer(1), sympy.Integer(3)))
        >>> two.pitch(((0, 0), (4, 0)), {})
        ((1, 0), -1)
        >>> ring = Mesh("R", "P", (sympy.Integer(3), sympy.Integer(1)), internal=True)
        >>> ring.pitch(((0, 0), (2, 0)), {})  # the pitch point (3, 0): beyond the planet
        ((1, 0), 1)
        """
        (x1, y1), (x2, y2) = centres
        r1, r2 = self.radii
        if not self.internal:
            span = r1 + r2
            return ((x2 - x1) / span, (y2 - y1) / span), -1
        ring_first = self.ring_first(values, file)
        span = r1 - r2 if ring_first else r2 - r1  # the centres' distance
        # from the ring's centre toward the smaller gear's: the pitch point lies that way
        u = (
            ((x2 - x1) / span, (y2 - y1) / span)
            if ring_first
            else ((x1 - x2) / span, (y1 - y2) / span)
        )
        return u, 1

    def ring_first(self, values: Mapping[sympy.Symbol, sympy.Expr], file: str = "") -> bool:
        """Whether the first gear of an internal mesh is the ring (the larger radius)."""
        from dynsolve.numbers import real_value

        sizes = [real_value(r, values) for r in self.radii]
        if sizes[0] is None or sizes[1] is None or sizes[0] == sizes[1]:
            raise SpecError(
                f"the internal mesh of {self.first} and {self.second} needs radii with values, "
                "one larger (the ring)",
                Position(file, self.line, self.column),
                hint="give the radii numbers",
            )
        return sizes[0] > sizes[1]

    def span(self, values: Mapping[sympy.Symbol, sympy.Expr], file: str = "") -> sympy.Expr:
        """The distance between the centres: r₁ + r₂, or the difference for a ring gear."""
        r1, r2 = self.radii
        if not self.internal:
            return r1 + r2
        return r1 - r2 if self.ring_first(values, file) else r2 - r1


@dataclass(frozen=True)
class Linkage:
    """A scene's linkage as written: what is fixed, what is given and what moves."""

    file: str
    fixed: Mapping[str, Vec]
    given: Mapping[str, Vec]  # joints placed exactly at the instant
    near: Mapping[str, Vec]  # joints placed roughly (the assembly nearest is taken)
    bars: Mapping[str, Bar]
    sliders: Mapping[str, Slider]
    drives: tuple[Drive, ...]
    branch: str = ""
    symbols: Mapping[str, sympy.Symbol] = field(default_factory=dict)
    values: Mapping[sympy.Symbol, sympy.Expr] = field(default_factory=dict)
    declared: Mapping[str, tuple[int, int]] = field(default_factory=dict)
    loads: tuple[Load, ...] = ()
    wheels: Mapping[str, Wheel] = field(default_factory=dict)
    meshes: tuple[Mesh, ...] = ()
    method: str = ""  # "ic": velocities by instantaneous centres; "" or "relative": v = v + ω × r

    def round(self, bar: str) -> bool:
        """Whether the bar is a wheel or a gear (its G and turning centre: its first point)."""
        return bar in self.wheels or any(bar in (m.first, m.second) for m in self.meshes)

    @property
    def joints(self) -> tuple[str, ...]:
        """Every point a bar names, fixed or moving, in order of first mention."""
        seen: dict[str, None] = {}
        for bar in self.bars.values():
            seen |= dict.fromkeys(bar.points)
        return tuple(seen)

    @property
    def moving(self) -> tuple[str, ...]:
        """The joints that are not fixed to the ground."""
        return tuple(p for p in self.joints if p not in self.fixed)

    def where(self, name: str) -> Position:
        """Where ``name`` (a bar or point) was declared, for errors."""
        line, column = self.declared.get(name, (1, 1))
        return Position(self.file, line, column)

    def drive(self, kind: str, name: str) -> Drive | None:
        """The drive of this kind on a bar or joint, if the scene gives one."""
        return next((d for d in self.drives if d.kind == kind and d.name == name), None)


def is_linkage(spec: Spec) -> bool:
    """Whether a spec's scene describes a linkage (it has ``bar`` lines).

    >>> from dynsolve.spec.parser import parse_spec
    >>> is_linkage(parse_spec("scene:\\n  bar AB: A to B\\nfind: w = omega(AB)\\n"))
    True
    """
    return any(stmt.kind == "bar" for stmt in spec.scene or ())


def read_linkage(spec: Spec) -> Linkage:
    """The linkage of ``spec``'s scene; a positioned SpecError for a line it cannot take."""
    givens = givens_of(spec)
    symbols = {g.name: g.symbol for g in givens}
    values = {g.symbol: g.value for g in givens if g.value is not None}
    reader = scene_reader(spec, symbols, {g.name: g.dim for g in givens}, values)
    fixed: dict[str, Vec] = {}
    given: dict[str, Vec] = {}
    near: dict[str, Vec] = {}
    bars: dict[str, Bar] = {}
    sliders: dict[str, Slider] = {}
    drives: list[Drive] = []
    loads: list[Load] = []
    wheels: dict[str, Wheel] = {}
    meshes: list[Mesh] = []
    branch = method = ""
    declared: dict[str, tuple[int, int]] = {}
    mentioned: dict[str, tuple[int, int]] = {}  # a joint's first bar line
    statements = tuple(spec.scene or ())
    pending: list[SceneStmt] = []
    for stmt in statements:
        where = Position(spec.file, stmt.line, stmt.column)
        if stmt.kind not in LINKAGE_LINES:
            raise SpecError(
                f"a '{stmt.kind}' line cannot go in a linkage scene (one with bars)",
                where,
                hint="a linkage takes point, bar, joint, slider, omega, alpha, velocity, "
                "acceleration, branch, method, gravity, couple and force lines (see "
                "docs/scene-mode.md, Linkages)",
            )
        if stmt.kind == "point":
            if stmt.body:
                raise SpecError(
                    "in a linkage, a point of a bar is a joint the bar names",
                    where,
                    hint=f"name it in the bar ('bar {stmt.body}: … to {stmt.name}') and place "
                    f"it with 'joint {stmt.name}: (x, y)'",
                )
            _new(stmt.name, declared, where, "point")
            fixed[stmt.name] = reader.vector(stmt.vectors[0], "a position")
        elif stmt.kind == "bar":
            _new(stmt.name, declared, where, "bar")
            bars[stmt.name] = _bar(stmt, reader, where)
            for joint in bars[stmt.name].points:  # for errors about a joint no line places
                mentioned.setdefault(joint, (stmt.line, stmt.column))
    for stmt in statements:
        where = Position(spec.file, stmt.line, stmt.column)
        if stmt.kind == "joint":
            _joint_named(stmt.name, bars, fixed, where)
            (near if stmt.word == "near" else given)[stmt.name] = reader.vector(
                stmt.vectors[0], "a position"
            )
            declared.setdefault(stmt.name, (stmt.line, stmt.column))
        elif stmt.kind == "slider":
            _joint_named(stmt.name, bars, fixed, where)
            if stmt.name in sliders:
                raise SpecError(f"joint {stmt.name} has two sliders", where, "keep one")
            mass = _mass(stmt.props[0], reader, symbols, where) if stmt.props else None
            if stmt.body:
                sliders[stmt.name] = replace(_on_bar(stmt, bars, where), mass=mass)
                continue
            assert stmt.direction is not None
            axis = reader.direction(stmt.direction)
            sliders[stmt.name] = Slider(
                stmt.name, axis, stmt.other, stmt.line, stmt.column, mass=mass
            )
        elif stmt.kind in RATES:
            drives.append(_drive(stmt, reader, bars, fixed, where))
        elif stmt.kind == "branch":
            branch = stmt.word
        elif stmt.kind == "method":
            method = stmt.word
        elif stmt.kind in ("gravity", "couple", "force"):
            pending.append(stmt)  # read once every slider is known (a load on a block)
        elif stmt.kind == "wheel":
            _bar_named(stmt.body, bars, where)
            assert stmt.value is not None
            normal = reader.direction(stmt.direction) if stmt.direction else UP
            radius = reader.value(stmt.value, LENGTH, "a wheel's radius", POSITIVE)
            wheels[stmt.body] = Wheel(stmt.body, radius, normal, stmt.line, stmt.column)
        elif stmt.kind == "mesh":
            _bar_named(stmt.body, bars, where)
            _bar_named(stmt.other, bars, where)
            radii = tuple(
                reader.value(e, LENGTH, "a gear's radius", POSITIVE) for e in stmt.vectors[0]
            )
            internal = stmt.word == "internal"
            pressure = reader.value(stmt.value, Dim(), "a pressure angle") if stmt.value else None
            meshes.append(
                Mesh(stmt.body, stmt.other, radii, stmt.line, stmt.column, internal, pressure)  # type: ignore[arg-type]
            )
    for stmt in pending:
        where = Position(spec.file, stmt.line, stmt.column)
        loads.append(_load(stmt, reader, bars, where, sliders))
    for bar in bars.values():
        round_bar = bar.name in wheels or any(bar.name in (m.first, m.second) for m in meshes)
        if bar.mass is not None and len(bar.points) != 2 and not round_bar:
            raise SpecError(
                f"bar {bar.name}: a mass is taken as a uniform bar between two points",
                Position(spec.file, bar.line, bar.column),
                hint="give a bar with mass two points (its ends), or make it a wheel",
            )
        if len(bar.points) == 1 and not round_bar:
            raise SpecError(
                f"bar {bar.name} has one point: only a wheel or a gear may",
                Position(spec.file, bar.line, bar.column),
                hint=f"name its other end ('bar {bar.name}: {bar.points[0]} to B'), or make it "
                f"a wheel ('rolls {bar.name}: radius r') or a gear ('mesh …')",
            )
    for slider in sliders.values():
        if slider.through and slider.through not in fixed and slider.through not in given:
            raise SpecError(
                f"the guide of slider {slider.point} passes through '{slider.through}', "
                "which is neither a fixed point nor a placed joint",
                Position(spec.file, slider.line, slider.column),
                hint=f"declare 'point {slider.through}: (x, y)'",
            )
    return Linkage(
        spec.file,
        fixed,
        given,
        near,
        bars,
        sliders,
        tuple(drives),
        branch,
        symbols,
        values,
        {**mentioned, **declared},
        tuple(loads),
        wheels,
        tuple(meshes),
        method,
    )


def _new(name: str, declared: dict[str, tuple[int, int]], where: Position, what: str) -> None:
    if name in declared:
        line, _ = declared[name]
        raise SpecError(f"'{name}' is declared twice (first on line {line})", where, "rename one")
    declared[name] = (where.line, where.column)


def _bar(stmt: SceneStmt, reader: SceneReader, where: Position) -> Bar:
    points = tuple(stmt.other.split())
    if len(set(points)) != len(points):
        raise SpecError(f"bar {stmt.name} names a point twice", where, "list each point once")
    props = {p.key: p for p in stmt.props}
    if len(props) != len(stmt.props):
        raise SpecError(f"bar {stmt.name} has a property twice", where, "keep one")
    if len(points) > 2 and {"length", "angle"} & set(props):
        raise SpecError(
            f"bar {stmt.name} has {len(points)} points: its shape comes from their positions",
            where,
            hint="place each point with 'joint P: (x, y)' instead of a length or angle",
        )
    length = angle = mass = gyration = None
    if "mass" in props and "weight" in props:
        raise SpecError(f"bar {stmt.name} has a mass and a weight", where, "keep one")
    for key in ("mass", "weight"):
        if key in props:
            mass = _mass(props[key], reader, reader.symbols, where)
    if "gyration" in props:
        if mass is None:
            raise SpecError(f"bar {stmt.name}: a gyration needs a mass", where, "add 'mass m'")
        gyration = reader.value(
            props["gyration"].values[0], LENGTH, "a radius of gyration", POSITIVE
        )
    if "length" in props:
        length = reader.value(props["length"].values[0], LENGTH, "a bar's length", POSITIVE)
    if "angle" in props:
        angle = reader.value(props["angle"].values[0], Dim(), "a bar's angle")
    return Bar(stmt.name, points, length, angle, stmt.line, stmt.column, mass, gyration)


def _mass(prop: Prop, reader: SceneReader, symbols: Mapping, where: Position) -> sympy.Expr:
    """A bar's or a block's mass: ``mass m``, or ``weight W`` (m = W/g, as a body's)."""
    if prop.key == "mass":
        return reader.value(prop.values[0], Dim.of("mass"), "a mass", NOT_NEGATIVE)
    g = symbols.get("g")
    if g is None:
        raise SpecError("a weight needs g", where, "give 'g' or write the mass ('mass m')")
    return reader.value(prop.values[0], Dim.of("force"), "a weight", NOT_NEGATIVE) / g


def _joint_named(
    name: str, bars: Mapping[str, Bar], fixed: Mapping[str, Vec], where: Position
) -> None:
    named = {p for bar in bars.values() for p in bar.points}
    if name in named and name not in fixed:
        return
    if name in fixed:
        raise SpecError(
            f"'{name}' is a fixed point: it does not move",
            where,
            hint="a joint line places a moving joint; fixed points are placed by 'point'",
        )
    close = difflib.get_close_matches(name, sorted(named), n=1)
    hint = f"did you mean '{close[0]}'?" if close else "name it in a bar first ('bar AB: A to B')"
    raise SpecError(f"no bar has a joint '{name}'", where, hint)


def _load(
    stmt: SceneStmt,
    reader: SceneReader,
    bars: Mapping[str, Bar],
    where: Position,
    sliders: Mapping[str, Slider],
) -> Load:
    """``gravity [: DIR]``, ``couple M on BAR: cw|ccw``, ``force P on BAR at JOINT: DIR``
    or ``force P on C at C: DIR`` (on the block of the massive slider C)."""
    if stmt.kind == "gravity":
        direction = reader.direction(stmt.direction) if stmt.direction else (0, -1)
        return Load("gravity", "g", direction=direction, line=stmt.line, column=stmt.column)
    block = sliders.get(stmt.body)
    if stmt.kind == "force" and stmt.body not in bars and block is not None:
        assert stmt.location is not None and stmt.direction is not None
        if block.mass is None or stmt.location.point != stmt.body:
            raise SpecError(
                f"force {stmt.name} on {stmt.body}: a force on a slider acts on its block, at "
                "the joint, and needs the block's mass",
                where,
                hint=f"write 'force {stmt.name} on {stmt.body} at {stmt.body}: DIR' and give "
                f"the block a mass ('slider {stmt.body}: …, mass m'), or put the force on a "
                "bar at the joint",
            )
        direction = reader.direction(stmt.direction)
        return Load("force", stmt.name, stmt.body, stmt.body, direction, 1, stmt.line, stmt.column)
    if stmt.body not in bars:
        close = difflib.get_close_matches(stmt.body, sorted(bars), n=1)
        raise SpecError(
            f"there is no bar '{stmt.body}'",
            where,
            hint=f"did you mean '{close[0]}'?" if close else "a load acts on a bar",
        )
    if stmt.kind == "couple":
        sense = -1 if stmt.word == "cw" else 1
        return Load("couple", stmt.name, stmt.body, sense=sense, line=stmt.line, column=stmt.column)
    assert stmt.location is not None and stmt.direction is not None
    point = stmt.location.point
    if point not in (*bars[stmt.body].points, "G"):
        raise SpecError(
            f"force {stmt.name} acts at '{point or 'a position'}', not a point of bar {stmt.body}",
            where,
            hint=f"apply it at one of {', '.join(bars[stmt.body].points)} or G",
        )
    return Load(
        "force",
        stmt.name,
        stmt.body,
        point,
        reader.direction(stmt.direction),
        line=stmt.line,
        column=stmt.column,
    )


def _bar_named(name: str, bars: Mapping[str, Bar], where: Position) -> None:
    if name not in bars:
        close = difflib.get_close_matches(name, sorted(bars), n=1)
        hint = f"did you mean '{close[0]}'?" if close else "declare it with 'bar NAME: O to …'"
        raise SpecError(f"there is no bar '{name}'", where, hint)


def _on_bar(stmt: SceneStmt, bars: Mapping[str, Bar], where: Position) -> Slider:
    """``slider B: along bar CD``: B must not be a point of CD itself (it slides on it)."""
    if stmt.body not in bars:
        close = difflib.get_close_matches(stmt.body, sorted(bars), n=1)
        raise SpecError(
            f"there is no bar '{stmt.body}'",
            where,
            hint=f"did you mean '{close[0]}'?" if close else "name the bar it slides along",
        )
    if stmt.name in bars[stmt.body].points:
        raise SpecError(
            f"{stmt.name} is a point of bar {stmt.body}, so it cannot slide along it",
            where,
            hint=f"leave {stmt.name} out of 'bar {stmt.body}: …' (it is a pin of another "
            "bar, riding in the slot)",
        )
    return Slider(stmt.name, None, "", stmt.line, stmt.column, stmt.body)


def _drive(
    stmt: SceneStmt,
    reader: SceneReader,
    bars: Mapping[str, Bar],
    fixed: Mapping[str, Vec],
    where: Position,
) -> Drive:
    assert stmt.value is not None
    value = reader.value(stmt.value, RATES[stmt.kind], f"an {stmt.kind}")
    if stmt.kind in ("omega", "alpha"):
        if stmt.body not in bars:
            close = difflib.get_close_matches(stmt.body, sorted(bars), n=1)
            hint = f"did you mean '{close[0]}'?" if close else "name a bar"
            raise SpecError(f"there is no bar '{stmt.body}'", where, hint)
        signed = -value if stmt.word == "cw" else value
        return Drive(stmt.kind, stmt.body, signed, None, stmt.line, stmt.column)
    _joint_named(stmt.body, bars, fixed, where)
    assert stmt.direction is not None
    direction = reader.direction(stmt.direction)
    return Drive(stmt.kind, stmt.body, value, direction, stmt.line, stmt.column)
