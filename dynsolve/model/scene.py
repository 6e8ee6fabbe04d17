"""Build the physical model of a scene from its spec lines: bodies, points, supports, loads.

Every expression is checked for its dimension (a mass is a mass, a position a length)
and every name for existence, with the spec line and column in the error; positions
become absolute scene coordinates (sympy, in terms of the givens).

>>> from dynsolve.spec.parser import parse_spec
>>> from dynsolve.units import Dim
>>> import sympy
>>> m, r = sympy.symbols("m r", positive=True)
>>> text = "scene:\\n  point O: (0, 0)\\n  body drum: mass m, disk r\\n  pin drum at O"
>>> spec = parse_spec(text, "s.dyn")
>>> scene = build_scene(spec, {"m": m, "r": r}, {"m": Dim.of("mass"), "r": Dim.of("length")})
>>> scene.bodies["drum"].I_G
m*r**2/2
"""

from __future__ import annotations

import difflib
from collections import Counter
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

import sympy

from dynsolve.dimensions import check_dimensions, constant_value
from dynsolve.errors import DimensionError, Position, SpecError
from dynsolve.expressions import to_sympy
from dynsolve.model.inertia import Part, composite, from_gyration, inertia_about_G, to_G
from dynsolve.model.momentum_events import Clutch, Reshape
from dynsolve.model.physical import NOT_NEGATIVE, POSITIVE, check_sign, check_some_mass

if TYPE_CHECKING:
    from dynsolve.system import Constraint
from dynsolve.numbers import light_tidying, real_value, tidy
from dynsolve.spec.ast import Direction, EquationStmt, Expr, Location, Name, Prop, SceneStmt, Spec
from dynsolve.spec.parser import iter_names
from dynsolve.spec.printing import expr_text
from dynsolve.units import Dim

Vec = tuple[sympy.Expr, sympy.Expr]
ZERO: Vec = (sympy.Integer(0), sympy.Integer(0))
WORDS: dict[str, Vec] = {
    "up": (sympy.Integer(0), sympy.Integer(1)),
    "down": (sympy.Integer(0), sympy.Integer(-1)),
    "right": (sympy.Integer(1), sympy.Integer(0)),
    "left": (sympy.Integer(-1), sympy.Integer(0)),
}
LENGTH, MASS, FORCE = Dim.of("length"), Dim.of("mass"), Dim.of("force")
LINKAGE_ONLY = {  # scene lines of a linkage (dynsolve.linkage), as written
    "joint": "joint",
    "slider": "slider",
    "alpha": "alpha",
    "acceleration": "acceleration",
    "branch": "branch",
    "method": "method",
    "wheel": "rolls …: radius",
    "mesh": "mesh",
}
GROUND = "ground"  # `impact B with ground`: the fixed surface (unless a body is so named)


@dataclass(frozen=True)
class Body:
    """A rigid body or particle: mass, I about G (z axis), G and its named points."""

    name: str
    mass: sympy.Expr
    I_G: sympy.Expr
    G: Vec  # absolute
    origin: Vec  # absolute: where body-relative positions are measured from ('at')
    shape: str
    sizes: tuple[sympy.Expr, ...]
    points: Mapping[str, Vec]  # absolute positions of the body's named points
    particle: bool
    inertia_note: str  # how I_G was found (shape formula, gyration, composite lines)
    line: int
    column: int
    parts: tuple[Part, ...] = ()  # a composite's parts and holes, placed from ``origin``

    @property
    def radius(self) -> sympy.Expr | None:
        """The radius of a round body (disk, ring, cylinder, sphere, shell, hollow)."""
        if self.shape in ("disk", "ring", "hollow", "sphere", "shell") and self.sizes:
            return self.sizes[0]
        return None


@dataclass(frozen=True)
class Support:
    """A pin, contact, rolling contact or flat base between a body and the fixed ground."""

    kind: str  # "pin", "contact", "rolls", "base"
    name: str  # the point's or base's name, used for the reactions (O_n, N_A, x_C)
    body: str
    point: Vec  # absolute position (a base: its start)
    normal: Vec  # unit normal, pushing on the body
    mu_s: sympy.Expr | None = None
    mu_k: sympy.Expr | None = None
    smooth: bool = False
    slides: Vec | None = None  # the sliding direction of the body's contact point
    end: Vec | None = None  # a base's end point
    line: int = 0
    column: int = 0
    two_sided: bool = False  # a guide (collar on a rod): the normal force may take either sign
    friction_sense: int | None = None  # ±1 along the tangent when sliding: opposes ``slides``
    normal_acceleration: sympy.Expr | int = 0  # a_P·n on a curved path: v²(K·n)
    constant_speed: bool = False  # a particle driven along its path at constant speed
    speed: sympy.Expr | None = None  # on a curved path: the particle's speed v
    rho: sympy.Expr | None = None  # on a curved path: its radius of curvature at G
    at: str = ""  # the point's own name when ``name`` carries the body too (two ``at G``)

    @property
    def point_name(self) -> str:
        """The name of the point where the support acts, as drawn on the diagram."""
        return self.at or self.name

    @property
    def tangent(self) -> Vec:
        """The normal turned 90° clockwise: the positive sense of the friction force."""
        return (self.normal[1], -self.normal[0])


@dataclass(frozen=True)
class Cord:
    """An inextensible massless cord pulling ``body`` at ``point`` along ``direction``."""

    name: str
    body: str
    point: Vec
    direction: Vec
    other: str = ""  # the body at the other end ("" for a fixed support)
    other_point: Vec | None = None
    line: int = 0
    column: int = 0


@dataclass(frozen=True)
class Spring:
    """A linear spring from a point of ``body`` to a fixed point or another body's point."""

    name: str
    body: str
    point: Vec
    other: str  # "" when the other end is a fixed point
    other_point: Vec
    k: sympy.Expr
    unstretched: sympy.Expr
    line: int = 0
    column: int = 0
    wound: bool = False  # on a cord wrapped round the body: its end moves with the rim
    tension_only: bool = False  # an elastic cord: no force while shorter than unstretched
    # an elastic cord's state assumed where its stretch's sign is not known before solving
    # (an unknown extent): taut (True) or slack; checked against the answer, and switched
    taut: bool | None = None
    # a spring the body rests against, not fixed to it: no force while longer than
    # unstretched (``taut`` then means in contact, compressed)
    compression_only: bool = False

    @property
    def one_way(self) -> int:
        """+1 for an elastic cord (acts while s > 0), −1 for a spring that only pushes (acts
        while s < 0), 0 for a plain spring."""
        return 1 if self.tension_only else -1 if self.compression_only else 0

    @property
    def acting_word(self) -> str:
        """What the one-way spring is called in messages."""
        return "elastic cord" if self.tension_only else "spring"

    def stretch(
        self, s: sympy.Expr, values: Mapping[sympy.Symbol, sympy.Expr], end: bool = False
    ) -> sympy.Expr:
        """The stretch that acts: ``s`` itself; for a tension-only spring max(s, 0) (a slack
        elastic cord pushes nothing and stores no energy), for a compression-only one
        min(s, 0) (a spring the body has left pulls nothing back); ValueError when the sign of
        ``s`` cannot be told, except at the ``end`` of a travel where the state is assumed
        (``taut``: acting, checked once solved).

        >>> k, L0 = sympy.Integer(800), sympy.Integer(15)
        >>> cord = Spring("S", "b", (0, 0), "", (0, 0), k, L0, tension_only=True)
        >>> cord.stretch(sympy.Integer(-15), {}), cord.stretch(sympy.Integer(5), {})
        (0, 5)
        >>> pad = Spring("S", "b", (0, 0), "", (0, 0), k, L0, compression_only=True)
        >>> pad.stretch(sympy.Integer(-15), {}), pad.stretch(sympy.Integer(5), {})
        (-15, 0)
        """
        if not self.one_way:
            return s
        from dynsolve.solver.roots import sign_of

        try:
            sign = sign_of(s, values)
        except ValueError:
            from dynsolve.numbers import real_value

            if real_value(s, values) == 0:  # just taut: it pulls nothing either way
                return sympy.Integer(0)
            if end and self.taut is not None:  # assumed, and checked once solved
                return s if self.taut else sympy.Integer(0)
            state = "stretched (L > L0)" if self.tension_only else "compressed (L < L0)"
            raise ValueError(
                f"whether the {self.acting_word} {self.name} is {state} cannot be told before "
                "solving (it depends on symbolic givens or an unknown extent): give them "
                "values, or use a plain spring"
            ) from None
        return s if sign * self.one_way > 0 else sympy.Integer(0)


