"""The 3D scene of a spec: one rigid body turning about a fixed axis on its bearings.

Lines (docs/scene-mode.md, *Rigid bodies in 3D*): ``body`` with a mass and a shape of
the 3D table (or ``inertia B: I_x, I_y, I_z``) at a 3D position; ``axis B: (x, y, z)``
(the body's z axis: a disk's or rod's axis) or ``axes B: (x-axis), (y-axis)``;
``rotates B: about (ux, uy, uz), through (x, y, z), omega EXPR [, alpha EXPR]`` (ω and α
along the axis by the right-hand rule); ``spins`` and ``nutates`` lines (the body's turns
relative to that frame: ω = φ̇ K + θ̇ i' + ψ̇ k); ``bearing A: at (x, y, z),
journal|thrust|ball|pin|fixed``;
``torque M on B`` (about the axis); ``gravity`` (−y: y is up). Between two states:
``rolls B at (x, y, z)`` (B's point there is at rest: it rolls on a fixed gear) and
``travel B: turns EXPR about (ux, uy, uz)`` (state 2: the turning frame has turned
through EXPR; state 1 at rest or, with ``, from omega W``, turning at W; the rates
those of state 2). A name in a position that
is not a given but is in find is an unknown angle (a steady angle), its root chosen by
``assume`` lines (``assume theta_s > 0``).

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec('''
... given:
...   m = 10 kg
...   r = 0.1 m
...   w = 30 rad/s
...   L = 0.2 m
... scene:
...   body gear: mass m, disk r, at (0, 0, 0)
...   axis gear: (1, 0, 0)
...   rotates gear: about (1, 0, 0), through (0, 0, 0), omega w
...   bearing A: at (-L, 0, 0), thrust
...   bearing B: at (L, 0, 0), journal
...   gravity
... find: A_y
... ''', "g.dyn")
>>> scene = read_scene3d(spec)
>>> scene.body.name, [b.kind for b in scene.bearings], scene.spin.axis
('gear', ['thrust', 'journal'], (1, 0, 0))
"""

from __future__ import annotations

import difflib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import sympy

from dynsolve.dimensions import check_dimensions
from dynsolve.errors import DimensionError, Position, SpecError
from dynsolve.expressions import relation, to_sympy
from dynsolve.model.physical import NOT_NEGATIVE, POSITIVE
from dynsolve.model.scene import SceneReader, scene_reader
from dynsolve.modes.equation_mode import givens_of
from dynsolve.rigid3d.inertia import Vec3, body_axes, physical_problem, principal, tensor, unit
from dynsolve.spec.ast import EquationStmt, Expr, Name, SceneStmt, Spec
from dynsolve.spec.parser import iter_names
from dynsolve.system import Constraint
from dynsolve.units import Dim

LENGTH, MASS = Dim.of("length"), Dim.of("mass")
MOMENT_OF_INERTIA = Dim(2, 1, 0)
KINDS_3D = frozenset(
    {
        "axis",
        "axes",
        "inertia3",
        "rotates",
        "spins",
        "nutates",
        "bearing",
        "torque",
        "rolls3",
        "travel3",
    }
)
LINES_3D = KINDS_3D | {"body", "gravity", "assume"}  # every line a 3D scene takes


@dataclass(frozen=True)
class Body3D:
    """A rigid body: mass, G, and its inertia tensor about G in scene axes."""

    name: str
    mass: sympy.Expr
    G: Vec3
    I_G: sympy.Matrix
    principal: tuple[sympy.Expr, sympy.Expr, sympy.Expr]
    axes: tuple[Vec3, Vec3, Vec3]
    shape: str
    products: tuple[sympy.Expr, sympy.Expr, sympy.Expr] | None = None


@dataclass(frozen=True)
class Spin:
    """Rotation about a fixed axis (unit ``axis``) through ``through``: ω, α along it."""

    axis: Vec3
    through: Vec3
    omega: sympy.Expr
    alpha: sympy.Expr
    line: int = 0


