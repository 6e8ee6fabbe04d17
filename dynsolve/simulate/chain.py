"""The equations of motion of an open chain of pinned bars (a double pendulum), in its bars' turns.

Each bar of the chain hangs from one joint: a fixed point, or a joint of a bar nearer the
ground. Its turn q_i from the scene as drawn (ccw positive) is a coordinate, and every
joint and mass centre is its fixed root plus one *link vector* d e(q_i + β) per bar on
the way to it (e(ψ) = (cos ψ, sin ψ)), as a textbook writes a double pendulum. With
ψ_k = q_k + β_k, Lagrange's equations M(q) q'' = f(q, q') read

    M_ab = Σ m Σ_{k∈a, l∈b} d_k d_l cos(ψ_k − ψ_l) + I_G δ_ab,
    f_a  = Σ m Σ_{k∈a, l} d_k d_l ω_l² sin(ψ_l − ψ_k) + Σ_F d_k (F_y cos ψ_k − F_x sin ψ_k)
           + Σ couples on a,

(k∈a: the link vectors of bar a on the way to the mass centre), with the weights m g and
constant ``force`` lines as F and T, V written the same way, so no simplification is
needed. For up to :data:`CLOSED_FORM` bars q'' is solved in closed form (LU on the
symbolic M) and lambdified as one plain function; beyond that M and f are lambdified and
solved with numpy at each step.

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec('''
... given:
...   m = 1 kg
...   L = 1 m
...   down = -90 deg
... scene:
...   point O: (0, 0)
...   bar OA: O to A, length L, angle down, mass m
...   bar AB: A to B, length L, angle down, mass m
...   gravity
... ''', "double.dyn")
>>> chain = chain_of(spec)
>>> chain.bars, chain.rates(0.0, [0.0, 0.0, 0.0, 0.0]) == [0, 0, 0, 0]  # hanging at rest
(('OA', 'AB'), True)
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import sympy

from dynsolve.linkage.kinetics import mass_centre
from dynsolve.linkage.model import Linkage, read_linkage
from dynsolve.linkage.position import Placement, place
from dynsolve.simulate.equations import NotSimulable
from dynsolve.spec.ast import Spec

CLOSED_FORM = 3  # up to this many bars q'' is solved symbolically (one plain function)


@dataclass(frozen=True)
class Chain:
    """An open chain's equations of motion, ready to integrate.

    ``places`` are the symbolic positions of every moving joint and each bar's G in q;
    ``qd0`` the start rates from the scene's ``omega`` lines (0 from rest).
    """

    bars: tuple[str, ...]  # one coordinate each: its turn from the scene as drawn
    joints: tuple[str, ...]  # the moving joints, in the order of the columns
    q: tuple[sympy.Symbol, ...]
    u: tuple[sympy.Symbol, ...]
    places: tuple[sympy.Expr, ...]  # x, y of each moving joint
    kinetic: sympy.Expr  # T(q, u)
    potential: sympy.Expr  # V(q)
    mass_matrix: sympy.Matrix
    forcing: sympy.Matrix  # Q − Σ m J_Gᵀ (J_G' q')
    qd0: tuple[float, ...]
    angles0: tuple[float, ...]  # each bar's drawn direction (first point to second), rad

    @property
    def size(self) -> int:
        """The number of coordinates (degrees of freedom)."""
        return len(self.bars)

    @functools.cached_property
    def _closed(self) -> Callable[..., list[float]] | None:
        if self.size > CLOSED_FORM:
            return None
        qdd = self.mass_matrix.LUsolve(self.forcing)
        return sympy.lambdify([*self.q, *self.u], [*self.u, *qdd], "math", cse=True)

    @functools.cached_property
    def _numeric(self) -> Callable[..., tuple[object, object]]:
        return sympy.lambdify(
            [*self.q, *self.u], (self.mass_matrix, self.forcing), "numpy", cse=True
        )

    def right_hand_side(self) -> Callable[[float, Sequence[float]], list[float]]:
        """(q', q'') of the state y = (q, q') as one plain function (solve_ivp's ``fun``)."""
        closed = self._closed
        if closed is not None:
            return lambda _t, y: closed(*y)
        numeric, n = self._numeric, self.size

        def rates(_t: float, y: Sequence[float]) -> list[float]:
            M, f = numeric(*y)
            qdd = np.linalg.solve(np.asarray(M, float), np.asarray(f, float).ravel())
            return [*y[n:], *qdd.tolist()]

        return rates

    def rates(self, t: float, y: Sequence[float]) -> list[float]:
        """(q', q'') at the state y = (q, q')."""
        return [float(v) for v in self.right_hand_side()(t, y)]

    @functools.cached_property
    def _energies(self) -> Callable[..., tuple[object, object]]:
        return sympy.lambdify([*self.q, *self.u], (self.kinetic, self.potential), "numpy")

    def energies(self, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """T and V at each column of the states ``y`` (shape 2n × samples)."""
        T, V = self._energies(*y)
        shape = y.shape[1:]
        return np.broadcast_to(T, shape).astype(float), np.broadcast_to(V, shape).astype(float)

    @functools.cached_property
    def _places(self) -> Callable[..., object]:
        return sympy.lambdify([*self.q], list(self.places), "numpy")

    def joints_at(self, q: Sequence[float]) -> list[float]:
        """x, y of each moving joint at one configuration q (plain floats)."""
        return [float(v) for v in self._places(*q)]  # type: ignore[union-attr]

    def positions(self, q: np.ndarray) -> np.ndarray:
        """x, y of each moving joint at each column of ``q`` (shape n × samples)."""
        shape = q.shape[1:]
        return np.array([np.broadcast_to(v, shape) for v in self._places(*q)], dtype=float)


def chain_of(spec: Spec) -> Chain:
    """The spec's chain of bars and its equations of motion; NotSimulable says why not."""
    linkage = read_linkage(spec)
    return chain_from(linkage, place(linkage))


def chain_from(linkage: Linkage, placement: Placement) -> Chain:
    """The equations of motion of a linkage already placed (an open chain)."""
    check_drives(linkage, "each bar's")
    if linkage.sliders or linkage.wheels or linkage.meshes:
        raise NotSimulable(
            "simulate integrates open chains of pinned bars; sliders, rolling wheels and "
            "gears in mesh are solved at an instant only"
        )
    for bar in linkage.bars.values():
        if len(bar.points) < 2:
            raise NotSimulable(f"bar {bar.name} has one point: simulate takes bars between joints")
    if placement.closure:
        raise NotSimulable(
            f"joints {', '.join(p for p, h in placement.how.items() if h == 'loop closure')} "
            "close a loop: the linkage is not an open chain"
        )

    def number(expr: object, what: str) -> sympy.Expr:
        value = number_of(linkage, expr, what)
        return sympy.Float(sympy.N(value, 17), 17) if not value.is_Integer else value

    r0 = {p: (number(x, f"joint {p}"), number(y, f"joint {p}")) for p, (x, y) in
          placement.positions.items()}  # fmt: skip
    order = _hanging_order(linkage)
    q = tuple(sympy.Symbol(f"theta_{bar}", real=True) for bar, _ in order)
    u = tuple(sympy.Symbol(f"omega_{bar}", real=True) for bar, _ in order)
    index = {name: i for i, (name, _) in enumerate(order)}
    # every point as its fixed root plus link vectors d e(q_i + β), one per bar on its path
    where: dict[str, _Place] = {p: (r0[p], ()) for p in linkage.fixed}
    masses: list[tuple[sympy.Expr, _Place, sympy.Expr, int]] = []
    for i, (name, pivot) in enumerate(order):
        root, terms = where[pivot]

        def hung(
            point: tuple[sympy.Expr, sympy.Expr],
            root: tuple[sympy.Expr, sympy.Expr] = root,
            terms: tuple[_Link, ...] = terms,
            pivot: str = pivot,
            i: int = i,
        ) -> _Place:
            dx, dy = point[0] - r0[pivot][0], point[1] - r0[pivot][1]
            d = sympy.sqrt(dx**2 + dy**2)
            link = (d, sympy.atan2(dy, dx), i) if d != 0 else None
            return root, terms + ((link,) if link else ())

        for point in linkage.bars[name].points:
            if point != pivot:
                where[point] = hung(r0[point])
        G0, I_G = mass_centre(linkage, name, r0)
        m = number(linkage.bars[name].mass or 0, f"bar {name}'s mass")
        G = hung((number(G0[0], "G"), number(G0[1], "G")))
        masses.append((m, G, number(I_G, "I_G"), i))
    loads = _loads(linkage, index, where, masses, number)
    n = len(q)
    M = sympy.zeros(n, n)
    forcing = sympy.zeros(n, 1)
    T = sympy.Integer(0)

    def psi(link: _Link) -> sympy.Expr:  # the direction of a link vector
        return q[link[2]] + link[1]

    for m, (_, terms), I_G, i in masses:
        for k in terms:
            for j in terms:
                # −m J_kᵀ (−Σ d_j ω_j² e(ψ_j)), with e(ψ_k + 90°)·e(ψ_j) = sin(ψ_j − ψ_k)
                forcing[k[2]] += m * k[0] * j[0] * u[j[2]] ** 2 * sympy.sin(psi(j) - psi(k))
                same = sympy.cos(psi(k) - psi(j))
                M[k[2], j[2]] += m * k[0] * j[0] * same
                T += m * k[0] * j[0] * u[k[2]] * u[j[2]] * same / 2
        M[i, i] += I_G
        T += I_G * u[i] ** 2 / 2
    V = sympy.Integer(0)
    for F, (root, terms) in loads["forces"]:
        V -= F[0] * root[0] + F[1] * root[1]
        for k in terms:
            V -= k[0] * (F[0] * sympy.cos(psi(k)) + F[1] * sympy.sin(psi(k)))
            forcing[k[2]] += k[0] * (F[1] * sympy.cos(psi(k)) - F[0] * sympy.sin(psi(k)))
    for size, i in loads["couples"]:
        V -= size * q[i]
        forcing[i] += size
    if any(M[i, i] == 0 for i in range(n)):
        empty = next(order[i][0] for i in range(n) if M[i, i] == 0)
        raise NotSimulable(f"bar {empty} and the bars it carries have no mass or inertia")
    moving = tuple(p for p in linkage.joints if p not in linkage.fixed)
    places = tuple(c for p in moving for c in _vector(where[p], q))
    rates = _start_rates(linkage, order, number)
    angles = []
    for name, _ in order:
        first, second = linkage.bars[name].points[:2]
        dx, dy = r0[second][0] - r0[first][0], r0[second][1] - r0[first][1]
        angles.append(float(sympy.atan2(dy, dx)))
    return Chain(
        tuple(name for name, _ in order), moving, q, u, places, T, V, M, forcing, rates,
        tuple(angles),
    )  # fmt: skip


_Link = tuple[sympy.Expr, sympy.Expr, int]  # d, β, the bar's index: d e(q_i + β)
_Place = tuple[tuple[sympy.Expr, sympy.Expr], tuple[_Link, ...]]  # root, link vectors


def _vector(place: _Place, q: Sequence[sympy.Symbol]) -> tuple[sympy.Expr, sympy.Expr]:
    """x, y of a point: its root plus its link vectors at the turns q."""
    (x, y), terms = place
    for d, beta, i in terms:
        x += d * sympy.cos(q[i] + beta)
        y += d * sympy.sin(q[i] + beta)
    return x, y


def check_drives(linkage: Linkage, whose: str) -> None:
    """Only start rates may be given: a given α (or a joint's motion) is what a
    simulation finds."""
    for drive in linkage.drives:
        if drive.kind != "omega":
            raise NotSimulable(
                f"'{drive.kind} {drive.name}' is given, but a simulation finds the motion: "
                f"give only {whose} start rate with 'omega BAR: …'"
            )


def number_of(linkage: Linkage, expr: object, what: str) -> sympy.Expr:
    """``expr`` (a model expression, never spec text) with the givens' values put in; it
    must be a number.

    >>> from dynsolve.linkage.model import Linkage
    >>> L = sympy.Symbol("L")
    >>> empty = Linkage("p.dyn", {}, {}, {}, {}, {}, (), values={L: 2})
    >>> number_of(empty, 3 * L, "a length")
    6
    """
    value = (sympy.Integer(0) + expr).xreplace(dict(linkage.values))
    if value.free_symbols:
        names = ", ".join(sorted(str(s) for s in value.free_symbols))
        raise NotSimulable(f"{what} needs a value for {names}: give it a number")
    return value


def _hanging_order(linkage: Linkage) -> list[tuple[str, str]]:
    """Each moving bar and the joint it hangs from, nearest the ground first."""
    placed = set(linkage.fixed)
    order: list[tuple[str, str]] = []
    left = [b for b in linkage.bars.values() if not set(b.points) <= set(linkage.fixed)]
    while left:
        progress = False
        for bar in list(left):
            held = [p for p in bar.points if p in placed]
            if len(held) > 1:
                raise NotSimulable(
                    f"bar {bar.name} joins {' and '.join(held)}, which the other bars already "
                    "place: the chain is rigid there; simulate integrates open chains and "
                    "loops closed by a joint the scene leaves free (a four-bar)"
                )
            if held:
                order.append((bar.name, held[0]))
                placed |= set(bar.points)
                left.remove(bar)
                progress = True
        if not progress:
            raise NotSimulable(
                f"bar {left[0].name} hangs from no fixed point: pin a chain to the ground "
                "with 'point O: (x, y)' at one of its joints"
            )
    return order


def _loads(
    linkage: Linkage,
    index: dict[str, int],
    where: dict[str, _Place],
    masses: Sequence[tuple[sympy.Expr, _Place, sympy.Expr, int]],
    number: Callable[[object, str], sympy.Expr],
) -> dict[str, list]:
    """The constant forces with the place each acts at (the weights m g at each G, the
    ``force`` lines) and the couples (ccw-signed size, the bar's index); loads on a bar
    that does not move do no work and are left out."""
    forces: list[tuple[tuple[sympy.Expr, sympy.Expr], _Place]] = []
    couples: list[tuple[sympy.Expr, int]] = []
    for load in linkage.loads:
        if load.kind == "gravity":
            assert load.direction is not None
            g = number(linkage.symbols["g"], "gravity")
            for m, G, _, _ in masses:
                if m != 0:
                    forces.append(((m * g * load.direction[0], m * g * load.direction[1]), G))
            continue
        if load.bar not in index:
            continue
        size = number(linkage.symbols.get(load.name, sympy.Symbol(load.name)), load.name)
        if load.kind == "couple":
            couples.append((load.sense * size, index[load.bar]))
        else:
            assert load.direction is not None
            place = masses[index[load.bar]][1] if load.point == "G" else where[load.point]
            forces.append(((size * load.direction[0], size * load.direction[1]), place))
    return {"forces": forces, "couples": couples}


def _start_rates(
    linkage: Linkage,
    order: Sequence[tuple[str, str]],
    number: Callable[[object, str], sympy.Expr],
) -> tuple[float, ...]:
    """Each bar's ω at the start from its ``omega`` line (ccw-signed), 0 without one."""
    rates = []
    for name, _ in order:
        drive = linkage.drive("omega", name)
        rates.append(float(number(drive.value, f"omega {name}")) if drive else 0.0)
    return tuple(rates)