@dataclass(frozen=True)
class CordState:
    """An elastic cord's state at the end of a travel where the sign of its stretch is not
    known before solving (an unknown extent): assumed (``taut``), kept as the root's
    branch, and checked against the answer (then switched)."""

    name: str
    stretch: sympy.Expr  # s at the end, L − L0 (as if taut)
    taut: bool
    state: int = 2  # the state at the travel's end
    line: int = 0  # the spring's line
    sign: int = 1  # +1 an elastic cord (acts while s > 0), −1 a push-only spring (s < 0)

    def branch(self) -> Constraint:
        """The root the assumed state keeps: acting (s > 0 for a cord, s < 0 for a
        push-only spring) or not."""
        from dynsolve.system import Constraint

        acting = self.sign * self.stretch
        relation = sympy.Gt(acting, 0) if self.taut else sympy.Le(acting, 0)
        state = self.words[0] if self.taut else self.words[1]
        return Constraint(
            relation, f"{self.name} {state} at state {self.state} (assumed)", self.line
        )

    @property
    def words(self) -> tuple[str, str]:
        """The state acting and not, in words: taut/slack, or in contact/clear."""
        return ("taut", "slack") if self.sign > 0 else ("in contact", "clear")


@dataclass(frozen=True)
class TorsionSpring:
    """A torsion spring between a rigid body and the ground: M = −k Δθ, at its neutral
    angle in the scene as drawn (no moment there)."""

    name: str
    body: str
    k: sympy.Expr  # N·m per radian
    line: int = 0
    column: int = 0


@dataclass(frozen=True)
class Link:
    """A rigid massless link (a two-force member) from a point of ``body`` to a fixed point
    or another body's point; its force acts along it."""

    name: str
    body: str
    point: Vec
    other: str
    other_point: Vec
    line: int = 0
    column: int = 0


@dataclass(frozen=True)
class Impact:
    """A collision of two bodies along a line of impact (smooth: no impulse across it);
    ``other`` is ``GROUND`` when the body strikes a fixed surface."""

    body: str
    other: str
    e: sympy.Expr  # coefficient of restitution, 0 ≤ e ≤ 1
    line: Vec  # unit vector of the line of impact, from body toward other
    stmt_line: int = 0
    column: int = 0


@dataclass(frozen=True)
class Pivot:
    """A rigid body striking a fixed point and turning about it afterwards (a plastic,
    eccentric impact: the point neither rebounds nor slides)."""

    body: str
    name: str
    point: Vec
    line: int = 0
    column: int = 0
    e: sympy.Expr | None = None  # with ``normal``: a smooth rebound off the point
    normal: Vec | None = None  # the line of impact at the point, from the body toward it


@dataclass(frozen=True)
class Travel:
    """How a body (or a link) gets from state 1, the scene as described, to state 2.

    ``kind`` is "to" (G reaches ``position``), "by" (G moves ``distance`` along
    ``direction``), "turns" (it turns through ``angle``, ccw positive) or "for" (the
    scene moves for ``duration``); ``stops`` says it is at rest in state 2.
    ``until`` names the event that ends it: "rolls" (an interval that ends when the
    sliding contact stops slipping), "slack" (the cord or link ``until_name`` goes slack)
    or "lost" (the particle leaves its circular surface); kind "until" has no extent given.
    """

    body: str
    kind: str
    position: Vec | None = None
    distance: sympy.Expr | None = None
    direction: Vec | None = None
    angle: sympy.Expr | None = None
    duration: sympy.Expr | None = None
    stops: bool = False
    line: int = 0
    column: int = 0
    until: str = ""
    until_name: str = ""


@dataclass(frozen=True)
class Path:
    """A fixed path in the plane: the curve ``curve = 0`` in the coordinates ``x``, ``y``,
    or ``y = explicit`` when it was written that way."""

    name: str
    curve: sympy.Expr
    x: sympy.Symbol
    y: sympy.Symbol
    explicit: sympy.Expr | None = None
    line: int = 0
    column: int = 0


@dataclass(frozen=True)
class Mover:
    """A point (a particle whose mass does not matter) moving along a path at constant speed."""

    name: str
    path: Path
    speed: sympy.Expr
    line: int = 0
    column: int = 0
    constant: bool = False  # ", constant": a_t = 0, held by a drive force along the path


@dataclass(frozen=True)
class Load:
    """A force (magnitude along ``direction`` at ``point``) or a couple (``sense`` ±1)."""

    kind: str  # "force" or "couple"
    name: str
    body: str
    point: Vec = ZERO
    point_name: str = ""
    direction: Vec = ZERO
    sense: int = 1  # +1 ccw, -1 cw (couples)
    line: int = 0
    column: int = 0


@dataclass(frozen=True)
class Scene:
    """The whole scene at the instant."""

    bodies: Mapping[str, Body]
    fixed_points: Mapping[str, Vec]
    supports: tuple[Support, ...]
    cords: tuple[Cord, ...]
    loads: tuple[Load, ...]
    gravity: Vec | None
    omegas: Mapping[str, sympy.Expr]  # signed, ccw positive
    motions: Mapping[str, str] = field(default_factory=dict)
    point_names: Mapping[Vec, str] = field(default_factory=dict)
    springs: tuple[Spring, ...] = ()
    links: tuple[Link, ...] = ()
    velocities: Mapping[str, Vec] = field(default_factory=dict)  # v_G given at the instant
    impacts: tuple[Impact, ...] = ()
    travels: Mapping[str, Travel] = field(default_factory=dict)  # how each gets to state 2
    movers: Mapping[str, Mover] = field(default_factory=dict)  # points moving along paths
    pivots: tuple[Pivot, ...] = ()  # eccentric impacts about a fixed point
    assumptions: tuple[sympy.core.relational.Relational, ...] = ()  # e.g. a > b
    values: Mapping[sympy.Symbol, sympy.Expr] = field(default_factory=dict)  # given values
    # travels, impacts, clutches and changes of inertia, as written
    events: tuple[Travel | Impact | Pivot | Clutch | Reshape, ...] = ()
    paths: Mapping[str, Path] = field(default_factory=dict)  # fixed paths, by name
    torsions: tuple[TorsionSpring, ...] = ()  # torsion springs to the ground