@dataclass(frozen=True)
class SpinOf:
    """A turn about ``axis`` through ``through`` (G when not given: a rotor's spin)
    relative to the frame before it, which carries the axis: the body's spin relative to
    the ``rotates`` frame (the precession; a shaft carrying the pin of a bar), or a
    ``nutates`` line's turn of the body's axis (then the spin is relative to it)."""

    axis: Vec3
    omega: sympy.Expr
    alpha: sympy.Expr
    through: Vec3 | None = None


@dataclass(frozen=True)
class Bearing:
    """A bearing on the shaft: a journal carries loads across the shaft, a thrust also
    along it; a ball joint (``ball``), anywhere, carries loads every way; a ``pin``
    (hinge) carries loads every way and couples across its axis (the shaft's); a
    ``fixed`` support (the arm or motor that holds and drives the body) carries loads and
    couples every way: its couple is the moment needed."""

    name: str
    at: Vec3
    kind: str
    line: int = 0
    column: int = 0


@dataclass(frozen=True)
class Rolling:
    """A point of the body (scene coordinates) that rolls without slipping on a fixed
    surface (a fixed gear's pitch circle): its velocity is zero."""

    at: Vec3
    line: int = 0
    column: int = 0


@dataclass(frozen=True)
class Travel3D:
    """State 2 of a two-state 3D scene: the turning frame has turned through ``angle``
    about ``axis`` (a unit vector along the ``rotates`` axis, either way); in state 1 the
    frame turns at ``omega_1`` (None: at rest)."""

    angle: sympy.Expr
    axis: Vec3
    line: int = 0
    column: int = 0
    omega_1: sympy.Expr | None = None


@dataclass(frozen=True)
class Scene3D:
    """One body on a fixed axis with its bearings and loads."""

    file: str
    body: Body3D
    spin: Spin
    bearings: tuple[Bearing, ...]
    gravity: Vec3 | None
    torques: tuple[str, ...] = ()
    symbols: Mapping[str, sympy.Symbol] = field(default_factory=dict)
    values: Mapping[sympy.Symbol, sympy.Expr] = field(default_factory=dict)
    spin_of: SpinOf | None = None
    rates: Mapping[sympy.Symbol, Dim] = field(default_factory=dict)  # unknown ω or α
    rolling: tuple[Rolling, ...] = ()
    travel: Travel3D | None = None
    angles: Mapping[sympy.Symbol, Dim] = field(default_factory=dict)  # unknown, in positions
    assumptions: tuple[Constraint, ...] = ()  # 'assume' lines: which root of an angle
    nutation: SpinOf | None = None  # the body's axis turning in the precessing frame

    @property
    def shaft(self) -> Vec3:
        """The axis the bearings' reactions are named across: the spin's, else the turn's."""
        return self.spin_of.axis if self.spin_of is not None else self.spin.axis


def is_3d(spec: Spec) -> bool:
    """Whether a spec's scene is 3D (it has a 3D line: rotates, bearing, axis, …).

    >>> from dynsolve.spec.parser import parse_spec
    >>> is_3d(parse_spec("scene:\\n  bearing A: at (0, 0, 1), journal\\nfind: A_x\\n"))
    True
    """
    return any(stmt.kind in KINDS_3D for stmt in spec.scene or ())


