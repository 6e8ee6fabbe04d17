"""The equation of motion of a one-degree-of-freedom scene in one coordinate q (Lagrange).

Every body's placement is a function of q (:func:`dynsolve.model.states.placements_of`
with the travel left as the parameter, or a particle's straight line), so
T = ½ M(q) q'² with M = Σ m |dr_G/dq|² + I_G (dθ/dq)², and Lagrange's equation reads
M q'' + ½ M' q'² = Q(q, q'). Q is the derivative of the work of the scene's loads,
written as a potential V(q) (weights −m g·r_G, springs ½ k (L − L₀)², constant forces
−F·r_P, couples −M θ) plus kinetic friction −μk N |dr_C/dq| sign q', with N from the
balance across a straight surface of a translating body. The functions are built with
sympy once and written as plain float functions (:mod:`dynsolve.simulate.compiled`).

>>> import sympy
>>> from dynsolve.model.scene import Body, Scene
>>> ball = Body("ball", 2, 0, (0, 5), (0, 5), "particle", (), {}, True, "", 0, 0)
>>> scene = Scene({"ball": ball}, {}, (), (), (), (0, -1), {})
>>> motion = straight_line(scene, "ball", (0, -1), {"g": sympy.Float(9.81)}, {})
>>> motion.acceleration(0.0, 0.0)  # q is the drop: q'' = g
9.81
"""

from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np
import sympy

from dynsolve.model.scene import Scene, Support, Travel, Vec
from dynsolve.model.states import Placement, placements_of
from dynsolve.simulate.compiled import float_function, float_scalar

Q = sympy.Symbol("q")  # no assumptions: a length sqrt(u²) stays smooth, not |u|
QD = sympy.Symbol("qd", real=True)


class _Root(sympy.Function):
    """√x of a squared length x ≥ 0, left as written: sympy's own ``sqrt((a·q + b)²)``
    asks the argument of a + b q (arg, floor, exp) at each power it forms, 10 ms a time,
    and a spring's force and its derivative form dozens. Evaluated for a number; its
    derivative is 1/(2√x); printed ``sqrt`` (lambdify: math.sqrt, numpy.sqrt, mpmath.sqrt).

    >>> x = sympy.Symbol("x")
    >>> root((x - 1) ** 2).diff(x), root(sympy.Integer(9))
    ((2*x - 2)/(2*sqrt((x - 1)**2)), 3)
    """

    nargs = 1

    @classmethod
    def eval(cls, x: sympy.Expr) -> sympy.Expr | None:
        """√x of a number, at once."""
        return sympy.sqrt(x) if x.is_Number else None

    def fdiff(self, argindex: int = 1) -> sympy.Expr:
        """d√x/dx = 1/(2√x)."""
        return 1 / (2 * self)


_Root.__name__ = "sqrt"  # the name the code printers know, in every lambdify module


def root(x: sympy.Expr) -> sympy.Expr:
    """√x of a squared length, as :class:`_Root` writes it (no evaluation of its powers)."""
    return _Root(sympy.Integer(0) + x)


class NotSimulable(ValueError):
    """The scene's motion cannot be written as one coordinate's equation here (the reason)."""