class _Builder:
    """Reads scene lines in two passes: bodies and points first, then what refers to them."""

    def __init__(
        self,
        spec: Spec,
        symbols: Mapping[str, sympy.Expr],
        dims: Mapping[str, Dim],
        given_values: Mapping[sympy.Symbol, sympy.Expr] | None = None,
    ):
        self.spec, self.symbols, self.dims = spec, symbols, dims
        self.dimensions: dict[str, Dim] = {}  # of each value's text, inferred once
        self.converted: dict[str, sympy.Expr] = {}  # each value's text as sympy, built once
        self.given_values = dict(given_values or {})
        self.file = spec.file
        self.bodies: dict[str, Body] = {}
        self.fixed: dict[str, Vec] = {}
        self.parts: dict[str, list[tuple[SceneStmt, Part]]] = {}
        self.masses: list[Expr] = []  # each mass (or weight) line's text, as read
        self.gravity()

    def gravity(self) -> None:
        """g, where weights act (a ``gravity`` line or a ``weight`` given), is positive:
        checked first, as the masses ``W/g`` are read from it."""
        weighed = (
            s
            for s in self.spec.scene
            if s.kind == "gravity" or any(p.key == "weight" for p in s.props)
        )
        stmt = next(weighed, None)
        if stmt is not None and "g" in self.symbols:
            self.value(Name("g", stmt.line, stmt.column), Dim(1, 0, -2), "gravity g", POSITIVE)

    # ---- helpers
    def where(self, line: int, column: int) -> Position:
        return Position(self.file, line, column)

    def value(self, expr: Expr, dim: Dim, what: str, sign: str = "") -> sympy.Expr:
        """An expression of the givens, checked to have dimension ``dim`` (0 fits any) and,
        where physics fixes its sign (``sign``: :data:`~dynsolve.model.physical.POSITIVE`
        or ``NOT_NEGATIVE``), to keep it. A literal 0 is always allowed (``mass 0``)."""
        if constant_value(expr) == 0:
            return sympy.Integer(0)
        converted = self._value(expr, dim, what)
        if sign:
            givens = {g.name: g for g in self.spec.givens}
            check_sign(converted, expr, what, sign, self.given_values, self.file, givens)
        return converted

    def _value(self, expr: Expr, dim: Dim, what: str) -> sympy.Expr:
        """An expression of the givens, checked to have dimension ``dim``."""
        for name in iter_names(expr):
            if name.text not in self.symbols and name.text != "pi":
                close = difflib.get_close_matches(name.text, list(self.symbols), n=1)
                hint = f"did you mean '{close[0]}'?" if close else "declare it under given:"
                raise SpecError(
                    f"'{name.text}' in the scene is not a given",
                    self.where(name.line, name.column),
                    hint,
                )
        text = expr_text(expr, str)
        found = self.dimension(expr, text)
        if found != dim:
            names = [n.text for n in iter_names(expr) if n.text != "pi"]
            hint = (
                "check the units of the givens it uses"
                if names
                else "a bare number has no unit: give it a name under 'given:' (e.g. "
                f"'x_C = {expr} m', or ft) and write the name here"
            )
            raise DimensionError(
                f"{what} must be {_article(dim.name)}, but '{expr}' is {_article(found.name)}",
                self.where(expr.line, expr.column),
                hint=hint,
            )
        if text not in self.converted:  # a chain of bodies writes 'm' and 'w/2' on every line
            self.converted[text] = to_sympy(expr, self.symbols, self.given_values)
        return self.converted[text]

    def dimension(self, expr: Expr, text: str) -> Dim:
        """The dimension of ``expr``, written ``text``, inferred once per text (an error is
        raised at the first, so none is kept)."""
        if text not in self.dimensions:
            probe = EquationStmt(
                Name("__value__", expr.line, expr.column), "=", expr, "", "", expr.line, expr.column
            )
            report = check_dimensions((probe,), {**self.dims, "pi": Dim()}, self.file)
            self.dimensions[text] = report.dims["__value__"]
        return self.dimensions[text]

    def vector(self, vector: tuple[Expr, Expr], what: str) -> Vec:
        return (self.value(vector[0], LENGTH, what), self.value(vector[1], LENGTH, what))

    def body(self, name: str, line: int, column: int) -> Body:
        if name not in self.bodies:
            close = difflib.get_close_matches(name, list(self.bodies), n=1)
            hint = f"did you mean '{close[0]}'?" if close else "declare it with 'body NAME: …'"
            raise SpecError(f"there is no body '{name}'", self.where(line, column), hint)
        return self.bodies[name]

    def location(self, body: Body, location: Location) -> tuple[Vec, str]:
        """An absolute point and its name for a location on ``body``."""
        if location.vector is not None:
            offset = self.vector(location.vector, "a position")
            return (body.origin[0] + offset[0], body.origin[1] + offset[1]), ""
        name = location.point
        if name == "G":
            return body.G, "G"
        if name in body.points:
            return body.points[name], name
        if name in self.fixed:
            return self.fixed[name], name
        known = sorted({*body.points, *self.fixed, "G"})
        close = difflib.get_close_matches(name, known, n=1)
        hint = f"did you mean '{close[0]}'?" if close else "declare it with 'point NAME: (x, y)'"
        raise SpecError(
            f"there is no point '{name}' on {body.name}",
            self.where(location.line, location.column),
            hint,
        )

    def direction(self, direction: Direction, origin: Vec | None = None) -> Vec:
        if direction.kind == "word":
            if direction.word not in WORDS:
                raise SpecError(
                    f"'{direction.word}' is not a direction here",
                    self.where(direction.line, direction.column),
                    hint="use up, down, left, right, angle EXPR, toward POINT or (dx, dy)",
                )
            return WORDS[direction.word]
        if direction.kind == "angle":
            assert direction.angle is not None
            angle = self.value(direction.angle, Dim(), "an angle")
            return (sympy.cos(angle), sympy.sin(angle))
        if direction.kind == "toward":
            if direction.point not in self.fixed:
                raise SpecError(
                    f"there is no fixed point '{direction.point}'",
                    self.where(direction.line, direction.column),
                    hint="declare it with 'point NAME: (x, y)'",
                )
            assert origin is not None
            target = self.fixed[direction.point]
            return _unit((target[0] - origin[0], target[1] - origin[1]))
        assert direction.vector is not None
        _known_names(self, direction.vector, self.symbols)
        x, y = (to_sympy(c, self.symbols) for c in direction.vector)
        return _unit((x, y))

    # ---- pass 1: bodies, parts, points
    def declare(self, stmt: SceneStmt) -> None:
        if stmt.kind == "body":
            if stmt.name in self.bodies:
                raise SpecError(
                    f"body '{stmt.name}' is declared twice",
                    self.where(stmt.line, stmt.column),
                    hint="give each body its own name",
                )
            self.bodies[stmt.name] = self.simple_body(stmt)
        elif stmt.kind in ("part", "hole"):
            self.parts.setdefault(stmt.body, []).append((stmt, self.part(stmt)))
        elif stmt.kind == "point" and not stmt.body:
            self.fixed[stmt.name] = self.vector(stmt.vectors[0], "a point's position")

    def props(self, stmt: SceneStmt) -> dict[str, Prop]:
        found: dict[str, Prop] = {}
        for prop in stmt.props:
            if prop.key in found:
                raise SpecError(
                    f"'{prop.key}' is given twice for {stmt.name or stmt.body}",
                    self.where(stmt.line, stmt.column),
                    hint="keep one",
                )
            found[prop.key] = prop
        return found

    def mass(self, props: dict[str, Prop], stmt: SceneStmt) -> sympy.Expr | None:
        if "mass" in props:
            self.masses.append(props["mass"].values[0])
            return self.value(props["mass"].values[0], MASS, "a mass", NOT_NEGATIVE)
        if "weight" in props:
            self.masses.append(props["weight"].values[0])
            weight = self.value(props["weight"].values[0], FORCE, "a weight", NOT_NEGATIVE)
            return weight / self.symbols["g"]
        return None

    def simple_body(self, stmt: SceneStmt) -> Body:
        props = self.props(stmt)
        at = self.vector(props["at"].vector, "a position") if "at" in props else ZERO
        where = self.where(stmt.line, stmt.column)
        if "composite" in props:
            # filled in by finish_composites once its parts are known
            return Body(
                stmt.name,
                sympy.Integer(0),
                sympy.Integer(0),
                at,
                at,
                "composite",
                (),
                {},
                False,
                "",
                stmt.line,
                stmt.column,
            )
        mass = self.mass(props, stmt)
        if mass is None:
            raise SpecError(
                f"body '{stmt.name}' has no mass", where, hint="add 'mass m' or 'weight W'"
            )
        shape = props["shape"].word if "shape" in props else ""
        sizes = tuple(
            self.value(v, LENGTH, f"a size of the {shape}", POSITIVE)
            for v in props.get("shape", Prop("")).values
        )
        I_G, note = self.inertia(stmt, props, mass, shape, sizes, at)
        particle = shape == "particle" or (
            not shape and "gyration" not in props and "inertia" not in props
        )
        return Body(
            stmt.name,
            mass,
            I_G,
            at,
            at,
            shape or "body",
            sizes,
            {},
            particle,
            note,
            stmt.line,
            stmt.column,
        )

    def inertia(
        self,
        stmt: SceneStmt,
        props: dict[str, Prop],
        mass: sympy.Expr,
        shape: str,
        sizes: tuple[sympy.Expr, ...],
        at: Vec,
    ) -> tuple[sympy.Expr, str]:
        where = self.where(stmt.line, stmt.column)
        if "gyration" in props:
            prop = props["gyration"]
            k = self.value(prop.values[0], LENGTH, "a radius of gyration", NOT_NEGATIVE)
            about = from_gyration(mass, k)
            if not prop.about:
                return about, "I_G = m k_G²"
            return self.moved(about, mass, prop.about, at, where), f"I_{prop.about} = m k²"
        if "inertia" in props:
            prop = props["inertia"]
            given = self.value(prop.values[0], Dim(2, 1, 0), "a moment of inertia", NOT_NEGATIVE)
            if not prop.about:
                return given, "I_G given"
            return self.moved(given, mass, prop.about, at, where), f"I_{prop.about} given"
        if shape and shape != "particle":
            try:
                return inertia_about_G(shape, mass, sizes), f"{shape} formula"
            except ValueError as exc:
                raise SpecError(str(exc), where, hint="see the shape table in docs") from None
        return sympy.Integer(0), "particle"

    def moved(
        self, I_P: sympy.Expr, mass: sympy.Expr, point: str, at: Vec, where: Position
    ) -> sympy.Expr:
        """I about G from I about a fixed point (parallel-axis theorem)."""
        if point not in self.fixed:
            raise SpecError(
                f"there is no fixed point '{point}' to take the inertia about",
                where,
                hint="declare it with 'point NAME: (x, y)' before the body",
            )
        P = self.fixed[point]
        d = sympy.sqrt((at[0] - P[0]) ** 2 + (at[1] - P[1]) ** 2)
        return to_G(I_P, mass, d)

    def part(self, stmt: SceneStmt) -> Part:
        props = self.props(stmt)
        where = self.where(stmt.line, stmt.column)
        shape = props["shape"].word if "shape" in props else "particle"
        sizes = tuple(
            self.value(v, LENGTH, f"a size of the {shape}", POSITIVE)
            for v in props.get("shape", Prop("")).values
        )
        at = self.vector(props["at"].vector, "a position") if "at" in props else ZERO
        mass = self.mass(props, stmt)
        if mass is None and "density" in props:
            from dynsolve.model.inertia import mass_from_density

            density = self.value(props["density"].values[0], Dim(-3, 1, 0), "a density", POSITIVE)
            thickness = (
                self.value(props["thickness"].values[0], LENGTH, "a thickness", POSITIVE)
                if "thickness" in props
                else None
            )
            try:
                mass = mass_from_density(shape, density, sizes, thickness)
            except ValueError as exc:
                raise SpecError(str(exc), where, hint="give a mass instead") from None
        if mass is None:
            raise SpecError(
                f"this {stmt.kind} of {stmt.body} has no mass",
                where,
                hint="add 'mass m', or 'density rho' (and 'thickness t' for flat shapes)",
            )
        name = f"{stmt.kind} {len(self.parts.get(stmt.body, [])) + 1} ({shape})"
        try:
            return Part(name, shape, mass, sizes, at, hole=stmt.kind == "hole")
        except ValueError as exc:
            raise SpecError(str(exc), where, hint="see the shape table in docs") from None

    def finish_composites(self) -> None:
        for name, body in list(self.bodies.items()):
            parts = self.parts.pop(name, [])
            if body.shape != "composite":
                if parts:
                    stmt = parts[0][0]
                    raise SpecError(
                        f"body '{name}' is not composite but has parts",
                        self.where(stmt.line, stmt.column),
                        hint=f"write 'body {name}: composite'",
                    )
                continue
            if not parts:
                raise SpecError(
                    f"composite body '{name}' has no parts",
                    self.where(body.line, body.column),
                    hint=f"add lines 'part {name}: disk R, mass m, at (x, y)'",
                )
            try:
                whole = composite(p for _, p in parts)
            except ValueError as exc:
                raise SpecError(
                    str(exc), self.where(body.line, body.column), "check the parts"
                ) from None
            G = (body.origin[0] + whole.G[0], body.origin[1] + whole.G[1])
            note = "composite: " + "; ".join(t.text() for t in whole.terms())
            self.bodies[name] = Body(
                name,
                whole.mass,
                whole.I_G,
                G,
                body.origin,
                "composite",
                (),
                {},
                False,
                note,
                body.line,
                body.column,
                tuple(p for _, p in parts),
            )
        for body_name, parts in self.parts.items():
            stmt = parts[0][0]
            raise SpecError(
                f"there is no body '{body_name}' for this {stmt.kind}",
                self.where(stmt.line, stmt.column),
                hint=f"declare 'body {body_name}: composite' first",
            )

    def body_points(self) -> None:
        """Attach ``point NAME on BODY`` points (relative to the body's origin)."""
        for stmt in self.spec.scene:
            if stmt.kind != "point" or not stmt.body:
                continue
            body = self.body(stmt.body, stmt.line, stmt.column)
            offset = self.vector(stmt.vectors[0], "a point's position")
            point = (body.origin[0] + offset[0], body.origin[1] + offset[1])
            self.bodies[body.name] = replace(body, points={**body.points, stmt.name: point})