def read_scene3d(spec: Spec) -> Scene3D:
    """The 3D scene of ``spec``; a positioned SpecError for a line it cannot take."""
    givens = givens_of(spec)
    symbols = {g.name: g.symbol for g in givens}
    values = {g.symbol: g.value for g in givens if g.value is not None}
    statements = tuple(spec.scene or ())
    angles = _unknown_angles(spec, statements, symbols)
    dims = {g.name: g.dim for g in givens} | {a.name: Dim() for a in angles}
    reader = scene_reader(spec, {**symbols, **{a.name: a for a in angles}}, dims, values)
    bodies = [s for s in statements if s.kind == "body"]
    for stmt in statements:
        if stmt.kind not in LINES_3D:
            raise SpecError(
                f"a '{stmt.kind}' line cannot go in a 3D scene",
                Position(spec.file, stmt.line, stmt.column),
                hint="a 3D scene takes body, axis, axes, inertia, rotates, spins, bearing, "
                "torque, gravity, 'rolls B at (x, y, z)' and 'travel B: turns EXPR about "
                "(ux, uy, uz)' lines (docs/scene-mode.md, Rigid bodies in 3D)",
            )
    if len(bodies) != 1:
        where = bodies[1] if bodies else (statements[0] if statements else None)
        raise SpecError(
            "a 3D scene holds one body turning about a fixed axis (for now)",
            Position(spec.file, where.line if where else 1, where.column if where else 1),
            hint="describe one 'body' (several bodies in 3D are not supported yet)",
        )
    body = _body(bodies[0], statements, reader, spec)
    spins = [s for s in statements if s.kind == "rotates"]
    if len(spins) != 1 or spins[0].body != body.name:
        where = spins[1] if len(spins) > 1 else bodies[0]
        raise SpecError(
            f"say how {body.name} turns: one 'rotates {body.name}: about (ux, uy, uz), "
            "through (x, y, z), omega w' line",
            Position(spec.file, where.line, where.column),
            hint="ω and α are along the axis by the right-hand rule",
        )
    rates: dict[sympy.Symbol, Dim] = {}
    spin = _spin(spins[0], reader, spec, rates)
    nutation = _nutation(statements, body, reader, spec, rates)
    spin_of = None
    own = [s for s in statements if s.kind == "spins"]
    if own:
        spin_of = _spin_of(own[0], body, reader, spec, rates)
    bearings = tuple(
        Bearing(
            s.name, _vector3(reader, s.vectors[0], "a bearing's position"), s.word, s.line, s.column
        )
        for s in statements
        if s.kind == "bearing"
    )
    gravity = None
    if any(s.kind == "gravity" for s in statements):
        gravity = (sympy.Integer(0), sympy.Integer(-1), sympy.Integer(0))
    torques = tuple(s.name for s in statements if s.kind == "torque")
    for stmt in statements:
        if stmt.kind in ("torque", "rolls3", "travel3") and stmt.body != body.name:
            raise SpecError(
                f"there is no body '{stmt.body}'",
                Position(spec.file, stmt.line, stmt.column),
                hint=f"the body is {body.name}" + _did_you_mean(stmt.body, [body.name]),
            )
    rolling = tuple(
        Rolling(_vector3(reader, s.vectors[0], "a rolling contact's position"), s.line, s.column)
        for s in statements
        if s.kind == "rolls3"
    )
    travel = _travel(statements, spin, reader, spec)
    shaft = spin_of.axis if spin_of is not None else spin.axis
    _check_shaft(shaft, bearings, own[0] if own else spins[0], spec)
    named = [b for b in bearings if b.kind in ("journal", "thrust", "pin")]
    if nutation is not None and named:
        raise SpecError(
            f"bearing {named[0].name} ({named[0].kind}) is named across one shaft, but a "
            "nutating body turns about two (the nutation's and the spin's)",
            Position(spec.file, named[0].line, named[0].column),
            hint="hold the body by a 'fixed' support (force and couple every way: the moment "
            "needed) or a 'ball' joint",
        )
    if nutation is not None and (travel is not None or rolling):
        stmt = next(s for s in statements if s.kind == "nutates")
        raise SpecError(
            "a nutating body is solved at an instant: not between two states (yet)",
            Position(spec.file, stmt.line, stmt.column),
            hint="leave out the travel and rolls lines, or the nutates line",
        )
    if any(s.kind == "assume" for s in statements):  # an unknown rate may be bounded too
        reader = scene_reader(
            spec,
            {**symbols, **{a.name: a for a in angles}, **{r.name: r for r in rates}},
            dims | {r.name: d for r, d in rates.items()},
            values,
        )
    unknowns = {*angles, *rates}
    assumptions = tuple(
        _assumption(s, reader, spec, unknowns) for s in statements if s.kind == "assume"
    )
    return Scene3D(
        spec.file,
        body,
        spin,
        bearings,
        gravity,
        torques,
        symbols,
        values,
        spin_of,
        rates,
        rolling,
        travel,
        angles,
        assumptions,
        nutation,
    )


