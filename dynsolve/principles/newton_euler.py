"""Newton–Euler equations of a planar scene: free-body diagrams, ΣF = m a_G, ΣM, constraints.

Each body gets the textbook's equations for its motion: translation (ΣF = m a_G,
ΣM = 0 about G or a kinetic moment about a better point), fixed-axis rotation about a
pin (n-t components and ΣM_O = I_O α) or general plane motion (ΣM_P = I_G α +
(r_G/P × m a_G) with P chosen to eliminate unknown reactions, and said why). Kinematic
constraints come from the supports: contact kept, no slip, rolling, taut cords.

Nothing here solves; the result is an equation system and the diagrams as data.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, field
from typing import Any

import sympy

from dynsolve.model.scene import Body, Cord, CordState, Scene, Support, Vec
from dynsolve.model.stages import StageRecord, State
from dynsolve.names import pretty
from dynsolve.numbers import real_value, tidy
from dynsolve.system import Constraint, Equation
from dynsolve.units import Dim


class VelocityConflict(ValueError):
    """The velocities a spec gives contradict a constraint of the scene (a cord's ends
    moving differently along it): refused wherever the instant is written, never skipped."""


FORCE, ACCELERATION, LENGTH = Dim.of("force"), Dim.of("acceleration"), Dim.of("length")
ANGULAR_ACCELERATION, MOMENT = Dim.of("angular_acceleration"), Dim.of("moment")


# Set only by the grading diagnosis (dynsolve.grade.diagnose): the classic mistake of taking
# I_G for the moment of inertia about a pin away from G, re-solved to name a student's number.
PARALLEL_AXIS_FORGOTTEN: ContextVar[bool] = ContextVar("parallel_axis_forgotten", default=False)


@contextmanager
def parallel_axis_forgotten() -> Iterator[None]:
    """Within the block, a pinned body's I about its pin is taken as I_G (the mistake).

    >>> with parallel_axis_forgotten():
    ...     PARALLEL_AXIS_FORGOTTEN.get()
    True
    >>> PARALLEL_AXIS_FORGOTTEN.get()
    False
    """
    token = PARALLEL_AXIS_FORGOTTEN.set(True)
    try:
        yield
    finally:
        PARALLEL_AXIS_FORGOTTEN.reset(token)


@dataclass(frozen=True)
class ForceTerm:
    """A force on a body's free-body diagram: magnitude along a unit direction at a point."""

    name: str
    # "weight", "applied", "tension", "spring", "link", "reaction", "traction", "friction"
    kind: str
    body: str
    point: Vec
    point_name: str
    direction: Vec
    magnitude: sympy.Expr  # a symbol (known or unknown) or an expression (μk N)
    known: bool

    @property
    def vector(self) -> Vec:
        """The force as a vector."""
        return (self.magnitude * self.direction[0], self.magnitude * self.direction[1])


@dataclass(frozen=True)
class CoupleTerm:
    """A couple moment on a body (signed, counterclockwise positive)."""

    name: str
    body: str
    moment: sympy.Expr
    known: bool


@dataclass(frozen=True)
class Kinematics:
    """How a body moves at the instant: α, a_G and ω as expressions of the unknowns."""

    motion: str  # "translation", "rotation", "general", "particle"
    alpha: sympy.Expr
    a_G: Vec
    omega: sympy.Expr
    pin: Support | None = None
    # on incline axes with no normal component: a_G = along · tangent (tangent down the slope)
    tangent: Vec | None = None
    along: sympy.Expr | None = None


@dataclass(frozen=True)
class Formulation:
    """The scene's equations, unknowns (with dimensions), diagrams and named quantities."""

    equations: tuple[Equation, ...]
    unknowns: Mapping[sympy.Symbol, Dim]
    forces: Mapping[str, tuple[ForceTerm, ...]]
    couples: Mapping[str, tuple[CoupleTerm, ...]]
    kinematics: Mapping[str, Kinematics]
    moment_points: Mapping[str, str]
    reactions: Mapping[str, tuple[sympy.Symbol, Vec]]  # unknown force name → (symbol, axis)
    kinetic: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    derived: Mapping[sympy.Symbol, tuple[sympy.Expr, Dim, str]] = field(default_factory=dict)
    after: Mapping[str, Vec] = field(default_factory=dict)  # velocities after an impact
    after_omega: Mapping[str, sympy.Expr] = field(default_factory=dict)  # ω after an impact
    speeds: Mapping[str, sympy.Expr] = field(default_factory=dict)  # |v_G| in state 2
    spins: Mapping[str, sympy.Expr] = field(default_factory=dict)  # ω in state 2 (ccw +)
    notes: tuple[tuple[str, str], ...] = ()  # (name, derivation) shown with the checks
    # contacts whose point slips at the instant (given velocities): v_P·t, kinetic friction
    sliding: Mapping[str, sympy.Expr] = field(default_factory=dict)
    # over an interval: a sliding contact's slip v_P·t at its start and its end
    interval_slips: Mapping[str, tuple[sympy.Expr, sympy.Expr]] = field(default_factory=dict)
    # an unknown's value found by a second method: (unknown, value, how, what it measures)
    second: tuple[tuple[sympy.Symbol, float, str, str], ...] = ()
    states: tuple[State, ...] = ()  # the motion at each numbered state of a chain of stages
    stages: tuple[StageRecord, ...] = ()  # what each stage found, in order
    displacements: Mapping[str, Vec] = field(default_factory=dict)  # Δr_G over an interval
    # until events: (what, detail, value to check > 0 or None, its meaning)
    events: tuple[tuple[str, sympy.Expr, str], ...] = ()
    turns: Mapping[str, sympy.Expr] = field(default_factory=dict)  # angle turned round a centre
    heights: Mapping[str, sympy.Expr] = field(default_factory=dict)  # rise of G (up +)
    constraints: tuple[Constraint, ...] = ()  # root branches the formulation chose
    # work and energy term by term: ("T1", T1), ("U_W = W·Δr_G (disk)", U), …, ("T2", T2)
    energy_terms: tuple[tuple[str, sympy.Expr], ...] = ()
    # over an interval solved by impulse and momentum: (T1, each force's work, T2), checked
    interval_energy: tuple[sympy.Expr, Mapping[str, sympy.Expr], sympy.Expr] | None = None
    cords: tuple[CordState, ...] = ()  # elastic cords whose state at a travel's end was assumed
    # bodies whose force equations are written along and normal to an incline: why, in words
    axes: Mapping[str, str] = field(default_factory=dict)
    inclines: Mapping[str, InclineAxes] = field(default_factory=dict)  # and the axes


def bare_formulation(bodies: Iterable[str], **fields: Any) -> Formulation:
    """A formulation without equations of motion (impacts, states, paths): no forces,
    couples or reactions; ``fields`` fills the rest.

    >>> bare_formulation(["A"]).equations
    ()
    """
    empty: dict[str, tuple] = {name: () for name in bodies}
    base: dict[str, Any] = {
        "equations": (),
        "unknowns": {},
        "forces": empty,
        "couples": empty,
        "kinematics": {},
        "moment_points": {},
        "reactions": {},
    }
    return Formulation(**(base | fields))