def _unit(vector: Vec) -> Vec:
    length = sympy.sqrt(tidy(vector[0] ** 2 + vector[1] ** 2, light=False))  # |v|² first: short
    return (tidy(vector[0] / length, light=False), tidy(vector[1] / length, light=False))


def _article(text: str) -> str:
    if text == "dimensionless":
        return "dimensionless (a pure number)"
    return ("an " if text[:1] in "aeiou" else "a ") + text


SceneReader = _Builder


def scene_reader(
    spec: Spec,
    symbols: Mapping[str, sympy.Expr],
    dims: Mapping[str, Dim],
    given_values: Mapping[sympy.Symbol, sympy.Expr] | None = None,
) -> SceneReader:
    """A reader of a scene line's values, positions and directions: each checked against
    its dimension, with a positioned error (used by front ends beside the scene model).

    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("given:\\n  L = 2 m\\nscene:\\n  point A: (L, 0)\\nfind: L\\n")
    >>> L = sympy.Symbol("L", positive=True)
    >>> scene_reader(spec, {"L": L}, {"L": LENGTH}).vector(spec.scene[0].vectors[0], "a position")
    (L, 0)
    """
    return _Builder(spec, symbols, dims, given_values)


def build_scene(
    spec: Spec,
    symbols: Mapping[str, sympy.Expr],
    dims: Mapping[str, Dim],
    given_values: Mapping[sympy.Symbol, sympy.Expr] | None = None,
) -> Scene:
    """The scene model of ``spec``; ``symbols`` and ``dims`` cover every given (and g);
    ``given_values`` lets numeric checks (0 ≤ e ≤ 1) be made at once. Its geometry is
    tidied in every mode (:func:`~dynsolve.numbers.light_tidying` off): every principle
    builds on it, and tidy positions and normals keep their formulas and tests small."""
    with light_tidying(False):
        return _build_scene(spec, symbols, dims, given_values)