POSITIONED = frozenset({"body", "axis", "axes", "bearing", "rotates", "spins", "nutates"})


def _unknown_angles(
    spec: Spec, statements: Sequence[SceneStmt], symbols: Mapping[str, sympy.Symbol]
) -> dict[sympy.Symbol, Dim]:
    """Names in the scene's positions and directions that are not givens but are asked
    for in find: unknown angles of the position (a bar's steady angle on a turning
    shaft), and the names of ``steady(theta)`` finds (the scene drawn at a given angle).
    Any other name that is not a given stays an error (a typo)."""
    asked = {
        item.ref.function if item.ref and not item.ref.args else item.name for item in spec.finds
    }
    found: dict[sympy.Symbol, Dim] = {}
    for stmt in statements:
        if stmt.kind not in POSITIONED:
            continue
        vectors = list(stmt.vectors)
        vectors += [p.vector for p in stmt.props if p.key == "at3" and p.vector]
        for vector in vectors:
            for component in vector:
                for name in iter_names(component):
                    text = name.text
                    if text in symbols or text == "pi" or text not in asked:
                        continue
                    found[sympy.Symbol(text, real=True)] = Dim()
    for item in spec.finds:  # 'theta_s = steady(theta)': the angle at rest in the frame
        if item.ref is not None and item.ref.function == "steady":
            found[sympy.Symbol(item.name, real=True)] = Dim()
    return found


def _assumption(
    stmt: SceneStmt, reader: SceneReader, spec: Spec, unknowns: set[sympy.Symbol]
) -> Constraint:
    """An ``assume`` line of a 3D scene: a range of an unknown angle or rate (which root is
    meant: ``assume theta_s > 0``, ``assume theta_s < pi/2``, or a top's slow precession
    ``assume W_p < w_s``), both sides of one dimension."""
    where = Position(spec.file, stmt.line, stmt.column)
    lhs_text, rhs_text = stmt.vectors[0]
    probe = EquationStmt(lhs_text, stmt.word, rhs_text, "", "", stmt.line, stmt.column)  # type: ignore[arg-type]
    try:
        check_dimensions((probe,), {**reader.dims, "pi": Dim()}, spec.file)
    except DimensionError as error:
        raise DimensionError(
            error.message, error.position, "both sides of an assume line have one dimension"
        ) from None
    lhs, rhs = (to_sympy(text, reader.symbols) for text in (lhs_text, rhs_text))
    try:
        built = relation(stmt.word, lhs, rhs)
    except TypeError:
        raise SpecError("this assumption compares a value that is not real", where, "") from None
    if built in (sympy.true, sympy.false) or not built.free_symbols & unknowns:
        raise SpecError(
            "an assume line of a 3D scene bounds an unknown of the scene (an angle or a rate)",
            where,
            hint="e.g. 'assume theta_s > 0' with theta_s in a position and in find",
        )
    text = f"assume {sympy.sstr(lhs)} {stmt.word} {sympy.sstr(rhs)}"
    return Constraint(built, text, stmt.line)


def _did_you_mean(name: str, names: Sequence[str]) -> str:
    hint = close_name(name, names)
    return f" ({hint})" if hint else ""


def _travel(
    statements: Sequence[SceneStmt], spin: Spin, reader: SceneReader, spec: Spec
) -> Travel3D | None:
    """The scene's one ``travel B: turns EXPR about (u)`` line, its axis the turn's."""
    travels = [s for s in statements if s.kind == "travel3"]
    if not travels:
        return None
    stmt = travels[-1]
    where = Position(spec.file, stmt.line, stmt.column)
    if len(travels) > 1:
        raise SpecError(
            "a 3D scene has one travel line (one state 2)",
            where,
            hint="keep one 'travel B: turns EXPR about (ux, uy, uz)'",
        )
    assert stmt.value is not None
    angle = reader.value(stmt.value, Dim(), "a turn (an angle: 2 rev, 90 deg)")
    axis = _direction3(reader, stmt.vectors[0], where)
    along = sympy.simplify(sum(a * b for a, b in zip(axis, spin.axis, strict=True)))
    if along not in (1, -1):
        raise SpecError(
            "the travel turns the frame about its own axis: the direction must be the "
            "'rotates' line's axis (or its opposite)",
            where,
            hint=f"write 'about ({', '.join(sympy.sstr(c) for c in spin.axis)})'",
        )
    start = [p for p in stmt.props if p.key == "from"]
    omega_1 = (
        reader.value(start[0].values[0], Dim(0, 0, -1), "the frame's rate in state 1")
        if start
        else None
    )
    return Travel3D(angle, axis, stmt.line, stmt.column, omega_1)


