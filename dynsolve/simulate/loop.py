"""The equation of motion of a linkage with closed loops and one degree of freedom (a four-bar).

The coordinate q is the turn of the *input bar*, the bar pinned to a fixed point whose
angle the scene gives (the crank). Every other moving joint follows from q through the
loop-closure constraints Φ(x, q) = 0, all quadratic in the joints' coordinates: a bar's
length |r_i − r_j|² = L², a slider in a fixed guide (r − r_0)·n = 0, a pin in the slot of
a bar (r_P − r_1) × (r_2 − r_1) = 0. At each q the joints are found by Newton's method
from the last solution; their rates per unit q' follow from Φ_x x' = −Φ_q, and the
second derivatives from Φ_x x'' = −(Φ_q q'' terms + x'ᵀ H x'), H the constraints'
constant Hessians (for a length: 2 |r_i' − r_j'|²). With r_G' = dr_G/dq and θ_b' = dθ_b/dq
of every bar, T = ½ M(q) q'², M = Σ m |r_G'|² + I_G θ_b'², and Lagrange's equation is

    M(q) q'' + h(q) q'² = Q(q),   h = Σ m r_G'·r_G'' + I_G θ_b' θ_b'',   Q = Σ F·r_P' + C θ'

(the weights and constant forces F at their points, couples C on the input bar). Where
Φ_x turns singular (a toggle position: the input bar at the end of its swing, where its
turn stops being a coordinate) the run stops and says so.

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec('''
... given:
...   L = 1 m
...   m = 2 kg
...   down = -90 deg
... scene:
...   point A: (0, 0)
...   point D: (L, 0)
...   bar AB: A to B, length L, angle down, mass m
...   bar BC: B to C, length L, mass m
...   bar CD: C to D, length L, mass m
...   joint C: near (L, -L)
...   gravity
... ''', "parallelogram.dyn")
>>> loop = loop_of(spec)
>>> loop.bars, [abs(v) < 1e-12 for v in loop.rates(0.0, [0.0, 0.0])]  # hanging: at rest
(('AB',), [True, True])
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np
import sympy

from dynsolve.linkage.kinetics import mass_centre
from dynsolve.linkage.model import Linkage, read_linkage
from dynsolve.linkage.position import Placement, place
from dynsolve.simulate.chain import check_drives, number_of
from dynsolve.simulate.equations import NotSimulable
from dynsolve.spec.ast import Spec

NEWTON_STEPS = 30
LOCKED = 1e4  # Φ_x's condition number past which the input bar is at a toggle position


class Locked(ValueError):
    """The loop cannot be closed at this q (a toggle position, or past it)."""


@dataclass
class Loop:
    """A one-degree-of-freedom linkage with loops, ready to integrate in its input bar's
    turn (the interface of :class:`dynsolve.simulate.chain.Chain`)."""

    bars: tuple[str, ...]  # the input bar alone: the coordinate is its turn
    joints: tuple[str, ...]  # the moving joints, in the order of the columns
    qd0: tuple[float, ...]
    pivot: np.ndarray  # the input bar's fixed point
    tip: str  # the input bar's moving joint
    arm: tuple[float, float]  # its length and drawn direction (rad)
    unknown: tuple[str, ...]  # the joints loop closure places
    start: dict[str, np.ndarray]  # every joint as drawn
    constraints: list[tuple[str, tuple[object, ...]]]
    masses: list[tuple[float, str, str, float, float]]  # m, first, second, I_G, t along
    # (a slider's block: first = second = its joint, I_G = 0)
    forces: list[tuple[np.ndarray, str, str, float]]  # F, bar's first, second, t along
    couple: float  # the ccw couple on the input bar
    size: int = 1
    _last: np.ndarray | None = field(default=None, repr=False)

    # -- positions and their derivatives along q

    def _known(self, q: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The input bar's tip, its first and second derivatives in q."""
        length, phi = self.arm
        e = np.array([math.cos(phi + q), math.sin(phi + q)])
        n = np.array([-e[1], e[0]])
        return self.pivot + length * e, length * n, -length * e

    def _where(self, q: float, x: np.ndarray) -> dict[str, np.ndarray]:
        places = dict(self.start)
        places[self.tip] = self._known(q)[0]
        for k, name in enumerate(self.unknown):
            places[name] = x[2 * k : 2 * k + 2]
        return places

    def _residuals(self, q: float, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Φ and Φ_x at (q, x)."""
        r = self._where(q, x)
        index = {name: 2 * k for k, name in enumerate(self.unknown)}
        values = np.zeros(len(self.constraints))
        jac = np.zeros((len(self.constraints), 2 * len(self.unknown)))
        for row, (_kind, grads, value) in enumerate(self._rows(r)):
            values[row] = value
            for name, g in grads:
                if name in index:
                    jac[row, index[name] : index[name] + 2] += g
        return values, jac

    def _rows(self, r: dict[str, np.ndarray]) -> list[tuple[str, list, float]]:
        """Each constraint's kind, its gradients by joint and its value at ``r``."""
        rows = []
        for kind, args in self.constraints:
            if kind == "length":
                i, j, L = args
                d = r[i] - r[j]
                rows.append((kind, [(i, 2 * d), (j, -2 * d)], float(d @ d - L * L)))
            elif kind == "guide":
                P, base, m = args
                rows.append((kind, [(P, m)], float((r[P] - base) @ m)))
            else:  # slot: (r_P − r_1) × (r_2 − r_1) = 0
                P, one, two = args
                a, b = r[P] - r[one], r[two] - r[one]
                gP = np.array([b[1], -b[0]])
                g2 = np.array([-a[1], a[0]])
                rows.append(
                    (kind, [(P, gP), (two, g2), (one, -gP - g2)], float(a[0] * b[1] - a[1] * b[0]))
                )
        return rows

    def solve(self, q: float) -> np.ndarray:
        """The unknown joints' coordinates at q, by Newton's method from the last solution."""
        x = self._last.copy() if self._last is not None else self._start_x()
        scale = max(1.0, float(np.max(np.abs(x))) if x.size else 1.0)
        for _ in range(NEWTON_STEPS):
            values, jac = self._residuals(q, x)
            if np.max(np.abs(values)) < 1e-13 * scale * scale:
                break
            try:
                x = x - np.linalg.solve(jac, values)
            except np.linalg.LinAlgError:
                raise Locked(f"the loop cannot close at q = {q:.6g} rad") from None
        else:
            raise Locked(f"the loop cannot close at q = {q:.6g} rad (past a toggle position)")
        self._last = x
        return x

    def _start_x(self) -> np.ndarray:
        return (
            np.concatenate([self.start[name] for name in self.unknown])
            if self.unknown
            else np.zeros(0)
        )

    def derivatives(self, q: float) -> tuple[dict[str, np.ndarray], ...]:
        """Every joint's place, first and second derivative in q."""
        x = self.solve(q)
        r = self._where(q, x)
        _, tip1, tip2 = self._known(q)
        zero = np.zeros(2)
        d1 = {name: zero for name in r} | {self.tip: tip1}
        _, jac = self._residuals(q, x)
        if np.linalg.cond(jac) > LOCKED:
            raise Locked(
                f"the linkage locks at q = {q:.6g} rad: a toggle position, where the input "
                "bar's turn stops being a coordinate (the rest of the loop may swing on)"
            )
        rows = self._rows(r)
        rhs = -np.array([sum(float(g @ d1[name]) for name, g in grads) for _, grads, _ in rows])
        x1 = np.linalg.solve(jac, rhs)
        d1 |= {name: x1[2 * k : 2 * k + 2] for k, name in enumerate(self.unknown)}
        d2 = {name: zero for name in r} | {self.tip: tip2}
        bias = []
        for (kind, args), (_, grads, _) in zip(self.constraints, rows, strict=True):
            known = sum(float(g @ d2[name]) for name, g in grads)  # the tip's part
            if kind == "length":
                i, j, _ = args
                dv = d1[i] - d1[j]
                known += 2 * float(dv @ dv)
            elif kind == "slot":
                P, one, two = args
                a, b = d1[P] - d1[one], d1[two] - d1[one]
                known += 2 * float(a[0] * b[1] - a[1] * b[0])
            bias.append(-known)
        x2 = np.linalg.solve(jac, np.array(bias))
        d2 |= {name: x2[2 * k : 2 * k + 2] for k, name in enumerate(self.unknown)}
        return r, d1, d2

    # -- the equation of motion

    def _terms(self, q: float) -> tuple[float, float, float, dict[str, np.ndarray]]:
        """M, h and Q at q (see the module's docstring), with the joints' places."""
        r, d1, d2 = self.derivatives(q)
        M = h = Q = 0.0
        for m, one, two, I_G, t in self.masses:
            G1 = (1 - t) * d1[one] + t * d1[two]
            G2 = (1 - t) * d2[one] + t * d2[two]
            M += m * float(G1 @ G1)
            h += m * float(G1 @ G2)
            if one == two:  # a slider's block: a particle, no turn
                continue
            d = r[two] - r[one]
            dd, ddd = d1[two] - d1[one], d2[two] - d2[one]
            size = float(d @ d)
            w = (d[0] * dd[1] - d[1] * dd[0]) / size  # θ_b'
            w2 = (d[0] * ddd[1] - d[1] * ddd[0]) / size - 2 * float(d @ dd) * w / size
            M += I_G * w * w
            h += I_G * w * w2
        for F, one, two, t in self.forces:
            Q += float(F @ ((1 - t) * d1[one] + t * d1[two]))
        Q += self.couple
        return M, h, Q, r

    def right_hand_side(self) -> Callable[[float, Sequence[float]], list[float]]:
        """(q', q'') of the state (q, q'): solve_ivp's ``fun``."""

        def rates(_t: float, y: Sequence[float]) -> list[float]:
            M, h, Q, _ = self._terms(float(y[0]))
            return [float(y[1]), float((Q - h * float(y[1]) ** 2) / M)]

        return rates

    def rates(self, t: float, y: Sequence[float]) -> list[float]:
        """(q', q'') at the state y = (q, q')."""
        return self.right_hand_side()(t, y)

    def _energy(self, q: float, qd: float) -> tuple[float, float]:
        M, _, _, r = self._terms(q)
        V = -self.couple * q
        for F, one, two, t in self.forces:
            V -= float(F @ ((1 - t) * r[one] + t * r[two]))
        return 0.5 * M * qd * qd, V

    def energies(self, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """T and V at each column of the states ``y`` (shape 2 × samples)."""
        pairs = [self._energy(float(q), float(qd)) for q, qd in zip(y[0], y[1], strict=True)]
        return np.array([p[0] for p in pairs]), np.array([p[1] for p in pairs])

    def joints_at(self, q: Sequence[float]) -> list[float]:
        """x, y of each moving joint at one configuration q = (θ,)."""
        r = self._where(float(q[0]), self.solve(float(q[0])))
        return [float(c) for name in self.joints for c in r[name]]

    def positions(self, q: np.ndarray) -> np.ndarray:
        """x, y of each moving joint at each column of ``q`` (shape 1 × samples)."""
        return np.array([self.joints_at([v]) for v in q[0]]).T


def loop_of(spec: Spec) -> Loop:
    """The spec's one-degree-of-freedom linkage with loops; NotSimulable says why not."""
    linkage = read_linkage(spec)
    return loop_from(linkage, place(linkage))


def loop_from(linkage: Linkage, placement: Placement) -> Loop:
    """A linkage already placed by loop closure, ready to integrate in its input bar's turn."""
    if linkage.wheels or linkage.meshes:
        raise NotSimulable("rolling wheels and gears in mesh are solved at an instant only")
    check_drives(linkage, "the input bar's")

    def number(expr: object, what: str) -> float:
        return float(number_of(linkage, expr, what))

    start = {
        p: np.array([number(c, f"joint {p}") for c in xy]) for p, xy in placement.positions.items()
    }
    crank = _input_bar(linkage)
    pivot, tip = (
        crank.points if crank.points[0] in linkage.fixed else tuple(reversed(crank.points[:2]))
    )
    d = start[tip] - start[pivot]
    constraints = _constraints(linkage, start, tip, number)
    unknown = tuple(p for p in linkage.joints if p not in linkage.fixed and p != tip)
    if len(constraints) != 2 * len(unknown):
        raise NotSimulable(
            f"the linkage has {2 * len(unknown) - len(constraints) + 1} degrees of freedom "
            "with its input bar turning: simulate takes one (a four-bar, a slider-crank) or "
            "an open chain"
        )
    masses, forces = [], []
    g = linkage.symbols.get("g")
    gravity = next((load for load in linkage.loads if load.kind == "gravity"), None)
    couple = 0.0
    for bar in linkage.bars.values():
        if bar.mass is None or set(bar.points) <= set(linkage.fixed):
            continue
        m = number(bar.mass, f"bar {bar.name}'s mass")
        _, I_G = mass_centre(linkage, bar.name, placement.positions)
        one, two = bar.points[:2]
        masses.append((m, one, two, number(I_G, f"bar {bar.name}'s I_G"), 0.5))
        if gravity is not None and g is not None:
            assert gravity.direction is not None
            weight = m * number(g, "g") * np.array([float(c) for c in gravity.direction])
            forces.append((weight, one, two, 0.5))
    for point, block in linkage.sliders.items():  # a block (piston, collar) at its joint
        if block.mass is None:
            continue
        m = number(block.mass, f"the mass of slider {point}")
        masses.append((m, point, point, 0.0, 0.0))
        if gravity is not None and g is not None:
            assert gravity.direction is not None
            weight = m * number(g, "g") * np.array([float(c) for c in gravity.direction])
            forces.append((weight, point, point, 0.0))
    for load in linkage.loads:
        if load.kind == "gravity":
            continue
        if load.bar not in linkage.bars:  # on a slider's block, at its joint
            assert load.direction is not None
            size = number(linkage.symbols.get(load.name, sympy.Symbol(load.name)), load.name)
            push = size * np.array([float(c) for c in load.direction])
            forces.append((push, load.bar, load.bar, 0.0))
            continue
        size = number(linkage.symbols.get(load.name, sympy.Symbol(load.name)), load.name)
        if load.kind == "couple":
            if load.bar != crank.name:
                raise NotSimulable(
                    f"couple {load.name} acts on {load.bar}: in time, a couple is taken on the "
                    f"input bar {crank.name} only"
                )
            couple += load.sense * size
            continue
        assert load.direction is not None
        bar = linkage.bars[load.bar]
        one, two = bar.points[:2]
        t = 0.5 if load.point == "G" else float(bar.points.index(load.point) > 0)
        if load.point not in ("G", one, two):
            raise NotSimulable(f"force {load.name} acts at a third point of {bar.name}")
        F = size * np.array([float(c) for c in load.direction])
        forces.append((F, one, two, t))
    if not any(m > 0 or I_G > 0 for m, _, _, I_G, _ in masses):
        raise NotSimulable(
            "no bar that moves has a mass: without inertia the linkage has no equation of "
            "motion to integrate (give the bars masses, e.g. 'bar AB: A to B, …, mass m')"
        )
    drive = linkage.drive("omega", crank.name)
    others = [dr for dr in linkage.drives if dr.name != crank.name]
    if others:
        raise NotSimulable(
            f"give the start rate of the input bar {crank.name} ('omega {crank.name}: …'), "
            f"not of {others[0].name}"
        )
    qd0 = (number(drive.value, f"omega {crank.name}") if drive else 0.0,)
    moving = tuple(p for p in linkage.joints if p not in linkage.fixed)
    return Loop(
        (crank.name,), moving, qd0, start[pivot], tip,
        (float(np.hypot(*d)), math.atan2(d[1], d[0])), unknown, start, constraints,
        masses, forces, couple,
    )  # fmt: skip


def _input_bar(linkage: Linkage) -> object:
    """The bar pinned to a fixed point whose angle the scene gives (the crank)."""
    for bar in linkage.bars.values():
        if (
            bar.angle is not None
            and len(bar.points) == 2
            and (set(bar.points) & set(linkage.fixed))
        ):
            return bar
    raise NotSimulable(
        "no input bar: give the angle of a bar pinned to a fixed point (the crank); its turn "
        "is the coordinate"
    )


def _constraints(
    linkage: Linkage,
    start: dict[str, np.ndarray],
    tip: str,
    number: Callable[[object, str], float],
) -> list[tuple[str, tuple[object, ...]]]:
    """The loop-closure constraints (lengths from the drawn assembly)."""
    out: list[tuple[str, tuple[object, ...]]] = []
    for bar in linkage.bars.values():
        points = [p for p in bar.points]
        if set(points) <= set(linkage.fixed) or (
            len(points) == 2 and tip in points and (set(points) - {tip}) <= set(linkage.fixed)
        ):
            continue  # the ground, or the input bar itself
        for i, j in _pairs(points):
            out.append(("length", (i, j, float(np.hypot(*(start[i] - start[j]))))))
    for slider in linkage.sliders.values():
        if slider.bar:
            one, two = linkage.bars[slider.bar].points[:2]
            out.append(("slot", (slider.point, one, two)))
            continue
        assert slider.axis is not None
        base = start[slider.through] if slider.through else start[slider.point]
        axis = np.array([number(c, "a guide") for c in slider.axis])
        out.append(("guide", (slider.point, base, np.array([axis[1], -axis[0]]))))
    return out


def _pairs(points: Sequence[str]) -> list[tuple[str, str]]:
    """The distances that keep a bar rigid: one for two points, every pair for three
    (a triangle), and the two to its first points for each further point."""
    if len(points) <= 3:
        return [
            (points[i], points[j]) for i in range(len(points)) for j in range(i + 1, len(points))
        ]
    return [(points[0], points[1])] + [(p, q) for p in points[2:] for q in points[:2]]