def _build_scene(
    spec: Spec,
    symbols: Mapping[str, sympy.Expr],
    dims: Mapping[str, Dim],
    given_values: Mapping[sympy.Symbol, sympy.Expr] | None = None,
) -> Scene:
    """The scene model of ``spec``; ``symbols`` and ``dims`` cover every given (and g);
    ``given_values`` lets numeric checks (0 ≤ e ≤ 1) be made at once."""
    builder = _Builder(spec, symbols, dims, given_values)
    for stmt in spec.scene:
        if any(p.key == "at3" for p in stmt.props):
            raise SpecError(
                "a body placed with three coordinates belongs in a 3D scene",
                builder.where(stmt.line, stmt.column),
                hint="a 3D scene says how the body turns ('rotates B: about …'); a plane "
                "scene places bodies with 'at (x, y)'",
            )
        if stmt.kind in LINKAGE_ONLY:
            raise SpecError(
                f"'{LINKAGE_ONLY[stmt.kind]}' describes a linkage, and this scene has no bars",
                builder.where(stmt.line, stmt.column),
                hint="declare the links with 'bar NAME: A to B' (docs/scene-mode.md, Linkages)",
            )
        builder.declare(stmt)
    builder.finish_composites()
    builder.body_points()
    givens = {g.name: g for g in spec.givens}
    check_some_mass(
        [b.mass for b in builder.bodies.values()],
        builder.masses,
        builder.given_values,
        builder.file,
        givens,
    )
    supports: list[Support] = []
    cords: list[Cord] = []
    loads: list[Load] = []
    gravity: Vec | None = None
    omegas: dict[str, sympy.Expr] = {}
    velocities: dict[str, Vec] = {}
    motions: dict[str, str] = {}
    springs: list[Spring] = []
    torsions: list[TorsionSpring] = []
    links: list[Link] = []
    impacts: list[Impact] = []
    headings: dict[str, Vec] = {}  # each given velocity's direction
    travels: dict[str, Travel] = {}
    link_names = {stmt.name for stmt in spec.scene if stmt.kind == "link"}
    paths: dict[str, Path] = {}
    pivots: list[Pivot] = []
    events: list[Travel | Impact | Pivot | Clutch | Reshape] = []
    movers: dict[str, Mover] = {}
    assumptions: list[sympy.core.relational.Relational] = []
    for stmt in spec.scene:
        if stmt.kind in ("pin", "contact", "rolls", "base"):
            supports.append(_support(builder, stmt))
        elif stmt.kind == "cord":
            cords.append(_cord(builder, stmt))
        elif stmt.kind in ("spring", "link"):
            body, point, other, other_point = _two_ends(builder, stmt)
            if stmt.kind == "link":
                links.append(
                    Link(stmt.name, body, point, other, other_point, stmt.line, stmt.column)
                )
            else:
                k = builder.value(
                    stmt.props[0].values[0], Dim(0, 1, -2), "a spring stiffness", POSITIVE
                )
                free = builder.value(
                    stmt.props[1].values[0], LENGTH, "an unstretched length", NOT_NEGATIVE
                )
                wound = any(p.key == "wound" for p in stmt.props)
                tension_only = any(p.key == "tension_only" for p in stmt.props)
                compression_only = any(p.key == "compression_only" for p in stmt.props)
                springs.append(
                    Spring(
                        stmt.name,
                        body,
                        point,
                        other,
                        other_point,
                        k,
                        free,
                        stmt.line,
                        stmt.column,
                        wound,
                        tension_only,
                        compression_only=compression_only,
                    )
                )
        elif stmt.kind == "torsion":
            torsions.append(_torsion(builder, stmt))
        elif stmt.kind in ("force", "couple"):
            loads.append(_load(builder, stmt, link_names))
        elif stmt.kind == "gravity":
            gravity = builder.direction(stmt.direction) if stmt.direction else WORDS["down"]
        elif stmt.kind == "omega":
            builder.body(stmt.body, stmt.line, stmt.column)
            assert stmt.value is not None
            omega = builder.value(stmt.value, Dim(0, 0, -1), "an angular velocity")
            omegas[stmt.body] = -omega if stmt.word == "cw" else omega
        elif stmt.kind == "impact":
            builder.body(stmt.body, stmt.line, stmt.column)
            if stmt.other != GROUND or GROUND in builder.bodies:
                builder.body(stmt.other, stmt.line, stmt.column)
            assert stmt.value is not None
            e = builder.value(stmt.value, Dim(), "a coefficient of restitution")
            numeric = real_value(e, builder.given_values)
            if numeric is not None and not 0 <= numeric <= 1:
                raise SpecError(
                    f"the coefficient of restitution must lie in [0, 1], got {numeric:g}",
                    builder.where(stmt.line, stmt.column),
                    hint="0 is perfectly plastic, 1 perfectly elastic",
                )
            impacts.append(
                Impact(
                    stmt.body,
                    stmt.other,
                    e,
                    builder.direction(stmt.direction) if stmt.direction else _UNSET,
                    stmt.line,
                    stmt.column,
                )
            )
            events.append(impacts[-1])
        elif stmt.kind in ("clutch", "change"):
            events.append(momentum_event(builder, stmt))
        elif stmt.kind == "travel":
            travels[stmt.body] = _travel(builder, stmt, link_names)
            events.append(travels[stmt.body])
        elif stmt.kind == "velocity":
            builder.body(stmt.body, stmt.line, stmt.column)
            assert stmt.value is not None and stmt.direction is not None
            speed = builder.value(stmt.value, Dim(1, 0, -1), "a speed")
            direction = builder.direction(stmt.direction)
            velocities[stmt.body] = (speed * direction[0], speed * direction[1])
            headings[stmt.body] = direction
        elif stmt.kind == "motion":
            builder.body(stmt.body, stmt.line, stmt.column)
            motions[stmt.body] = stmt.word
        elif stmt.kind == "pivot":
            pivots.append(_pivot(builder, stmt))
            events.append(pivots[-1])
        elif stmt.kind == "path":
            paths[stmt.name] = _path(builder, stmt)
        elif stmt.kind == "moves":
            movers[stmt.name] = _mover(builder, stmt, paths)
            if stmt.name in builder.bodies:
                supports.append(_on_path(builder, movers[stmt.name]))
        elif stmt.kind == "assume":
            assumptions.append(_assumption(builder, stmt))
    lines = {
        id(i): embedded_line(builder, i, supports, headings) for i in impacts if i.line is _UNSET
    }
    impacts = [replace(i, line=lines[id(i)]) if id(i) in lines else i for i in impacts]
    events = [replace(e, line=lines[id(e)]) if id(e) in lines else e for e in events]  # type: ignore[type-var]
    names = {v: k for k, v in builder.fixed.items()}
    for body in builder.bodies.values():
        names.update({v: k for k, v in body.points.items()})
    return Scene(
        builder.bodies,
        builder.fixed,
        distinct_names(supports),
        tuple(cords),
        tuple(loads),
        gravity,
        omegas,
        motions,
        names,
        springs=tuple(springs),
        links=tuple(links),
        velocities=velocities,
        impacts=tuple(impacts),
        travels=travels,
        movers=movers,
        paths=paths,
        pivots=tuple(pivots),
        assumptions=tuple(assumptions),
        values=builder.given_values,
        events=tuple(events),
        torsions=_torsions_at_rest(builder, torsions, events),
    )