def _vector3(reader: SceneReader, vector: Sequence[Expr], what: str) -> Vec3:
    x, y, z = (reader.value(c, LENGTH, what) for c in vector)
    return (x, y, z)


def _direction3(reader: SceneReader, vector: Sequence[Expr], where: Position) -> Vec3:
    """A direction: numbers, or lengths (such as a side of the body), normalised."""
    try:
        components = tuple(reader.value(c, Dim(), "a direction's component") for c in vector)
    except DimensionError:
        components = tuple(reader.value(c, LENGTH, "a direction's component") for c in vector)
    try:
        return unit(components)
    except ValueError as error:
        raise SpecError(str(error), where, "give a nonzero direction") from None


def _body(
    stmt: SceneStmt, statements: Sequence[SceneStmt], reader: SceneReader, spec: Spec
) -> Body3D:
    where = Position(spec.file, stmt.line, stmt.column)
    props = {p.key: p for p in stmt.props}
    if "at" in props:
        raise SpecError(
            "a body in a 3D scene is placed with three coordinates",
            where,
            hint="write 'at (x, y, z)'",
        )
    if "mass" in props:
        m = reader.value(props["mass"].values[0], MASS, "a mass", POSITIVE)
    elif "weight" in props:
        g = reader.symbols.get("g")
        m = reader.value(props["weight"].values[0], Dim.of("force"), "a weight", POSITIVE) / g
    else:
        raise SpecError(f"body {stmt.name} needs a mass", where, "add 'mass m'")
    G = (
        _vector3(reader, props["at3"].vector, "a position")
        if "at3" in props
        else (sympy.Integer(0),) * 3
    )  # type: ignore[arg-type]
    shapes = [p for p in stmt.props if p.key == "shape"]
    explicit = [s for s in statements if s.kind == "inertia3" and s.body == stmt.name]
    products: tuple[sympy.Expr, ...] | None = None
    if explicit:
        moments = tuple(
            reader.value(e, MOMENT_OF_INERTIA, "a moment of inertia", NOT_NEGATIVE)
            for e in explicit[0].vectors[0]
        )
        shape = "given principal moments"
        if len(explicit[0].vectors) > 1:
            products = tuple(
                reader.value(e, MOMENT_OF_INERTIA, "a product of inertia")
                for e in explicit[0].vectors[1]
            )
            shape = "given moments and products of inertia"
    elif shapes:
        sizes = tuple(reader.value(v, LENGTH, "a size", POSITIVE) for v in shapes[0].values)
        try:
            moments = principal(shapes[0].word, m, sizes)
        except ValueError as error:
            raise SpecError(str(error), where, "see the 3D shape table") from None
        shape = shapes[0].word
    else:
        raise SpecError(
            f"body {stmt.name} needs its inertia: a shape (disk r, plate a by b, …) or "
            f"'inertia {stmt.name}: I_x, I_y, I_z'",
            where,
            hint="see the 3D shape table in docs/scene-mode.md",
        )
    z_axis: Vec3 = (sympy.Integer(0), sympy.Integer(0), sympy.Integer(1))
    x_axis: Vec3 | None = None
    spinning = [
        s for s in statements if s.kind == "spins" and s.body == stmt.name and len(s.vectors) == 1
    ]
    if spinning:  # a rotor's z is its spin axis unless said otherwise
        z_axis = _direction3(
            reader, spinning[0].vectors[0], Position(spec.file, stmt.line, stmt.column)
        )
    for line in statements:
        if line.body != stmt.name or line.kind not in ("axis", "axes"):
            continue
        at = Position(spec.file, line.line, line.column)
        if line.kind == "axis":
            z_axis = _direction3(reader, line.vectors[0], at)
        else:
            x_axis = _direction3(reader, line.vectors[0], at)
            y_axis = _direction3(reader, line.vectors[1], at)
            z_axis = (
                x_axis[1] * y_axis[2] - x_axis[2] * y_axis[1],
                x_axis[2] * y_axis[0] - x_axis[0] * y_axis[2],
                x_axis[0] * y_axis[1] - x_axis[1] * y_axis[0],
            )
    has_axis = any(line.body == stmt.name and line.kind == "axis" for line in statements)
    has_axis = has_axis or bool(spinning)
    if products is not None and x_axis is None and not has_axis:
        # no axis lines: the body axes are the scene's, x = (1, 0, 0) and z = (0, 0, 1)
        x_axis = (sympy.Integer(1), sympy.Integer(0), sympy.Integer(0))
    if products is not None and any(p != 0 for p in products) and x_axis is None:
        # products of inertia belong to a pair of body axes: with 'axis' alone, x and y
        # would be an arbitrary pair about z
        raise SpecError(
            f"body {stmt.name}'s products of inertia are about its x, y, z axes, "
            "but only its z axis is given",
            where,
            hint=f"write 'axes {stmt.name}: (x-axis), (y-axis)' in scene coordinates "
            "(without axis lines the body axes are the scene's)",
        )
    if x_axis is None and sympy.simplify(moments[0] - moments[1]) != 0:
        raise SpecError(
            f"body {stmt.name} is not symmetric about its z axis (I_x ≠ I_y): give both "
            "of its x and y axes",
            where,
            hint=f"write 'axes {stmt.name}: (x-axis), (y-axis)' in scene coordinates",
        )
    axes = body_axes(z_axis, x_axis)
    if products is not None:
        # only where products are given: principal moments alone are taken as written
        # (a seed's thin gear sits at I_z = I_x + I_y, and its graded variants vary I_z
        # and I_x apart)
        _check_physical(stmt.name, moments, products, reader, where)
    I_G = tensor(moments, axes, products)
    return Body3D(stmt.name, m, G, I_G, moments, axes, shape, products)  # type: ignore[arg-type]