def cross(r: Vec, f: Vec) -> sympy.Expr:
    """The z component of r × f.

    >>> cross((1, 0), (0, 2))
    2
    """
    return r[0] * f[1] - r[1] * f[0]


def dot(a: Vec, b: Vec) -> sympy.Expr:
    """a · b.

    >>> dot((1, 2), (3, 4))
    11
    """
    return a[0] * b[0] + a[1] * b[1]


def point_text(P: Vec, G: Vec) -> str:
    """An unnamed point, written relative to G: ``G + (r, 0)``.

    >>> import sympy
    >>> r = sympy.Symbol("r")
    >>> point_text((r, 0), (0, 0))
    'G + (r, 0)'
    """
    dx, dy = (tidy(P[0] - G[0]), tidy(P[1] - G[1]))
    return f"G + ({sympy.sstr(dx)}, {sympy.sstr(dy)})"


def _projected(forces: list[ForceTerm], axis: Vec) -> sympy.Expr:
    """Σ F·axis, each force's direction cosine simplified (so O_n·e_n reads O_n)."""
    return sympy.Add(*(f.magnitude * tidy(dot(f.direction, axis), light=False) for f in forces))


def _moment(forces: list[ForceTerm], couples: list[CoupleTerm], P: Vec) -> sympy.Expr:
    """Σ (r − P) × F + Σ couples, each moment arm simplified."""
    arms = (f.magnitude * tidy(cross(_minus(f.point, P), f.direction), light=False) for f in forces)
    return sympy.Add(*arms) + sympy.Add(*(c.moment for c in couples))


def _minus(a: Vec, b: Vec) -> Vec:
    return (a[0] - b[0], a[1] - b[1])


def _perp(r: Vec) -> Vec:
    """k × r."""
    return (-r[1], r[0])


def _is_zero(expr: sympy.Expr) -> bool:
    return bool(tidy(expr) == 0)


def point_acceleration(kin: Kinematics, G: Vec, point: Vec) -> Vec:
    """a_P = a_G + α k × r_P/G − ω² r_P/G of a point of a rigid body.

    >>> kin = Kinematics("general", sympy.Integer(2), (1, 0), sympy.Integer(3))
    >>> point_acceleration(kin, (0, 0), (0, -1))
    (3, 9)
    """
    r = _minus(point, G)
    return (
        kin.a_G[0] + kin.alpha * _perp(r)[0] - kin.omega**2 * r[0],
        kin.a_G[1] + kin.alpha * _perp(r)[1] - kin.omega**2 * r[1],
    )


def touches_at_rim(body: Body, support: Support) -> bool:
    """True when a round body touches the surface at its rim, straight below G along the
    normal: the contact point then moves round the body as it turns.

    >>> from dynsolve.model.scene import WORDS
    >>> r = sympy.Symbol("r", positive=True)
    >>> wheel = Body("w", 1, 1, (0, r), (0, r), "disk", (r,), {}, False, "", 0, 0)
    >>> touches_at_rim(wheel, Support("contact", "C", "w", (0, 0), WORDS["up"]))
    True
    """
    if body.radius is None:
        return False
    offset = _minus(body.G, support.point)
    return _is_zero(offset[0] - body.radius * support.normal[0]) and _is_zero(
        offset[1] - body.radius * support.normal[1]
    )


@dataclass(frozen=True)
class InclineAxes:
    """Axes along (t, down the slope) and normal (n, out of the surface) to an incline, or
    to a particle's curved path (n then toward the centre of curvature, as the textbook's
    ΣF_n = m v²/ρ).

    ``t`` and ``n`` are exact unit vectors in x–y; ``t_beta`` and ``n_beta`` are the same
    vectors written with the incline angle β (``(-cos β, -sin β)``), so that a weight
    projects as ``m g sin β`` rather than as a quotient of the slope's components.
    """

    support: str  # the contact whose normal gives the axes
    t: Vec
    n: Vec
    t_beta: Vec
    n_beta: Vec
    beta: sympy.Expr  # the incline angle (a given or a derived quantity)
    normal_fixed: bool  # a_G has no n component (the contact is kept): a_G = (a_G)_t t
    rolling: bool  # rolls without slip: (a_G)_t = α r, no acceleration unknown of its own
    # on a curved path: n points to the centre of curvature and (a_G)_n = v²/ρ (a given
    # quantity's value); normal_fixed is then False
    a_n: sympy.Expr | None = None

    def component(self, direction: Vec, axis: str) -> sympy.Expr:
        """direction · t (or · n): exactly ±1 or 0 for a direction along an axis, else in β.

        >>> b = sympy.Symbol("beta", positive=True)
        >>> c, s = sympy.cos(b), sympy.sin(b)
        >>> axes = InclineAxes("C", (-c, -s), (-s, c), (-c, -s), (-s, c), b, True, False)
        >>> axes.component((0, -1), "t"), axes.component((-s, c), "t")
        (sin(beta), 0)
        """
        exact, written = (self.t, self.t_beta) if axis == "t" else (self.n, self.n_beta)
        along = tidy(dot(direction, exact), light=False)
        if along.is_Number or _is_zero(cross(direction, exact)):
            return along
        return tidy(dot(direction, written), light=False)

    def cross(self, r: Vec, f: Vec) -> sympy.Expr:
        """The z component of r × f from their t and n components (in β, not the slope).

        >>> b = sympy.Symbol("beta", positive=True)
        >>> c, s = sympy.cos(b), sympy.sin(b)
        >>> axes = InclineAxes("C", (-c, -s), (-s, c), (-c, -s), (-s, c), b, True, False)
        >>> axes.cross((s, -c), (0, -1))
        -sin(beta)
        """
        handed = tidy(cross(self.t, self.n))  # ±1: t then n turn ccw (+1) or cw (−1)
        r_t, r_n = self.component(r, "t"), self.component(r, "n")
        f_t, f_n = self.component(f, "t"), self.component(f, "n")
        return tidy(handed * (r_t * f_n - r_n * f_t))


def _sign(expr: sympy.Expr, values: Mapping[sympy.Symbol, sympy.Expr]) -> int:
    """+1 or −1 where ``expr``'s sign is known (from the numbers or the symbols'
    assumptions), else 0."""
    value = real_value(expr, values)
    if value is not None:
        return 0 if abs(value) < 1e-12 else (1 if value > 0 else -1)
    expr = tidy(expr, light=False)
    if expr.is_positive:
        return 1
    if expr.is_negative:
        return -1
    return 0