def _torsion(builder: _Builder, stmt: SceneStmt) -> TorsionSpring:
    body = builder.body(stmt.body, stmt.line, stmt.column)
    if body.particle:
        raise SpecError(
            f"a torsion spring turns a rigid body, and {body.name} is a particle",
            builder.where(stmt.line, stmt.column),
            hint="give the body a shape or an inertia (a torsion pendulum: 'disk R')",
        )
    k = builder.value(stmt.props[0].values[0], Dim(2, 1, -2), "a torsional stiffness", POSITIVE)
    return TorsionSpring(stmt.name, body.name, k, stmt.line, stmt.column)


def _torsions_at_rest(
    builder: _Builder, torsions: list[TorsionSpring], events: list[object]
) -> tuple[TorsionSpring, ...]:
    """The torsion springs; refused between states and across impacts, whose principles
    do not take them yet (never left out silently)."""
    if torsions and events:
        raise SpecError(
            "a torsion spring is taken at an instant and in vibrations, not yet between "
            "states or across impacts",
            builder.where(torsions[0].line, torsions[0].column),
            hint="ask period(B), omega_n(B) or f_n(B) of the scene at rest, without travel "
            "or impact lines",
        )
    return tuple(torsions)


def _support(builder: _Builder, stmt: SceneStmt) -> Support:
    body = builder.body(stmt.body, stmt.line, stmt.column)
    props = {p.key: p for p in stmt.props}
    normal = builder.direction(props["normal"].direction) if "normal" in props else WORDS["up"]
    mu_s = (
        builder.value(props["mu_s"].values[0], Dim(), "μs", NOT_NEGATIVE)
        if "mu_s" in props
        else None
    )
    mu_k = (
        builder.value(props["mu_k"].values[0], Dim(), "μk", NOT_NEGATIVE)
        if "mu_k" in props
        else None
    )
    slides = builder.direction(props["slides"].direction) if "slides" in props else None
    smooth = "smooth" in props or (mu_s is None and mu_k is None and stmt.kind == "contact")
    two_sided = "guide" in props
    if stmt.kind == "pin":
        if stmt.name not in builder.fixed:
            raise SpecError(
                f"there is no fixed point '{stmt.name}' to pin {body.name} at",
                builder.where(stmt.line, stmt.column),
                hint=f"declare it with 'point {stmt.name}: (x, y)'",
            )
        return Support(
            "pin",
            stmt.name,
            body.name,
            builder.fixed[stmt.name],
            WORDS["up"],
            line=stmt.line,
            column=stmt.column,
        )
    if stmt.kind == "base":
        start = builder.vector(stmt.vectors[0], "a base's end")
        end = builder.vector(stmt.vectors[1], "a base's end")
        start = (body.origin[0] + start[0], body.origin[1] + start[1])
        end = (body.origin[0] + end[0], body.origin[1] + end[1])
        along = _unit((end[0] - start[0], end[1] - start[1]))
        normal = (-along[1], along[0])  # the base's left normal: into the body from below
        return Support(
            "base",
            stmt.name,
            body.name,
            start,
            normal,
            mu_s,
            mu_k,
            smooth,
            slides,
            end,
            stmt.line,
            stmt.column,
            friction_sense=_friction_sense(builder, stmt, slides, normal),
        )
    assert stmt.location is not None
    point, name = builder.location(body, stmt.location)
    if not name:
        name = f"{stmt.kind[0].upper()}{len(stmt.body)}"
    if stmt.kind == "rolls" and body.radius is None:
        raise SpecError(
            f"{body.name} rolls but has no radius",
            builder.where(stmt.line, stmt.column),
            hint="give it a round shape, e.g. 'disk R'",
        )
    return Support(
        stmt.kind,
        name,
        body.name,
        point,
        normal,
        mu_s,
        mu_k,
        smooth,
        slides,
        None,
        stmt.line,
        stmt.column,
        two_sided,
        _friction_sense(builder, stmt, slides, normal),
    )


def distinct_names(supports: list[Support]) -> tuple[Support, ...]:
    """The supports with unique names: where two share a point name (each body's ``at G``)
    each is named for its body too (``G_A``), so its unknowns are ``N_G_A``, ``F_G_A``.

    >>> up = WORDS["up"]
    >>> [s.name for s in distinct_names([Support("contact", "G", "A", up, up),
    ...                                  Support("contact", "G", "B", up, up)])]
    ['G_A', 'G_B']
    """
    counts = Counter(s.name for s in supports)
    return tuple(
        replace(s, name=f"{s.name}_{s.body}", at=s.name) if counts[s.name] > 1 else s
        for s in supports
    )


def _two_ends(builder: _Builder, stmt: SceneStmt) -> tuple[str, Vec, str, Vec]:
    """A spring's or link's two ends: a body point, then a fixed point or a body point."""
    body = builder.body(stmt.body, stmt.line, stmt.column)
    assert stmt.location is not None
    point, _ = builder.location(body, stmt.location)
    if stmt.other in builder.bodies:
        other = builder.bodies[stmt.other]
        if stmt.other_location is None:
            return body.name, point, other.name, other.G
        return body.name, point, other.name, builder.location(other, stmt.other_location)[0]
    if stmt.other in builder.fixed and stmt.other_location is None:
        return body.name, point, "", builder.fixed[stmt.other]
    known = sorted({*builder.bodies, *builder.fixed})
    close = difflib.get_close_matches(stmt.other, known, n=1)
    hint = f"did you mean '{close[0]}'?" if close else "end it at a fixed point or a body"
    raise SpecError(
        f"the {stmt.kind} {stmt.name} ends at '{stmt.other}', which is neither a body nor a "
        "fixed point",
        builder.where(stmt.line, stmt.column),
        hint,
    )


def _friction_sense(
    builder: _Builder, stmt: SceneStmt, slides: Vec | None, normal: Vec
) -> int | None:
    """The sense (±1 along the tangent) of kinetic friction opposing ``slides``."""
    if slides is None:
        return None
    along = real_value(slides[0] * normal[1] - slides[1] * normal[0], builder.given_values)
    if along is None or along == 0:
        raise SpecError(
            "the sliding direction must run along the surface",
            builder.where(stmt.line, stmt.column),
            hint="give 'slides' a direction across the contact normal",
        )
    return -1 if along > 0 else 1