@dataclass(frozen=True)
class OneDof:
    """M(q) q'' + ½ M'(q) q'² = Q(q, q'), with the placements to report and check.

    ``terms`` are M, M', Q_c = −V', the size of the friction force (generalized) and V;
    ``place_terms`` each body's x_G, y_G, Δθ and their q-derivatives: all functions of
    :data:`Q` alone, numbers put in. Each float function is written when first used.
    """

    coordinate: str  # what q measures
    unit: str  # "rad" or "m"
    bodies: tuple[str, ...]
    terms: tuple[sympy.Expr, ...]
    place_terms: tuple[sympy.Expr, ...]
    hold: sympy.Expr | int = 0  # Σ μs N |dr_C/dq|: the most static friction can hold at rest

    @property
    def frictionless(self) -> bool:
        """No kinetic friction acts (T + V is conserved)."""
        return self.terms[3] == 0

    @functools.cached_property
    def _terms(self) -> Callable[[float], tuple[float, ...]]:
        return float_function([Q], self.terms)

    @functools.cached_property
    def _places(self) -> Callable[[float], tuple[float, ...]]:
        return float_function([Q], self.place_terms)

    @functools.cached_property
    def _accel_expr(self) -> sympy.Expr:
        M, dM, Qc = self.terms[:3]
        return (Qc - dM * QD**2 / 2) / M

    @functools.cached_property
    def _accel(self) -> Callable[[float, float], float] | None:
        if not self.frictionless:
            return None
        return float_scalar([Q, QD], self._accel_expr)

    @functools.cached_property
    def _jacobian(self) -> Callable[[float, float], tuple[float, float]] | None:
        if not self.frictionless:
            return None
        a = self._accel_expr
        return float_function([Q, QD], (sympy.diff(a, Q), sympy.diff(a, QD)))

    def energies(self, q: np.ndarray, qd: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """T and V at each sample (arrays)."""
        terms = np.array([self._terms(x) for x in np.asarray(q, dtype=float).ravel()])
        M = terms[:, 0].reshape(np.shape(q)) if terms.size else np.zeros(np.shape(q))
        V = terms[:, 4].reshape(np.shape(q)) if terms.size else np.zeros(np.shape(q))
        return 0.5 * M * np.asarray(qd, dtype=float) ** 2, V

    def acceleration(self, q: float, qd: float) -> float:
        """q'' from Lagrange's equation at (q, q')."""
        if self._accel is not None:
            return self._accel(q, qd)
        M, dM, Qc, friction, _ = self._terms(q)
        return (Qc - friction * _sign(qd) - 0.5 * dM * qd * qd) / M

    def accelerator(self) -> Callable[[float, float], float]:
        """q''(q, q') as one plain function (the fastest right-hand side)."""
        return self._accel or self.acceleration

    def right_hand_side(self) -> Callable[[float, object], list[float]] | None:
        """(q', q'') of the state (q, q') as one plain function, without friction."""
        if self._accel is not None:
            accel = self._accel
            return lambda _t, y: [y[1], accel(y[0], y[1])]
        return None

    def jacobian(self) -> Callable[[float, object], list[list[float]]] | None:
        """d(q', q'')/d(q, q') for the implicit methods (Radau, BDF, LSODA), without friction."""
        if self._jacobian is None:
            return None
        partials = self._jacobian

        def jac(_t: float, y: object) -> list[list[float]]:
            d_q, d_qd = partials(y[0], y[1])  # type: ignore[index]
            return [[0.0, 1.0], [d_q, d_qd]]

        return jac

    def rates(self, q: float, qd: float) -> tuple[float, float]:
        """q'' and the friction's power at (q, q'), from one evaluation."""
        M, dM, Qc, friction, _ = self._terms(q)
        return (Qc - friction * _sign(qd) - 0.5 * dM * qd * qd) / M, -friction * abs(qd)

    @functools.cached_property
    def _hold(self) -> Callable[[float], float]:
        return float_scalar([Q], sympy.Integer(0) + self.hold)

    def holds(self, q: float) -> bool:
        """At rest at q, static friction can hold the body there: |Q_c(q)| ≤ Σ μs N |dr_C/dq|
        (Coulomb; μs taken as μk where it is not given). Never without friction.

        >>> block = OneDof("x", "m", ("b",), (2, 0, -200 * Q, 1.962, 100 * Q**2), (), 1.962)
        >>> block.holds(0.0019), block.holds(0.0215)  # k |x| against μs m g = 1.962 N
        (True, False)
        """
        if self.frictionless:
            return False
        Qc = self._terms(q)[2]
        return abs(Qc) <= self._hold(q) * (1 + 1e-12)

    def friction_power(self, q: float, qd: float) -> float:
        """The (negative) power of kinetic friction at (q, q')."""
        return -self._terms(q)[3] * abs(qd)

    def energy(self, q: float, qd: float) -> float:
        """T + V (V of the weights, springs and constant loads; friction is not in it)."""
        M, _, _, _, V = self._terms(q)
        return 0.5 * M * qd * qd + V

    def kinetic(self, q: float, qd: float) -> float:
        """T = ½ M(q) q'²."""
        return 0.5 * self._terms(q)[0] * qd * qd

    def generalized_force(self, q: float, qd: float) -> float:
        """Q(q, q'): the loads' generalized force, friction included."""
        _, _, Qc, friction, _ = self._terms(q)
        return Qc - friction * _sign(qd)

    def places(self, q: float) -> dict[str, tuple[float, ...]]:
        """Per body: x_G, y_G, Δθ, and dx_G/dq, dy_G/dq, dθ/dq."""
        flat = self._places(q)
        return {name: tuple(flat[6 * i : 6 * i + 6]) for i, name in enumerate(self.bodies)}

    def velocities(self, q: float, qd: float) -> dict[str, tuple[float, float, float]]:
        """Per body: v_Gx, v_Gy, ω (ccw positive) at (q, q')."""
        return {n: (p[3] * qd, p[4] * qd, p[5] * qd) for n, p in self.places(q).items()}


def _sign(x: float) -> float:
    return 0.0 if x == 0 else math.copysign(1.0, x)


def _dot(a: Vec, b: Vec) -> sympy.Expr:
    return a[0] * b[0] + a[1] * b[1]


def _point(scene: Scene, placements: Mapping[str, Placement], body: str, P: Vec) -> Vec:
    """Where the material point of ``body`` at P in the scene is after the placement."""
    placement = placements.get(body)
    if placement is None:
        return P
    G = scene.bodies[body].G
    rho = (P[0] - G[0], P[1] - G[1])
    c, s = placement.cos, placement.sin
    return (
        G[0] + placement.shift[0] + c * rho[0] - s * rho[1],
        G[1] + placement.shift[1] + s * rho[0] + c * rho[1],
    )


def numeric_scene(scene: Scene, values: Mapping[sympy.Symbol, sympy.Expr]) -> Scene:
    """The scene with the givens' values put in every expression (its geometry, masses,
    loads, travels), so that placing it in terms of q needs no symbolic simplification.

    >>> from dynsolve.model.scene import Body
    >>> L = sympy.Symbol("L")
    >>> rod = Body("rod", 1, 1, (L / 2, 0), (0, 0), "rod", (L,), {}, False, "", 0, 0)
    >>> numeric_scene(Scene({"rod": rod}, {}, (), (), (), None, {}), {L: 2}).bodies["rod"].G
    (1, 0)
    """
    return _substituted(scene, dict(values))  # type: ignore[no-any-return]


def _substituted(item: object, values: dict[sympy.Symbol, sympy.Expr]) -> object:
    if isinstance(item, sympy.Basic):
        return item.xreplace(values)
    if dataclasses.is_dataclass(item) and not isinstance(item, type):
        changes = {
            f.name: _substituted(getattr(item, f.name), values)
            for f in dataclasses.fields(item)
            if f.init
        }
        return dataclasses.replace(item, **changes)  # type: ignore[type-var]
    if isinstance(item, tuple):
        return tuple(_substituted(part, values) for part in item)
    if isinstance(item, Mapping):
        return {key: _substituted(value, values) for key, value in item.items()}
    return item


def mechanism(
    scene: Scene,
    travel: Travel,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    coordinate: str,
    unit: str,
    simplify: bool = False,
) -> OneDof:
    """The equation of motion of a rigid body or linkage, q the parameter of ``travel``
    (``angle``/``distance`` written in terms of :data:`Q`)."""
    from dataclasses import replace

    try:
        placed = replace(scene, travels={travel.body: travel})
        placements, link_turns = placements_of(placed, simplify=False)
    except ValueError as exc:
        raise NotSimulable(str(exc)) from None
    return _build(scene, placements, link_turns, symbols, values, coordinate, unit, simplify)


def straight_line(
    scene: Scene,
    body: str,
    direction: Vec,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    what: str = "",
) -> OneDof:
    """A lone particle moving along the straight line ``direction`` (unit) from its place,
    q the distance along it; the line must be a guide's, or the forces must have no part
    across it (else its path is not straight)."""
    unit = (sympy.Integer(0) + direction[0], sympy.Integer(0) + direction[1])
    placements = {body: Placement((Q * unit[0], Q * unit[1]), sympy.Integer(0), 1, 0)}
    if not any(s.body == body for s in scene.supports):
        across = (-float(unit[1]), float(unit[0]))
        numbers = _numbers(symbols, values)
        for q in (0.0, 0.5, 1.0):  # the net force at three places, in numbers
            at = {body: Placement((q * unit[0], q * unit[1]), sympy.Integer(0), 1, 0)}
            net = [_float(f) for f in _applied(scene, at, body, numbers)]
            push = net[0] * across[0] + net[1] * across[1]
            if abs(push) > 1e-12 * max(math.hypot(*net), 1e-300):
                raise NotSimulable(
                    f"the forces on {body} have a part across its travel and nothing guides "
                    "it: its path is not straight"
                )
    numbers = _numbers(symbols, values)
    along = _dot(_applied(scene, placements, body, numbers), unit)  # Q_c = F·u = −dV/dq
    what = what or f"distance of {body} along its travel"
    return _build(scene, placements, {}, numbers, values, what, "m", force=along)


def _applied(
    scene: Scene, placements: Mapping[str, Placement], body: str, symbols: Mapping[str, sympy.Expr]
) -> Vec:
    """The sum of the weight, constant forces and springs on ``body`` (no supports)."""
    fx, fy = sympy.Integer(0), sympy.Integer(0)
    mass = scene.bodies[body].mass
    if scene.gravity is not None:
        fx += mass * symbols["g"] * scene.gravity[0]
        fy += mass * symbols["g"] * scene.gravity[1]
    for load in scene.loads:
        if load.body == body and load.kind == "force":
            fx += _size(load.name, symbols) * load.direction[0]
            fy += _size(load.name, symbols) * load.direction[1]
    for spring in scene.springs:
        if body not in (spring.body, spring.other):
            continue
        a = _point(scene, placements, spring.body, spring.point)
        b = _point(scene, placements, spring.other, spring.other_point) if spring.other else None
        b = b or spring.other_point
        d = (b[0] - a[0], b[1] - a[1])  # from the spring's start toward its other end
        length = root(_dot(d, d))
        pull = spring.k * (length - spring.unstretched) / length
        if spring.tension_only:  # no force (nor direction, at zero length) while slack
            pull = sympy.Piecewise((pull, length > spring.unstretched), (0, True))
        elif getattr(spring, "compression_only", False):  # none once the body leaves it
            pull = sympy.Piecewise((pull, length < spring.unstretched), (0, True))
        sense = 1 if spring.body == body else -1
        fx += sense * pull * d[0]
        fy += sense * pull * d[1]
    return fx, fy


def _acting(spring: object, s: sympy.Expr) -> sympy.Expr:
    """The stretch that acts along the motion: for an elastic cord (tension only) none
    while it is slack, for a push-only spring none once the body has left it."""
    if getattr(spring, "compression_only", False):
        return sympy.Piecewise((s, s < 0), (0, True))
    if not getattr(spring, "tension_only", False):
        return s
    return sympy.Piecewise((s, s > 0), (0, True))


def _size(name: str, symbols: Mapping[str, sympy.Expr]) -> sympy.Expr:
    if name not in symbols:
        raise NotSimulable(f"the size of the load {name} is not known")
    return symbols[name]


def _numbers(
    symbols: Mapping[str, sympy.Expr], values: Mapping[sympy.Symbol, sympy.Expr]
) -> dict[str, sympy.Expr]:
    """The scene's named quantities (g, the loads' sizes) with the givens' values put in,
    so the terms are built in numbers (and q) from the start."""
    rule = dict(values)
    return {name: (sympy.Integer(0) + v).xreplace(rule) for name, v in symbols.items()}


def _float(expr: sympy.Expr) -> float:
    """A force component in numbers as a float; NotSimulable where a given has no value,
    ArithmeticError where it is not finite (a spring of zero length)."""
    value = sympy.Integer(0) + expr
    if value.free_symbols:
        names = ", ".join(sorted(str(s) for s in value.free_symbols))
        raise NotSimulable(f"symbolic givens ({names}) have no values")
    number = float(value)
    if not math.isfinite(number):
        raise ArithmeticError(f"the force is not finite there ({number})")
    return number


def _samples(
    expr: sympy.Expr, values: Mapping[sympy.Symbol, sympy.Expr], points: tuple[float, ...]
) -> list[float]:
    """``expr`` (a function of :data:`Q`) with the values put in, at each of ``points``:
    a few numbers to decide on, without generating code for them."""
    numeric = (sympy.Integer(0) + expr).xreplace(dict(values))
    left = numeric.free_symbols - {Q}
    if left:
        names = ", ".join(sorted(str(s) for s in left))
        raise NotSimulable(f"symbolic givens ({names}) have no values")
    return [float(numeric.xreplace({Q: sympy.Float(q)})) for q in points]


def _potential(
    scene: Scene,
    placements: Mapping[str, Placement],
    link_turns: Mapping[str, sympy.Expr],
    symbols: Mapping[str, sympy.Expr],
) -> sympy.Expr:
    """V(q) of the weights, springs, torsion springs, constant forces and couples (V = 0
    in the scene)."""
    terms: list[sympy.Expr] = []
    if scene.gravity is not None:
        for name, placement in placements.items():
            weight = scene.bodies[name].mass * symbols["g"]
            terms.append(-weight * _dot(scene.gravity, placement.shift))
    for spring in scene.springs:
        if spring.body not in placements and spring.other not in placements:
            continue
        if spring.wound:
            placement = placements[spring.body]
            G = scene.bodies[spring.body].G
            rho = (spring.point[0] - G[0], spring.point[1] - G[1])
            a = (
                spring.point[0] + placement.shift[0] - placement.turn * rho[1],
                spring.point[1] + placement.shift[1] + placement.turn * rho[0],
            )
        else:
            a = _point(scene, placements, spring.body, spring.point)
        b = _point(scene, placements, spring.other, spring.other_point) if spring.other else None
        b = b or spring.other_point
        d = (b[0] - a[0], b[1] - a[1])
        terms.append(spring.k * _acting(spring, root(_dot(d, d)) - spring.unstretched) ** 2 / 2)
    for torsion in scene.torsions:  # ½ k Δθ², neutral as drawn
        placement = placements.get(torsion.body)
        if placement is not None:
            terms.append(torsion.k * placement.turn**2 / 2)
    for load in scene.loads:
        if load.kind == "couple":
            turn = link_turns.get(load.body)
            if turn is None:
                placement = placements.get(load.body)
                turn = placement.turn if placement is not None else sympy.Integer(0)
            terms.append(-_size(load.name, symbols) * load.sense * turn)
        elif load.body in placements:
            P = _point(scene, placements, load.body, load.point)
            step = (P[0] - load.point[0], P[1] - load.point[1])
            terms.append(-_size(load.name, symbols) * _dot(load.direction, step))
    return sympy.Add(*terms)


def _friction(
    scene: Scene,
    placements: Mapping[str, Placement],
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    static: bool = False,
) -> sympy.Expr:
    """Σ μk N |dr_C/dq| over the rough contacts that slide (its sign is set by q'); with
    ``static``, Σ μs N |dr_C/dq|, the most friction can hold at rest (μk where no μs)."""
    total = sympy.Integer(0)
    for support in scene.supports:
        if support.body not in placements or support.kind in ("pin", "rolls"):
            continue
        P = _point(scene, placements, support.body, support.point)
        slip = (sympy.diff(P[0], Q), sympy.diff(P[1], Q))
        G = _point(scene, placements, support.body, scene.bodies[support.body].G)
        if _is_still(slip, (sympy.diff(G[0], Q), sympy.diff(G[1], Q)), values):
            continue
        if support.smooth:
            continue
        if support.mu_k is None:
            raise NotSimulable(f"{support.body} slides at {support.name}: mu_k is not known")
        mu = support.mu_s if static and support.mu_s is not None else support.mu_k
        total += mu * _normal(scene, placements, support, symbols, values) * root(_dot(slip, slip))
    return total


def _is_still(slip: Vec, v_G: Vec, values: Mapping[sympy.Symbol, sympy.Expr]) -> bool:
    """The contact point does not move along the travel: |dr_C/dq|² at most 1e-24 of
    |dr_C/dq|² + |dr_G/dq|² at three points (scale-free: a travel coordinate that is an
    angle gives both a length's size)."""
    points = (0.0, 0.37, 1.0)
    slips = _samples(_dot(slip, slip), values, points)
    sizes = _samples(_dot(v_G, v_G), values, points)
    return all(abs(s) <= 1e-24 * (abs(s) + g) for s, g in zip(slips, sizes, strict=True))


def _normal(
    scene: Scene,
    placements: Mapping[str, Placement],
    support: Support,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> sympy.Expr:
    """N at a contact of a body translating along a straight surface: −ΣF·n of the rest."""
    name = support.body
    turns = _samples(placements[name].turn, values, (0.0, 0.37, 1.0))
    alone = not any(s.body == name and s is not support for s in scene.supports) and not any(
        name in (link.body, link.other) for link in scene.links
    )
    if not alone or any(abs(t) > 1e-12 for t in turns):
        raise NotSimulable(
            f"the normal force at {support.name} changes with the motion (the body turns, or "
            "another support or link shares the load)"
        )
    N = -_dot(_applied(scene, placements, name, symbols), support.normal)
    return sympy.Abs(N) if support.two_sided else N


def _build(
    scene: Scene,
    placements: Mapping[str, Placement],
    link_turns: Mapping[str, sympy.Expr],
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    coordinate: str,
    unit: str,
    simplify: bool = False,
    force: sympy.Expr | None = None,
) -> OneDof:
    """M, M', Q_c = −V', the friction's size and V, and each body's placement, to be
    written as float functions; ``force``: Q_c as found without differentiating V (the
    applied force along a particle's straight line)."""
    symbols = _numbers(symbols, values)
    mass_matrix, slope = sympy.Integer(0), sympy.Integer(0)  # M and M' = dM/dq
    places: list[sympy.Expr] = []
    names = tuple(placements)
    for name in names:
        body, placement = scene.bodies[name], placements[name]
        dx, dy = sympy.diff(placement.shift[0], Q), sympy.diff(placement.shift[1], Q)
        dtheta = sympy.diff(placement.turn, Q)
        mass_matrix += body.mass * (dx**2 + dy**2) + body.I_G * dtheta**2
        # M' by the product rule on the parts (sympy's diff of the squares costs more)
        ddx, ddy, ddtheta = (sympy.diff(d, Q) for d in (dx, dy, dtheta))
        slope += 2 * body.mass * (dx * ddx + dy * ddy) + 2 * body.I_G * dtheta * ddtheta
        places += [
            body.G[0] + placement.shift[0],
            body.G[1] + placement.shift[1],
            placement.turn,
            dx,
            dy,
            dtheta,
        ]
    V = _potential(scene, placements, link_turns, symbols)
    terms = [mass_matrix, slope, -sympy.diff(V, Q) if force is None else force]
    terms += [_friction(scene, placements, symbols, values), V]
    hold = _friction(scene, placements, symbols, values, static=True) if terms[3] != 0 else 0
    numeric = [(sympy.Integer(0) + t).xreplace(dict(values)) for t in [*terms, *places, hold]]
    hold = numeric.pop()
    if simplify:  # a long run: a leaner right-hand side is worth sympy's simplify once
        numeric[:3] = [min(t, sympy.simplify(t), key=sympy.count_ops) for t in numeric[:3]]
    left = set().union(*(t.free_symbols for t in numeric)) - {Q}
    if left:
        raise NotSimulable(f"symbolic givens ({', '.join(sorted(map(str, left)))}) have no values")
    M0 = float(sympy.N(numeric[0].subs(Q, 0)))
    if not M0 > 0:
        raise NotSimulable("the scene has no inertia along its motion (M = 0)")
    return OneDof(coordinate, unit, names, tuple(numeric[:5]), tuple(numeric[5:]), hold)