def _incline_angle(t: Vec, side: int) -> sympy.Expr:
    """β with |t_x| = side·t_x = cos β and −t_y = sin β (t down the slope): ``θ`` itself
    when t is written with a given angle, else ``atan`` of the slope.

    >>> k = sympy.Symbol("k", positive=True)
    >>> _incline_angle((-1 / sympy.sqrt(1 + k**2), -k / sympy.sqrt(1 + k**2)), -1)
    atan(k)
    """
    across, down = tidy(side * t[0], light=False), tidy(-t[1], light=False)
    if isinstance(down, sympy.sin) and tidy(across - sympy.cos(down.args[0])) == 0:
        return down.args[0]
    return tidy(sympy.atan(down / across), light=False)


class _Writer:
    """Collects unknowns, forces and equations while walking the scene."""

    def __init__(
        self, scene: Scene, symbols: Mapping[str, sympy.Expr], slipping: Mapping[str, int]
    ):
        self.scene, self.symbols, self.slipping = scene, symbols, slipping
        self.unknowns: dict[sympy.Symbol, Dim] = {}
        self.equations: list[tuple[sympy.Expr, sympy.Expr, str]] = []
        self.constraints: list[tuple[sympy.Expr, sympy.Expr, str]] = []
        self.forces: dict[str, list[ForceTerm]] = {name: [] for name in scene.bodies}
        self.couples: dict[str, list[CoupleTerm]] = {name: [] for name in scene.bodies}
        self.reactions: dict[str, tuple[sympy.Symbol, Vec]] = {}
        self.kinematics: dict[str, Kinematics] = {}
        self.moment_points: dict[str, str] = {}
        self.kinetic: dict[str, tuple[str, ...]] = {}
        self.derived: dict[sympy.Symbol, tuple[sympy.Expr, Dim, str]] = {}
        self.several = len(scene.bodies) > 1
        self.notes: list[tuple[str, str]] = []  # shown with the checks (a slack cord)
        self.sliding: dict[str, sympy.Expr] = {}  # contacts slipping at the instant: v_P·t
        self.inclines: dict[str, InclineAxes] = {}  # bodies written along/normal to an incline
        self.incline_allowed = True
        self.axes: dict[str, str] = {}  # and why, in words

    # ---- names and symbols
    def unknown(self, name: str, dim: Dim) -> sympy.Symbol:
        symbol = sympy.Symbol(name, real=True)
        if name in self.symbols:
            raise ValueError(f"the unknown {name} would clash with a given of that name")
        self.unknowns.setdefault(symbol, dim)
        return symbol

    def magnitude(self, name: str, dim: Dim) -> tuple[sympy.Expr, bool]:
        """A load's magnitude: the given of that name, else a new unknown."""
        if name in self.symbols:
            return self.symbols[name], True
        return self.unknown(name, dim), False

    def suffix(self, name: str, body: str) -> str:
        return f"{name}_{body}" if self.several else name

    def equation(self, lhs: sympy.Expr, rhs: sympy.Expr, note: str) -> None:
        self.equations.append((lhs, rhs, note))

    def constraint(self, lhs: sympy.Expr, rhs: sympy.Expr, note: str) -> None:
        """A kinematic constraint; one that the axes already satisfy (0 = 0: a contact
        kept on incline axes, where a_G has no normal component) is not written."""
        if self.inclines:  # a_G = (a_G)_t t: the axes' cosines combine (sin² + cos² = 1)
            if _is_zero(lhs - rhs):
                return
            lhs, rhs = tidy(lhs), tidy(rhs)
        self.constraints.append((lhs, rhs, note))

    def numbered(self) -> tuple[Equation, ...]:
        """Equations of motion first, then the kinematic constraints, numbered (1), (2), …"""
        rows = self.equations + self.constraints
        return tuple(
            Equation(lhs, rhs, label=f"eq. {i}", line=i, note=note)
            for i, (lhs, rhs, note) in enumerate(rows, start=1)
        )

    # ---- kinematics of each body
    def motion(self, body: Body) -> str:
        stated = self.scene.motions.get(body.name)
        if stated:
            return stated
        mine = [s for s in self.scene.supports if s.body == body.name]
        if any(s.kind == "pin" for s in mine):
            return "rotation"
        if any(s.kind == "base" for s in mine):
            return "translation"
        if body.particle and len([s for s in mine if s.kind in ("contact", "rolls")]) >= 2:
            return "translation"  # no inertia given, resting on two supports: it translates
        if body.particle:
            return "particle"
        return "general"

    def body_kinematics(self, body: Body) -> Kinematics:
        motion = self.motion(body)
        omega = self.scene.omegas.get(body.name, self.omega_from_velocity(body))
        axes = self.incline_axes(body, motion, omega)
        if axes is not None:
            return self._incline_kinematics(body, motion, omega, axes)
        if motion in ("translation", "particle"):
            a_G = (
                self.unknown(self.suffix("a_Gx", body.name), ACCELERATION),
                self.unknown(self.suffix("a_Gy", body.name), ACCELERATION),
            )
            return Kinematics(motion, sympy.Integer(0), a_G, sympy.Integer(0))
        alpha = self.unknown(self.suffix("alpha", body.name), ANGULAR_ACCELERATION)
        if motion == "rotation":
            pin = next(s for s in self.scene.supports if s.kind == "pin" and s.body == body.name)
            r = _minus(body.G, pin.point)
            a_G = (alpha * _perp(r)[0] - omega**2 * r[0], alpha * _perp(r)[1] - omega**2 * r[1])
            return Kinematics(motion, alpha, a_G, omega, pin)
        a_G = (
            self.unknown(self.suffix("a_Gx", body.name), ACCELERATION),
            self.unknown(self.suffix("a_Gy", body.name), ACCELERATION),
        )
        return Kinematics(motion, alpha, a_G, omega)

    def incline_axes(self, body: Body, motion: str, omega: sympy.Expr) -> InclineAxes | None:
        """The axes along and normal to the incline a body rests on, as the textbook takes
        them: every support of the body is a contact, roll or base with one common normal
        that is neither vertical nor horizontal (a wall is not an incline), on a straight
        surface (no v²/ρ), under gravity straight down. None (x–y kept) for level problems,
        pins, contacts with different normals and anything else."""
        mine = [s for s in self.scene.supports if s.body == body.name]
        if not self.incline_allowed or motion == "rotation" or not mine:
            return None
        if self.scene.gravity is None:
            return None
        if any(s.kind not in ("contact", "rolls", "base") for s in mine):
            return None
        curved = any(not _is_zero(s.normal_acceleration) for s in mine)
        if curved and (motion != "particle" or len(mine) != 1):
            return None
        first = mine[0]
        if any(not _is_zero(cross(s.normal, first.normal)) for s in mine[1:]):
            return None
        if any(_sign(dot(s.normal, first.normal), self.scene.values) != 1 for s in mine[1:]):
            return None
        gravity = tuple(tidy(c, light=False) for c in self.scene.gravity)
        if gravity != (0, -1):
            return None
        values = self.scene.values
        side = _sign(first.tangent[0], values)
        downhill = _sign(dot(gravity, first.tangent), values)
        if side == 0 or downhill == 0:  # level, a wall, or a slope of unknown sense
            return None
        t = (
            tidy(downhill * first.tangent[0], light=False),
            tidy(downhill * first.tangent[1], light=False),
        )
        side = downhill * side
        beta_value = _incline_angle(t, side)
        cos_b, sin_b = sympy.cos(beta_value), sympy.sin(beta_value)
        if tidy(cos_b - side * t[0]) != 0 or tidy(sin_b + t[1]) != 0:
            return None  # β could not be written exactly: x–y rather than a guess
        name = "beta"
        taken = self.derived.get(sympy.Symbol(name, positive=True))
        if name in self.symbols or (taken is not None and tidy(taken[0] - beta_value) != 0):
            name = f"beta_{first.name}"
        meaning = f"incline angle at {first.point_name}, from its normal"
        if curved:
            meaning = f"slope of the path {first.name} at {body.name}, from its normal"
        beta = self.name_quantity(name, beta_value, Dim(), meaning)
        t_beta = (side * sympy.cos(beta), -sympy.sin(beta))
        perp = _perp(t)  # n is t turned ±90°: the sense that points out of the surface
        turn = 1 if tidy(dot(first.normal, perp) - 1) == 0 else -1
        n_beta = (-turn * t_beta[1], turn * t_beta[0])
        exact = {beta: beta_value} if beta != beta_value else {}
        for written, vector in ((t_beta, t), (n_beta, first.normal)):
            if any(tidy(w.xreplace(exact) - v) != 0 for w, v in zip(written, vector, strict=True)):
                return None  # the β form is not the same vector: x–y rather than a guess
        if curved:
            return self._path_axes(first, t, t_beta, n_beta, beta)
        at_rim = all(s.kind == "rolls" or touches_at_rim(body, s) for s in mine)
        normal_fixed = motion in ("translation", "particle") or at_rim
        rolling = (
            motion == "general"
            and len(mine) == 1
            and at_rim
            and not first.smooth
            and self._rolls_without_slip(body, first, omega)
        )
        return InclineAxes(first.name, t, first.normal, t_beta, n_beta, beta, normal_fixed, rolling)

    def _path_axes(
        self, path: Support, t: Vec, t_beta: Vec, n_beta: Vec, beta: sympy.Expr
    ) -> InclineAxes | None:
        """t along a particle's curved path (downhill) and n toward its centre of curvature,
        with a_n = v²/ρ named as a given quantity; None (x–y kept) where the centre's side
        is not known."""
        toward = _sign(path.normal_acceleration, self.scene.values)
        if toward == 0:
            return None
        n = (tidy(toward * path.normal[0]), tidy(toward * path.normal[1]))
        n_beta = (tidy(toward * n_beta[0]), tidy(toward * n_beta[1]))
        a_n_value = tidy(toward * path.normal_acceleration)
        if path.rho is not None and path.speed is not None:  # ρ first, as the textbook
            rho = self.name_quantity(
                self.suffix("rho", path.body),
                path.rho,
                LENGTH,
                f"radius of curvature of the path {path.name} at {path.body}: "
                "ρ = [1 + (dy/dx)²]^(3/2) / |d²y/dx²|",
            )
            if _is_zero(path.speed**2 / path.rho - a_n_value):  # a_n = v²/ρ, as it must
                a_n_value = path.speed**2 / rho
        a_n = self.name_quantity(
            self.suffix("a_n", path.body),
            a_n_value,
            ACCELERATION,
            f"a_n = v²/ρ on the path {path.name}, toward its centre of curvature",
        )
        return InclineAxes(path.name, t, n, t_beta, n_beta, beta, False, False, a_n)

    def _rolls_without_slip(self, body: Body, support: Support, omega: sympy.Expr) -> bool:
        """True when the contact's friction is static (no slip assumed): not declared or
        found slipping, and its point not already sliding at the instant."""
        if support.name in self.slipping:
            return not self.slipping[support.name]
        if support.friction_sense is not None:
            return False
        v_G = self.scene.velocities.get(body.name, (sympy.Integer(0), sympy.Integer(0)))
        r = _minus(support.point, body.G)
        v_P = (v_G[0] + omega * _perp(r)[0], v_G[1] + omega * _perp(r)[1])
        return _is_zero(dot(v_P, support.tangent))

    def _incline_kinematics(
        self, body: Body, motion: str, omega: sympy.Expr, axes: InclineAxes
    ) -> Kinematics:
        """a_G along and normal to the incline: (a_G)_t = α r where the body rolls without
        slip, else an unknown (a_G)_t; (a_G)_n = 0 where the contact is kept by the axes'
        choice, else an unknown."""
        self.inclines[body.name] = axes
        support = next(s for s in self.scene.supports if s.body == body.name)
        where = support.point_name
        alpha: sympy.Expr = sympy.Integer(0)
        if motion not in ("translation", "particle"):
            alpha = self.unknown(self.suffix("alpha", body.name), ANGULAR_ACCELERATION)
        if axes.rolling:  # a_C·t = 0: (a_G)_t = −α (k × r_C/G)·t
            along = tidy(-alpha * dot(_perp(_minus(support.point, body.G)), axes.t))
        elif axes.a_n is not None and support.constant_speed:
            along = sympy.Integer(0)  # driven at constant speed along the path: a_t = 0
        else:
            along = self.unknown(self.suffix("a_Gt", body.name), ACCELERATION)
        normal: sympy.Expr = sympy.Integer(0)
        if axes.a_n is not None:
            normal = axes.a_n
        elif not axes.normal_fixed:
            normal = self.unknown(self.suffix("a_Gn", body.name), ACCELERATION)
        a_G = (
            tidy(along * axes.t[0] + normal * axes.n[0]),
            tidy(along * axes.t[1] + normal * axes.n[1]),
        )
        why = (
            f"axes t down the incline and n normal to it, as the contact normal at {where} "
            "gives them"
        )
        if axes.a_n is not None:
            why = (
                f"axes t along the path {support.name} (downhill) and n toward its centre of "
                "curvature: (a_G)_n = v²/ρ"
            )
        if axes.normal_fixed:
            why += f" (contact at {where} kept: (a_G)_n = 0)"
        if axes.rolling:
            why += f"; rolling without slip at {where}: (a_G)_t = α r"
        self.axes[body.name] = why
        tangent, component = (axes.t, along) if axes.normal_fixed else (None, None)
        return Kinematics(motion, alpha, a_G, omega, None, tangent, component)

    def omega_from_velocity(self, body: Body) -> sympy.Expr:
        """ω implied by a given v_G: rolling without slip (v_C = 0) or rotation about a pin."""
        v = self.scene.velocities.get(body.name)
        if v is None or body.particle:  # a particle does not turn: its contact slides
            return sympy.Integer(0)
        for support in self.scene.supports:
            if support.body != body.name:
                continue
            if support.kind == "rolls" or (
                support.kind == "contact" and not support.smooth and support.slides is None
            ):
                r = _minus(support.point, body.G)  # v_C = v_G + ω k × r_C/G = 0 along t
                return tidy(-dot(v, support.tangent) / dot(_perp(r), support.tangent))
            if support.kind == "pin":
                r = _minus(body.G, support.point)  # v_G = ω k × r_G/O
                return tidy(dot(v, _perp(r)) / dot(r, r))
        return sympy.Integer(0)

    def point_acceleration(self, body: str, point: Vec) -> Vec:
        return point_acceleration(self.kinematics[body], self.scene.bodies[body].G, point)

    def point_velocity(self, body: str, point: Vec) -> Vec:
        """v_P = v_G + ω k × r_P/G at the instant (v_G = ω k × r_G/O about a pin when no
        velocity is given; zero for a body at rest)."""
        kin, G = self.kinematics[body], self.scene.bodies[body].G
        v_G = self.scene.velocities.get(body)
        if v_G is None:
            r = _minus(G, kin.pin.point) if kin.pin is not None else (0, 0)
            v_G = (kin.omega * _perp(r)[0], kin.omega * _perp(r)[1])
        r = _minus(point, G)
        return (tidy(v_G[0] + kin.omega * _perp(r)[0]), tidy(v_G[1] + kin.omega * _perp(r)[1]))

    # ---- loads and reactions
    def add_force(self, term: ForceTerm) -> None:
        self.forces[term.body].append(term)

    def loads(self) -> None:
        scene = self.scene
        if scene.gravity is not None:
            g = self.symbols["g"]
            for body in scene.bodies.values():
                weight = body.mass * g
                self.add_force(
                    ForceTerm(
                        f"W_{body.name}" if self.several else "W",
                        "weight",
                        body.name,
                        body.G,
                        "G",
                        scene.gravity,
                        weight,
                        True,
                    )
                )
        for load in scene.loads:
            if load.kind == "couple":
                moment, known = self.magnitude(load.name, MOMENT)
                self.couples[load.body].append(
                    CoupleTerm(load.name, load.body, load.sense * moment, known)
                )
                continue
            magnitude, known = self.magnitude(load.name, FORCE)
            self.add_force(
                ForceTerm(
                    load.name,
                    "applied",
                    load.body,
                    load.point,
                    load.point_name or self._name_of(load.point, load.body),
                    load.direction,
                    magnitude,
                    known,
                )
            )

    def supports(self) -> None:
        for support in self.scene.supports:
            getattr(self, f"_{support.kind}")(support)
        for spring in self.scene.springs:
            self._spring(spring)
        for link in self.scene.links:
            self._link(link)
        for cord in self.scene.cords:
            tension = self.unknown(cord.name, FORCE)
            self.reactions[cord.name] = (tension, cord.direction)
            self.add_force(
                ForceTerm(
                    cord.name,
                    "tension",
                    cord.body,
                    cord.point,
                    self._name_of(cord.point, cord.body),
                    cord.direction,
                    tension,
                    False,
                )
            )
            a_1 = self.point_acceleration(cord.body, cord.point)
            if cord.other:
                assert cord.other_point is not None
                back = (-cord.direction[0], -cord.direction[1])
                self.add_force(
                    ForceTerm(
                        cord.name,
                        "tension",
                        cord.other,
                        cord.other_point,
                        self._name_of(cord.other_point, cord.other),
                        back,
                        tension,
                        False,
                    )
                )
                a_2 = self.point_acceleration(cord.other, cord.other_point)
                self._cord_velocity(cord)
                self.constraint(
                    dot(a_1, cord.direction),
                    dot(a_2, cord.direction),
                    f"cord {cord.name} inextensible: equal accelerations along it",
                )
            else:
                across = cross(cord.direction, self.point_velocity(cord.body, cord.point))
                value = real_value(across, self.scene.values)
                if (value is not None and value != 0) or (value is None and tidy(across) != 0):
                    raise ValueError(
                        f"{cord.body} moves across the cord {cord.name}, which then swings "
                        "about its fixed end: its length sets the acceleration along it "
                        f"(v²/ℓ); write it as a link to that point ('link {cord.name}: "
                        f"{cord.body} at … to O')"
                    )
                self.constraint(
                    dot(a_1, cord.direction),
                    sympy.Integer(0),
                    f"cord {cord.name} fixed: its end on {cord.body} does not move along it",
                )

    def _given_motion(self, body: str) -> bool:
        """Whether the velocity of every point of ``body`` is stated by the spec: a particle's
        ``velocity`` line, or an ``omega`` line of a body pinned at a fixed point."""
        if self.scene.bodies[body].particle:
            return body in self.scene.velocities
        pinned = any(s.body == body and s.kind == "pin" for s in self.scene.supports)
        return body in self.scene.omegas and pinned and body not in self.scene.velocities

    def _cord_velocity(self, cord: Cord) -> None:
        """A cord's two ends, where the spec states both motions, move equally along it:
        refuse velocities that stretch or slacken it (B said to move down while the cord
        over a turning pulley lifts it), which the answers would otherwise ignore."""
        assert cord.other_point is not None
        if not (self._given_motion(cord.body) and self._given_motion(cord.other)):
            return
        v_1 = self.point_velocity(cord.body, cord.point)
        v_2 = self.point_velocity(cord.other, cord.other_point)
        gap = tidy(dot(v_1, cord.direction) - dot(v_2, cord.direction))
        value = real_value(gap, self.scene.values)
        ends = [real_value(dot(v, cord.direction), self.scene.values) for v in (v_1, v_2)]
        scale = max((abs(e) for e in ends if e is not None), default=0.0)
        if (value is not None and abs(value) > 1e-9 * scale) or (value is None and gap != 0):
            shown = ", ".join(
                f"{name} {e:.4g}"
                for name, e in zip((cord.body, cord.other), ends, strict=True)
                if e is not None
            )
            raise VelocityConflict(
                f"the velocities given stretch or slacken the cord {cord.name}: its ends move "
                f"along it at different speeds ({shown} m/s); an inextensible cord's ends move "
                "equally along it, so check the directions of the velocity and omega lines"
            )

    def _ends(self, body: str, point: Vec, other: str, other_point: Vec) -> tuple[Vec, sympy.Expr]:
        """The unit vector from ``point`` toward the other end, and the length between them."""
        d = _minus(other_point, point)
        # |d|² tidied first (sin² + cos² = 1 on a short form), then its root and d/|d|
        length = tidy(sympy.sqrt(tidy(d[0] ** 2 + d[1] ** 2, light=False)), light=False)
        return (tidy(d[0] / length, light=False), tidy(d[1] / length, light=False)), length

    def _spring(self, spring: object) -> None:
        from dynsolve.model.scene import Spring

        assert isinstance(spring, Spring)
        u, length = self._ends(spring.body, spring.point, spring.other, spring.other_point)
        stretch = spring.stretch(length - spring.unstretched, self.scene.values)
        if not spring.tension_only and real_value(length, self.scene.values) == 0:
            # both ends at one point: the force k|L0| has no direction the scene fixes; an
            # unknown angle leaves whatever depends on it undetermined rather than guessed
            theta = self.unknown(f"theta_{spring.name}", Dim())
            u = (sympy.cos(theta), sympy.sin(theta))
            self.notes.append(
                (
                    f"spring {spring.name}",
                    "both ends at one point: its force has no direction here, so nothing "
                    "at this instant that depends on it can be found (an elastic cord, slack "
                    "there? write ', tension only')",
                )
            )
        if spring.tension_only and stretch == 0:
            self.notes.append(
                (
                    f"elastic cord {spring.name}",
                    f"slack: its length {sympy.sstr(length)} is not more than its unstretched "
                    f"length {sympy.sstr(spring.unstretched)}, so it pulls nothing",
                )
            )
            return  # no force (its direction may not even exist: ends together)
        if spring.compression_only and stretch == 0:
            self.notes.append(
                (
                    f"spring {spring.name}",
                    f"clear: its length {sympy.sstr(length)} is not less than its unstretched "
                    f"length {sympy.sstr(spring.unstretched)}, so it pushes nothing",
                )
            )
            return
        force = spring.k * stretch  # tension positive: pulls the ends together
        self.add_force(
            ForceTerm(
                spring.name,
                "spring",
                spring.body,
                spring.point,
                self._name_of(spring.point, spring.body),
                u,
                force,
                True,
            )
        )
        if spring.other:
            back = (-u[0], -u[1])
            self.add_force(
                ForceTerm(
                    spring.name,
                    "spring",
                    spring.other,
                    spring.other_point,
                    self._name_of(spring.other_point, spring.other),
                    back,
                    force,
                    True,
                )
            )

    def _link(self, link: object) -> None:
        from dynsolve.model.scene import Link

        assert isinstance(link, Link)
        u, length = self._ends(link.body, link.point, link.other, link.other_point)
        force = self.unknown(link.name, FORCE)
        self.reactions[link.name] = (force, u)
        self.add_force(
            ForceTerm(
                link.name,
                "link",
                link.body,
                link.point,
                self._name_of(link.point, link.body),
                u,
                force,
                False,
            )
        )
        a_1 = self.point_acceleration(link.body, link.point)
        if link.other:
            self.add_force(
                ForceTerm(
                    link.name,
                    "link",
                    link.other,
                    link.other_point,
                    self._name_of(link.other_point, link.other),
                    (-u[0], -u[1]),
                    force,
                    False,
                )
            )
            a_2 = self.point_acceleration(link.other, link.other_point)
            v_2 = self.point_velocity(link.other, link.other_point)
        else:
            a_2 = v_2 = (sympy.Integer(0), sympy.Integer(0))
        # |r| fixed: r·v = 0 and r·a + v·v = 0 (relative, r = ℓ u from P₁ toward P₂):
        # (a₂ − a₁)·u = −|v₂ − v₁|²/ℓ, the centripetal part of the relative acceleration
        v = _minus(v_2, self.point_velocity(link.body, link.point))
        self._link_velocity(link.name, dot(v, u))
        speed2 = tidy(dot(v, v))
        self.constraint(
            dot(a_2, u) - dot(a_1, u),
            tidy(-speed2 / length),
            f"link {link.name} rigid: along it, the relative acceleration of its ends is "
            + ("zero (at relative rest)" if speed2 == 0 else "−v²/ℓ (toward each other)")
            if link.other
            else f"link {link.name} to a fixed point: its end's acceleration along it is "
            + ("zero (at rest)" if speed2 == 0 else "v²/ℓ toward the fixed point"),
        )

    def _link_velocity(self, name: str, along: sympy.Expr) -> None:
        """A rigid link's ends have no relative velocity along it: refuse one that has."""
        value = real_value(along, self.scene.values)
        if (value is not None and value != 0) or (value is None and tidy(along) != 0):
            raise ValueError(
                f"the velocities given stretch the link {name} (the relative velocity of "
                "its ends has a part along it): a rigid link's ends move across it"
            )

    def _name_of(self, point: Vec, body: str) -> str:
        G = self.scene.bodies[body].G
        if point == G:
            return "G"
        return self.scene.point_names.get(point) or point_text(point, G)

    def _pin(self, support: Support) -> None:
        body = self.scene.bodies[support.body]
        r = _minus(body.G, support.point)
        if _is_zero(r[0]) and _is_zero(r[1]):
            axes = {
                "x": (sympy.Integer(1), sympy.Integer(0)),
                "y": (sympy.Integer(0), sympy.Integer(1)),
            }
        else:
            # e_r tidied once here (|r|² first), not in every projection of every force on it
            length = sympy.sqrt(tidy(r[0] ** 2 + r[1] ** 2, light=False))
            e_r = (tidy(r[0] / length, light=False), tidy(r[1] / length, light=False))
            axes = {"n": (-e_r[0], -e_r[1]), "t": _perp(e_r)}
        for axis, direction in axes.items():
            name = f"{support.name}_{axis}"
            symbol = self.unknown(name, FORCE)
            self.reactions[name] = (symbol, direction)
            self.add_force(
                ForceTerm(
                    name,
                    "reaction",
                    body.name,
                    support.point,
                    support.point_name,
                    direction,
                    symbol,
                    False,
                )
            )

    def _contact(self, support: Support) -> None:
        self._normal_and_friction(support)
        axes = self.inclines.get(support.body)
        if support.constant_speed:
            self._drive_along_path(support, axes)
        if axes is not None and axes.a_n is not None:
            return  # (a_G)_n = v²/ρ is built into the path's n–t axes
        a_P = self.point_acceleration(support.body, support.point)
        note = (
            f"on the curved path {support.name}: a_n = v²/ρ toward the centre of curvature"
            if support.normal_acceleration != 0
            else f"contact at {support.name} kept: no acceleration into the surface"
        )
        a_n = dot(a_P, support.normal)
        if support.normal_acceleration == 0 and touches_at_rim(
            self.scene.bodies[support.body], support
        ):  # the contact point changes as it turns: the centre keeps its height
            a_n = dot(self.kinematics[support.body].a_G, support.normal)
            note = f"contact at {support.name} kept: {support.body}'s centre keeps its height"
        self.constraint(a_n, sympy.Integer(0) + support.normal_acceleration, note)
        if self._static(support):
            self.constraint(
                dot(a_P, support.tangent),
                sympy.Integer(0),
                f"no slip at {support.name} (assumed; checked after solving)",
            )

    def _rolls(self, support: Support) -> None:
        self._normal_and_friction(support)
        kin = self.kinematics[support.body]
        self.constraint(
            dot(kin.a_G, support.normal),
            sympy.Integer(0),
            f"{support.body} rolls: its centre keeps its distance from the surface",
        )
        if self._static(support):
            a_P = self.point_acceleration(support.body, support.point)
            self.constraint(
                dot(a_P, support.tangent),
                sympy.Integer(0),
                f"rolling without slip at {support.name}: a_G = α r",
            )

    def _base(self, support: Support) -> None:
        body = self.scene.bodies[support.body]
        assert support.end is not None
        along = support.tangent
        foot_distance = dot(_minus(body.G, support.point), along)
        foot = (
            support.point[0] + foot_distance * along[0],
            support.point[1] + foot_distance * along[1],
        )
        x = self.unknown(f"x_{support.name}", LENGTH)
        point = (foot[0] + x * along[0], foot[1] + x * along[1])
        self._normal_and_friction(support, point)
        kin = self.kinematics[support.body]
        self.constraint(
            dot(kin.a_G, support.normal),
            sympy.Integer(0),
            f"{support.body} stays on the surface at base {support.name}",
        )
        if self._static(support):
            self.constraint(
                dot(kin.a_G, support.tangent),
                sympy.Integer(0),
                f"no slip on base {support.name} (assumed; checked after solving)",
            )

    def _static(self, support: Support) -> bool:
        """True when friction here is an unknown with a no-slip assumption."""
        return not support.smooth and self._sliding_sense(support) is None

    def _drive_along_path(self, support: Support, axes: InclineAxes | None) -> None:
        """A particle driven along its path at constant speed (a car's traction or brakes):
        an unknown force F_PATH along the path, and a_t = 0 (on the path's n–t axes, built
        in; in x–y, a constraint)."""
        direction = axes.t if axes is not None else support.tangent
        name = f"F_{support.name}"
        force = self.unknown(name, FORCE)
        self.reactions[name] = (force, direction)
        self.add_force(
            ForceTerm(
                name, "traction", support.body, support.point, support.point_name, direction,
                force, False,
            )
        )  # fmt: skip
        if axes is None:
            a_P = self.point_acceleration(support.body, support.point)
            note = f"constant speed along the path {support.name}: a_t = 0"
            self.constraint(dot(a_P, support.tangent), sympy.Integer(0), note)

    def _normal_and_friction(self, support: Support, point: Vec | None = None) -> None:
        where = point if point is not None else support.point
        normal = self.unknown(f"N_{support.name}", FORCE)
        self.reactions[f"N_{support.name}"] = (normal, support.normal)
        self.add_force(
            ForceTerm(
                f"N_{support.name}",
                "reaction",
                support.body,
                where,
                support.point_name,
                support.normal,
                normal,
                False,
            )
        )
        if support.smooth:
            return
        name = f"F_{support.name}"
        sense = self._sliding_sense(support)
        if sense is None:
            friction: sympy.Expr = self.unknown(name, FORCE)
            self.reactions[name] = (friction, support.tangent)
        else:
            if support.mu_k is None:
                raise ValueError(f"{support.name} slides but has no mu_k")
            friction = sense * support.mu_k * normal
            self.reactions[name] = (friction, support.tangent)
        self.add_force(
            ForceTerm(
                name,
                "friction",
                support.body,
                where,
                support.point_name,
                support.tangent,
                friction,
                sense is not None,
            )
        )

    def _sliding_sense(self, support: Support) -> int | None:
        """+1/−1 along the tangent for kinetic friction, None for unknown static friction
        (also where ``slipping`` holds 0: a declared slide that the answer contradicted)."""
        if support.name in self.slipping:
            return self.slipping[support.name] or None
        if support.friction_sense is not None:
            return support.friction_sense
        return self._slip_at(support)

    def _slip_at(self, support: Support) -> int | None:
        """Kinetic friction's sense where the contact point already slips at the instant
        (its velocity along the surface, v_P·t ≠ 0: a block sliding at a given speed), or
        None where it does not (static friction, checked against μs N)."""
        slip = tidy(dot(self.point_velocity(support.body, support.point), support.tangent))
        if slip == 0:
            return None
        value = real_value(slip, self.scene.values)
        if value is None:
            raise ValueError(
                f"whether {support.body} slides at {support.name} depends on symbolic givens "
                f"(its contact point moves at {sympy.sstr(slip)} along the surface); state it "
                f"on the contact ('slides right'), or give the givens values"
            )
        if value == 0:
            return None
        self.sliding[support.name] = slip
        return -1 if value > 0 else 1  # against the slip

    # ---- equations of motion
    def newton_euler(self, body: Body) -> None:
        kin = self.kinematics[body.name]
        forces, couples = self.forces[body.name], self.couples[body.name]
        m, tag = body.mass, f"({body.name})"
        if kin.motion == "rotation" and kin.pin is not None:
            self._rotation(body, kin, forces, couples)
            return
        axes = self.inclines.get(body.name)
        if axes is not None:
            self._along_and_normal(body, kin, forces, axes)
        else:
            sum_x = sympy.Add(*(f.vector[0] for f in forces))
            sum_y = sympy.Add(*(f.vector[1] for f in forces))
            self.equation(sum_x, m * kin.a_G[0], f"ΣF_x = m (a_G)_x {tag}")
            self.equation(sum_y, m * kin.a_G[1], f"ΣF_y = m (a_G)_y {tag}")
            self.kinetic[body.name] = ("m (a_G)_x", "m (a_G)_y")
        if kin.motion == "particle":
            self.moment_points[body.name] = ""
            return
        P, why = self._moment_point(body, forces)
        if axes is not None and axes.normal_fixed and kin.motion == "general":
            P, why = body.G, "G (ΣM_G = I_G α, as the textbook writes a wheel on an incline)"
        if kin.motion == "translation" and P == body.G:
            why = "G (translation: ΣM_G = 0)"
        moment = _moment(forces, couples, P)
        r_GP = _minus(body.G, P)
        kinetic = body.I_G * kin.alpha + cross(r_GP, (m * kin.a_G[0], m * kin.a_G[1]))
        name = self._point_label(P, body)
        principle = f"ΣM_{name} = I_G α + (r_G/{name} × m a_G)" if name != "G" else "ΣM_G = I_G α"
        if kin.motion == "translation":
            principle = (
                f"ΣM_{name} = (r_G/{name} × m a_G) (translation: α = 0)"
                if name != "G"
                else "ΣM_G = 0 (translation)"
            )
        self.equation(moment, kinetic, f"{principle} {tag}")
        self.moment_points[body.name] = why
        if kin.motion != "translation":
            self.kinetic[body.name] = (*self.kinetic[body.name], "I_G α")

    def _along_and_normal(
        self, body: Body, kin: Kinematics, forces: list[ForceTerm], axes: InclineAxes
    ) -> None:
        """ΣF_t = m (a_G)_t and ΣF_n = m (a_G)_n, t down the incline and n out of it."""
        m, tag = body.mass, f"({body.name})"
        along = tidy(dot(kin.a_G, axes.t), light=False)
        normal = tidy(dot(kin.a_G, axes.n), light=False)
        sum_t = sympy.Add(*(f.magnitude * axes.component(f.direction, "t") for f in forces))
        sum_n = sympy.Add(*(f.magnitude * axes.component(f.direction, "n") for f in forces))
        where = next(s.point_name for s in self.scene.supports if s.name == axes.support)
        t_label = f"ΣF_t = m (a_G)_t {tag}"
        if axes.rolling:
            t_label = f"ΣF_t = m (a_G)_t, (a_G)_t = α r (rolls without slip at {where}) {tag}"
        n_label = f"ΣF_n = m (a_G)_n {tag}"
        if axes.a_n is not None:
            t_label = f"ΣF_t = m a_t {tag}"
            if _is_zero(along):
                t_label = f"ΣF_t = m a_t = 0 (constant speed) {tag}"
            n_label = f"ΣF_n = m a_n, a_n = v²/ρ toward the centre of curvature {tag}"
        elif axes.normal_fixed:
            n_label = f"ΣF_n = m (a_G)_n = 0 (contact at {where} kept) {tag}"
        self.equation(sum_t, m * along, t_label)
        self.equation(sum_n, m * normal, n_label)
        along_term = ("m α r",) if axes.rolling else ("m (a_G)_t",) * (not _is_zero(along))
        self.kinetic[body.name] = along_term + (() if axes.normal_fixed else ("m (a_G)_n",))

    def _rotation(
        self, body: Body, kin: Kinematics, forces: list[ForceTerm], couples: list[CoupleTerm]
    ) -> None:
        pin = kin.pin
        assert pin is not None
        m, tag = body.mass, f"({body.name})"
        r = (
            tidy(body.G[0] - pin.point[0], light=False),
            tidy(body.G[1] - pin.point[1], light=False),
        )
        r_G_value = tidy(sympy.sqrt(tidy(r[0] ** 2 + r[1] ** 2, light=False)), light=False)
        pin_name = pin.name
        on_axis = _is_zero(r_G_value)
        r_G = self.name_quantity(
            self.suffix("r_G", body.name), r_G_value, LENGTH, f"distance {pin_name}–G"
        )
        I_O = body.I_G
        if not on_axis and not PARALLEL_AXIS_FORGOTTEN.get():
            I_O = self.name_quantity(
                self.suffix(f"I_{pin_name}", body.name),
                tidy(body.I_G + m * r_G_value**2, light=False),
                Dim(2, 1, 0),
                f"I about {pin_name}: I_G + m r_G² (parallel-axis theorem)",
            )
        if on_axis:
            self.equation(
                sympy.Add(*(f.vector[0] for f in forces)),
                sympy.Integer(0),
                f"ΣF_x = m (a_G)_x = 0 (G on the axis) {tag}",
            )
            self.equation(
                sympy.Add(*(f.vector[1] for f in forces)),
                sympy.Integer(0),
                f"ΣF_y = m (a_G)_y = 0 (G on the axis) {tag}",
            )
            self.kinetic[body.name] = ("I_G α",)
        else:
            e_r = (tidy(r[0] / r_G_value), tidy(r[1] / r_G_value))
            e_n, e_t = (-e_r[0], -e_r[1]), _perp(e_r)
            n_label = f"ΣF_n = m ω² r_G {tag}"
            at_rest = _is_zero(kin.omega)  # released from rest: no centripetal term to draw
            if at_rest:
                n_label = f"ΣF_n = m ω² r_G = 0 (ω = 0 at the instant) {tag}"
            self.equation(_projected(forces, e_n), m * kin.omega**2 * r_G, n_label)
            self.equation(_projected(forces, e_t), m * kin.alpha * r_G, f"ΣF_t = m α r_G {tag}")
            spin = () if at_rest else ("m ω² r_G",)
            self.kinetic[body.name] = (*spin, "m α r_G", "I_G α")
        moment = _moment(forces, couples, pin.point)
        note = (
            f"ΣM_{pin_name} = I_{pin_name} α, I_{pin_name} = I_G + m r_G² {tag}"
            if not on_axis
            else f"ΣM_{pin_name} = I_G α {tag}"
        )
        self.equation(moment, I_O * kin.alpha, note)
        self.moment_points[body.name] = (
            f"the pin {pin_name}, which eliminates its reaction components"
        )

    def name_quantity(self, name: str, value: sympy.Expr, dim: Dim, meaning: str) -> sympy.Expr:
        """A geometric or inertial quantity shown by name in the equations (r_G, I_O),
        with its value listed beside the givens; a plain symbol or number is kept as is."""
        if value.is_Symbol or value.is_Number or name in self.symbols:
            return value
        symbol = sympy.Symbol(name, positive=True)
        self.derived[symbol] = (value, dim, meaning)
        return symbol

    def _moment_point(self, body: Body, forces: list[ForceTerm]) -> tuple[Vec, str]:
        unknown = [f for f in forces if not f.known]
        candidates: list[Vec] = [body.G]
        candidates += [
            f.point
            for f in unknown
            if f.point not in candidates  # a point at an unknown place (a base's N) is no help
            and not any(s in self.unknowns for s in sympy.Add(*f.point).free_symbols)
        ]
        best, best_names = body.G, []
        for P in candidates:
            names = [f.name for f in unknown if _is_zero(cross(_minus(f.point, P), f.direction))]
            if len(names) > len(best_names):
                best, best_names = P, names
        if best == body.G:
            return body.G, "G (ΣM_G = I_G α)"
        label = self._point_label(best, body)
        listed = " and ".join(pretty(n) for n in best_names)
        return best, f"{label}, which eliminates {listed}, the unknowns acting there"

    def _point_label(self, P: Vec, body: Body) -> str:
        if P == body.G:
            return "G"
        named = self.scene.point_names.get(P) or next(
            (f.point_name for f in self.forces[body.name] if f.point == P and f.point_name), ""
        )
        return named or point_text(P, body.G)