def _cord(builder: _Builder, stmt: SceneStmt) -> Cord:
    body = builder.body(stmt.body, stmt.line, stmt.column)
    assert stmt.location is not None and stmt.direction is not None
    point, _ = builder.location(body, stmt.location)
    direction = builder.direction(stmt.direction, point)
    other_point = None
    if stmt.other:
        other = builder.body(stmt.other, stmt.line, stmt.column)
        if stmt.other_location is not None:
            other_point, _ = builder.location(other, stmt.other_location)
        else:
            other_point = other.G
    elif stmt.word != "fixed":
        raise SpecError(
            f"cord {stmt.name} has one end on {body.name} and no other end",
            builder.where(stmt.line, stmt.column),
            hint="add 'to BODY' or ', fixed'",
        )
    return Cord(
        stmt.name, body.name, point, direction, stmt.other, other_point, stmt.line, stmt.column
    )


def _pivot(builder: _Builder, stmt: SceneStmt) -> Pivot:
    """``impact BODY at POINT: e 0``: BODY strikes the fixed POINT and turns about it."""
    body = builder.body(stmt.body, stmt.line, stmt.column)
    if stmt.name not in builder.fixed:
        raise SpecError(
            f"there is no fixed point '{stmt.name}' for {body.name} to strike",
            builder.where(stmt.line, stmt.column),
            hint=f"declare it with 'point {stmt.name}: (x, y)'",
        )
    assert stmt.value is not None
    e = builder.value(stmt.value, Dim(), "a coefficient of restitution")
    if stmt.direction is not None:  # a smooth rebound off the point along the line
        value = real_value(e, builder.given_values)
        if value is not None and not 0 <= value <= 1:
            raise SpecError(
                f"a coefficient of restitution is between 0 and 1, not {value:g}",
                builder.where(stmt.line, stmt.column),
                hint="e 0 is plastic, e 1 elastic",
            )
        return Pivot(
            body.name,
            stmt.name,
            builder.fixed[stmt.name],
            stmt.line,
            stmt.column,
            e=e,
            normal=builder.direction(stmt.direction),
        )
    if real_value(e, builder.given_values) != 0:
        raise SpecError(
            "an impact about a fixed point with e > 0 needs its line of impact: the body "
            "rebounds off the point (smooth); with e 0 and no line it turns about the point",
            builder.where(stmt.line, stmt.column),
            hint="write 'e e, line down' (from the body toward the point), or 'e 0'",
        )
    return Pivot(body.name, stmt.name, builder.fixed[stmt.name], stmt.line, stmt.column)


COORDINATES = ("x", "y")


def _path(builder: _Builder, stmt: SceneStmt) -> Path:
    """``path NAME: LHS = RHS`` in the coordinates x and y (lengths)."""
    lhs, rhs = stmt.vectors[0]
    x, y = (sympy.Symbol(c, real=True) for c in COORDINATES)
    taken = [c for c in COORDINATES if c in builder.symbols]
    if taken:
        raise SpecError(
            f"'{taken[0]}' is a coordinate of the path, but also a given",
            builder.where(stmt.line, stmt.column),
            hint=f"rename the given '{taken[0]}'",
        )
    symbols = {**builder.symbols, "x": x, "y": y}
    _known_names(builder, (lhs, rhs), symbols)
    probe = EquationStmt(lhs, "=", rhs, "", "", stmt.line, stmt.column)
    dims = {**builder.dims, "x": LENGTH, "y": LENGTH, "pi": Dim()}
    try:
        check_dimensions((probe,), dims, builder.file)  # x and y are lengths
    except DimensionError as error:  # y = 0.0025*x^2: the number's unit is not written
        raise DimensionError(
            error.message.removeprefix(f"line {stmt.line}: "),
            error.position,
            hint="x and y are lengths, so a path's coefficients carry units: give them as "
            "givens, e.g. 'k = 0.0025 1/m' and 'path road: y = k*x^2', or 'y = x^2/(2*c)' "
            "with 'c = 200 m'",
        ) from None
    left, right = to_sympy(lhs, symbols), to_sympy(rhs, symbols)
    explicit = right if left == y and not right.has(y) else None
    return Path(stmt.name, left - right, x, y, explicit, stmt.line, stmt.column)


def _known_names(
    builder: _Builder, exprs: tuple[Expr, ...], symbols: Mapping[str, sympy.Expr]
) -> None:
    """Every name in ``exprs`` must be one of ``symbols`` (or pi)."""
    for expr in exprs:
        for name in iter_names(expr):
            if name.text not in symbols and name.text != "pi":
                close = difflib.get_close_matches(name.text, list(symbols), n=1)
                raise SpecError(
                    f"'{name.text}' in the scene is not a given",
                    builder.where(name.line, name.column),
                    f"did you mean '{close[0]}'?" if close else "declare it under given:",
                )


def _mover(builder: _Builder, stmt: SceneStmt, paths: Mapping[str, Path]) -> Mover:
    if stmt.other not in paths:
        close = difflib.get_close_matches(stmt.other, list(paths), n=1)
        raise SpecError(
            f"there is no path '{stmt.other}'",
            builder.where(stmt.line, stmt.column),
            f"did you mean '{close[0]}'?" if close else "declare it first with 'path NAME: …'",
        )
    assert stmt.value is not None
    speed = builder.value(stmt.value, Dim(1, 0, -1), "a speed")
    constant = stmt.word == "constant"
    return Mover(stmt.name, paths[stmt.other], speed, stmt.line, stmt.column, constant)


def _on_path(builder: _Builder, mover: Mover) -> Support:
    """A particle on a curved path at the instant: a two-sided smooth contact along the
    path's normal n = ∇F/|∇F| at G, whose point accelerates along n by v² K·n, with
    K = −(t·H t) ∇F/|∇F|² the curvature vector of F = 0 (H the Hessian, t the tangent)."""
    body = builder.bodies[mover.name]
    where = builder.where(mover.line, mover.column)
    if not body.particle:
        raise SpecError(
            f"{body.name} moves along a path but is a rigid body",
            where,
            hint="a path carries a particle; give the body no shape or inertia",
        )
    path = mover.path
    at = {path.x: body.G[0], path.y: body.G[1]}
    on_path = path.curve.xreplace(at)
    residual = real_value(on_path, builder.given_values)
    terms = [real_value(t, builder.given_values) for t in sympy.Add.make_args(on_path)]
    size = sum(abs(t) for t in terms if t is not None)  # relative: scale-free
    # the numbers first: the identity (a tidy with letters) only when they cannot settle it
    if (residual is None or abs(residual) > 1e-9 * size) and tidy(on_path) != 0:
        raise SpecError(
            f"{body.name}'s G is not on the path {path.name}",
            where,
            hint="place the body with 'at (x, y)' on the path",
        )
    F_x, F_y = (sympy.diff(path.curve, c) for c in (path.x, path.y))
    H = [[sympy.diff(d, c) for c in (path.x, path.y)] for d in (F_x, F_y)]
    grad = (F_x.xreplace(at), F_y.xreplace(at))
    # the small pieces tidied first (|∇F|², τ·Hτ with τ = |∇F| t), so that the normal,
    # a_n and ρ are tidied from short forms: a circle's 4R²sin²θ + 4R²cos²θ is 4R² once
    size2 = tidy(grad[0] ** 2 + grad[1] ** 2)
    size = sympy.sqrt(size2)
    tau = (-grad[1], grad[0])
    tHt = tidy(sum(tau[i] * H[i][j].xreplace(at) * tau[j] for i in range(2) for j in range(2)))
    normal = (tidy(grad[0] / size), tidy(grad[1] / size))
    return Support(
        "contact",
        path.name,
        body.name,
        body.G,
        normal,
        smooth=True,
        line=mover.line,
        column=mover.column,
        two_sided=True,
        normal_acceleration=tidy(-(mover.speed**2) * tHt / (size2 * size)),
        constant_speed=mover.constant,
        speed=mover.speed,
        rho=None if _is_zero_number(tHt) else tidy(size2 * size / sympy.Abs(tHt)),
    )