def _check_physical(
    name: str,
    moments: Sequence[sympy.Expr],
    products: Sequence[sympy.Expr],
    reader: SceneReader,
    where: Position,
) -> None:
    """Refuse moments and products of inertia that no rigid body has (a negative principal
    moment, or one larger than the other two together), when the givens are numbers."""
    J = tensor(moments, body_axes((0, 0, 1), (1, 0, 0)), products)  # type: ignore[arg-type]
    J = J.xreplace(reader.given_values)
    if J.free_symbols:
        return
    why = physical_problem(J)
    if why is not None:
        raise SpecError(
            f"the inertia given for {name} is not a rigid body's: {why}",
            where,
            hint="products of inertia are I_xy = ∫ x y dm (the tensor holds −I_xy); "
            "check their signs and sizes",
        )


def _spin(stmt: SceneStmt, reader: SceneReader, spec: Spec, rates: dict[sympy.Symbol, Dim]) -> Spin:
    where = Position(spec.file, stmt.line, stmt.column)
    axis = _along_an_axis(_direction3(reader, stmt.vectors[0], where), where)
    through = _vector3(reader, stmt.vectors[1], "a point of the axis")
    omega, alpha = _rates(stmt, reader, rates)
    return Spin(axis, through, omega, alpha, stmt.line)


def _spin_of(
    stmt: SceneStmt, body: Body3D, reader: SceneReader, spec: Spec, rates: dict[sympy.Symbol, Dim]
) -> SpinOf:
    where = Position(spec.file, stmt.line, stmt.column)
    if stmt.body != body.name:
        raise SpecError(f"there is no body '{stmt.body}'", where, hint=f"the body is {body.name}")
    axis = _direction3(reader, stmt.vectors[0], where)
    through = (
        _vector3(reader, stmt.vectors[1], "a point of the axis") if len(stmt.vectors) > 1 else None
    )
    omega, alpha = _rates(stmt, reader, rates)
    return SpinOf(axis, omega, alpha, through)