def formulate(
    scene: Scene,
    symbols: Mapping[str, sympy.Expr],
    slipping: Mapping[str, int] | None = None,
    inclines: bool = True,
) -> Formulation:
    """The Newton–Euler equations and constraints of ``scene``.

    ``slipping`` maps contacts whose no-slip assumption failed to the sense (±1 along
    the contact tangent) of their kinetic friction, and declared slides that the answer
    contradicted to 0 (no slip assumed instead). ``inclines=False`` keeps x–y for every
    body (impulse and momentum over an interval reads each a_G component as a symbol).
    """
    writer = _Writer(scene, symbols, slipping or {})
    writer.incline_allowed = inclines
    for body in scene.bodies.values():
        writer.kinematics[body.name] = writer.body_kinematics(body)
    writer.loads()
    writer.supports()
    for body in scene.bodies.values():
        writer.newton_euler(body)
    return Formulation(
        equations=writer.numbered(),
        unknowns=writer.unknowns,
        forces={k: tuple(v) for k, v in writer.forces.items()},
        couples={k: tuple(v) for k, v in writer.couples.items()},
        kinematics=writer.kinematics,
        moment_points=writer.moment_points,
        reactions=writer.reactions,
        kinetic=writer.kinetic,
        derived=writer.derived,
        notes=tuple(writer.notes),
        sliding=dict(writer.sliding),
        axes=dict(writer.axes),
        inclines=dict(writer.inclines),
    )