def _is_zero_number(expr: sympy.Expr) -> bool:
    """A curvature term that is surely 0 (a straight stretch: no radius of curvature)."""
    return (sympy.Integer(0) + expr).is_zero is True


def _assumption(builder: _Builder, stmt: SceneStmt) -> sympy.core.relational.Relational:
    """``assume LHS REL RHS`` between givens of the same dimension (decides orderings)."""
    lhs, rhs = stmt.vectors[0]
    _known_names(builder, (lhs, rhs), builder.symbols)
    probe = EquationStmt(lhs, stmt.word, rhs, "", "", stmt.line, stmt.column)  # type: ignore[arg-type]
    check_dimensions((probe,), {**builder.dims, "pi": Dim()}, builder.file)
    relation = {">": sympy.Gt, "<": sympy.Lt, ">=": sympy.Ge, "<=": sympy.Le}.get(stmt.word)
    if relation is None:
        raise SpecError(
            "an assumption is an inequality",
            builder.where(stmt.line, stmt.column),
            hint="write e.g. 'assume a > b'",
        )
    return relation(to_sympy(lhs, builder.symbols), to_sympy(rhs, builder.symbols))


def _travel(builder: _Builder, stmt: SceneStmt, links: set[str]) -> Travel:
    """A travel line: to a position, by a distance along a direction, or through an angle."""
    stops = any(p.key == "stops" for p in stmt.props)
    line, column = stmt.line, stmt.column
    until = next((p for p in stmt.props if p.key == "until"), None)
    if until is not None and stmt.word not in ("for", "until"):
        raise SpecError(
            f"'until {until.word}' ends an interval: it goes on a 'for' line",
            builder.where(until.line, until.column),
            hint=f"write 'travel {stmt.body}: for t_1, until {until.word}' and find t_1",
        )
    if stmt.word == "until":
        assert until is not None
        builder.body(stmt.body, stmt.line, stmt.column)
        return Travel(stmt.body, "until", line=line, column=column, until=until.word,
                      until_name=until.about)  # fmt: skip
    if stmt.body not in links:
        body = builder.body(stmt.body, stmt.line, stmt.column)
    elif stmt.word not in ("cw", "ccw"):
        raise SpecError(
            f"a link's state is its angle: {stmt.body} can only turn",
            builder.where(stmt.line, stmt.column),
            hint=f"write 'travel {stmt.body}: turns ANGLE ccw'",
        )
    if stmt.word == "for":
        assert stmt.value is not None
        duration = builder.value(stmt.value, Dim(0, 0, 1), "a duration", POSITIVE)
        return Travel(stmt.body, "for", duration=duration, stops=stops, line=line, column=column,
                      until=until.word if until else "")  # fmt: skip
    if stmt.vectors:
        position = builder.vector(stmt.vectors[0], "a position")
        return Travel(stmt.body, "to", position=position, stops=stops, line=line, column=column)
    assert stmt.value is not None
    if stmt.word in ("cw", "ccw"):
        if stmt.body not in links and body.particle:
            raise SpecError(
                f"{stmt.body} is a particle: it has no angle to turn through",
                builder.where(stmt.line, stmt.column),
                hint=f"write 'travel {stmt.body}: by DISTANCE, DIRECTION' or 'to (x, y)'",
            )
        angle = builder.value(stmt.value, Dim(), "an angle")
        angle = -angle if stmt.word == "cw" else angle
        return Travel(stmt.body, "turns", angle=angle, stops=stops, line=line, column=column)
    assert stmt.direction is not None
    distance = builder.value(stmt.value, LENGTH, "a distance", POSITIVE)
    direction = builder.direction(stmt.direction)
    return Travel(
        stmt.body,
        "by",
        distance=distance,
        direction=direction,
        stops=stops,
        line=line,
        column=column,
    )


def _load(builder: _Builder, stmt: SceneStmt, links: set[str]) -> Load:
    """A force or couple; a couple may act on a link (its work counts between states)."""
    if stmt.kind == "couple" and stmt.body in links:
        return Load(
            "couple",
            stmt.name,
            stmt.body,
            sense=-1 if stmt.word == "cw" else 1,
            line=stmt.line,
            column=stmt.column,
        )
    body = builder.body(stmt.body, stmt.line, stmt.column)
    if stmt.kind == "couple":
        return Load(
            "couple",
            stmt.name,
            body.name,
            sense=-1 if stmt.word == "cw" else 1,
            line=stmt.line,
            column=stmt.column,
        )
    assert stmt.location is not None and stmt.direction is not None
    point, name = builder.location(body, stmt.location)
    direction = builder.direction(stmt.direction, point)
    return Load(
        "force", stmt.name, body.name, point, name, direction, line=stmt.line, column=stmt.column
    )


def momentum_event(builder: _Builder, stmt: SceneStmt) -> Clutch | Reshape:
    """``clutch A with B`` or ``change B: gyration k`` / ``inertia I`` (a rigid body's)."""
    body = builder.body(stmt.body, stmt.line, stmt.column)
    if stmt.kind == "clutch":
        other = builder.body(stmt.other, stmt.line, stmt.column)
        for rotor in (body, other):
            if rotor.particle:
                raise SpecError(
                    f"{rotor.name} is a particle: a clutch locks two rotors",
                    builder.where(stmt.line, stmt.column),
                    hint="give each rotor an inertia (a shape, gyration or inertia) and a pin",
                )
        return Clutch(stmt.body, stmt.other, stmt.line, stmt.column)
    assert stmt.value is not None
    if body.particle:
        raise SpecError(
            f"{body.name} is a particle: it has no inertia of its own to change",
            builder.where(stmt.line, stmt.column),
            hint="give it a shape, gyration or inertia in its body line",
        )
    if stmt.word == "gyration":
        k = builder.value(stmt.value, Dim(1, 0, 0), "a radius of gyration", POSITIVE)
        I_G = from_gyration(body.mass, k)
    else:
        I_G = builder.value(stmt.value, Dim(2, 1, 0), "a moment of inertia", POSITIVE)
    how = f"{stmt.word} {expr_text(stmt.value, str)}"
    return Reshape(stmt.body, I_G, how, stmt.line, stmt.column)


_UNSET: Vec = (sympy.nan, sympy.nan)  # an impact written without its line, until resolved


def embedded_line(
    builder: _Builder, impact: Impact, supports: list[Support], headings: Mapping[str, Vec]
) -> Vec:
    """The line of an impact written without one: a particle given its velocity that
    embeds (e 0) in a pinned body strikes along that velocity; anything else needs it."""
    pinned = any(s.body == impact.other and s.kind == "pin" for s in supports)
    plastic = real_value(impact.e, builder.given_values) == 0
    if pinned and plastic and impact.body in headings:
        return headings[impact.body]
    raise SpecError(
        "this impact needs its line of impact",
        builder.where(impact.stmt_line, impact.column),
        hint="add ', line DIR' (from the first body toward the second); it may be left out "
        "only for a particle given its velocity that embeds (e 0) in a pinned body",
    )