def _nutation(
    statements: Sequence[SceneStmt],
    body: Body3D,
    reader: SceneReader,
    spec: Spec,
    rates: dict[sympy.Symbol, Dim],
) -> SpinOf | None:
    """The scene's one ``nutates B: about (n), through (P), omega w [, alpha a]`` line:
    the body's axis turns about n through P, which the precessing frame carries (Hibbeler
    20.1: ω = φ̇ K + θ̇ i' + ψ̇ k, the nutation θ̇ about i')."""
    lines = [s for s in statements if s.kind == "nutates"]
    if not lines:
        return None
    stmt = lines[-1]
    where = Position(spec.file, stmt.line, stmt.column)
    if len(lines) > 1:
        raise SpecError(
            "a 3D scene has one nutates line", where, hint="keep one 'nutates B: about (n), …'"
        )
    if stmt.body != body.name:
        raise SpecError(
            f"there is no body '{stmt.body}'",
            where,
            hint=f"the body is {body.name}" + _did_you_mean(stmt.body, [body.name]),
        )
    axis = _direction3(reader, stmt.vectors[0], where)
    through = _vector3(reader, stmt.vectors[1], "a point of the axis")
    omega, alpha = _rates(stmt, reader, rates)
    return SpinOf(axis, omega, alpha, through)


def _check_shaft(shaft: Vec3, bearings: Sequence[Bearing], stmt: SceneStmt, spec: Spec) -> None:
    """A journal, thrust or pin bearing names its reactions across the shaft (the spin's
    axis, else the turn's), which must then lie along x, y or z; a ball or fixed support
    takes any axis (a top's tilted spin axis)."""
    named = [b for b in bearings if b.kind in ("journal", "thrust", "pin")]
    if named and sum(1 for c in shaft if c != 0) != 1:
        raise SpecError(
            f"bearing {named[0].name} ({named[0].kind}) lies on a shaft that is not along x, "
            "y or z: its reactions are named across the shaft by those axes",
            Position(spec.file, stmt.line, stmt.column),
            hint="choose the scene axes with the shaft along one of them, or hold the body "
            "by a 'ball' or 'fixed' support",
        )


def _along_an_axis(axis: Vec3, where: Position) -> Vec3:
    if sum(1 for c in axis if c != 0) != 1:
        raise SpecError(
            "the axis of rotation must lie along x, y or z (the bearings' reactions are "
            "named by those axes)",
            where,
            hint="choose the scene axes with the shaft along one of them",
        )
    return axis


def _rates(
    stmt: SceneStmt, reader: SceneReader, rates: dict[sympy.Symbol, Dim]
) -> tuple[sympy.Expr, sympy.Expr]:
    """ω and α of a ``rotates`` or ``spins`` line: expressions of the givens, or a name
    that is not a given (an unknown rate, found: a steady precession's Ω)."""
    assert stmt.value is not None
    expressions = [(stmt.value, Dim(0, 0, -1), "an angular velocity")]
    if stmt.props:
        expressions.append((stmt.props[0].values[0], Dim(0, 0, -2), "an angular acceleration"))
    found = []
    for expr, dim, what in expressions:
        if isinstance(expr, Name) and expr.text not in reader.symbols and expr.text != "pi":
            symbol = sympy.Symbol(expr.text, real=True)
            rates[symbol] = dim
            found.append(symbol)
        else:
            found.append(reader.value(expr, dim, what))
    return found[0], found[1] if len(found) > 1 else sympy.Integer(0)


def close_name(name: str, names: Sequence[str]) -> str:
    """A did-you-mean hint for ``name`` among ``names``."""
    close = difflib.get_close_matches(name, list(names), n=1)
    return f"did you mean '{close[0]}'?" if close else ""
