"""A particle on a circular path in time: its equation of motion in its turn about the
centre, the normal force N(q, q') the path exerts, and the event where N falls to zero.

A lone particle whose G lies on a circular ``path`` (``path dome: x^2 + y^2 = R^2``) is
placed at C + R ê(φ₀ + q), q its turn about the centre C (ccw positive, rad), so Lagrange's
equation is m R² q'' = Q(q) with Q from the weight, constant forces and springs
(:mod:`dynsolve.simulate.equations`). Along ê, m (−R q'²) = F·ê + N·ê with F the applied
forces, so the push of the path, positive while it holds the particle, is

    N = side · (m R q'² + F·ê)

with ``side`` +1 on the inside of the circle (the path pushes toward C: a loop) and −1 on
the outside (it pushes away: a dome). The side is that of the start, as for ``travel B:
until contact lost`` (:func:`dynsolve.principles.until._circle`): outside when the weight
presses the particle toward C, inside otherwise. A path is smooth (the scene language
gives it no friction).

>>> import sympy
>>> from dynsolve.model.scene import Body, Path, Scene
>>> x, y = sympy.symbols("x y")
>>> dome = Path("dome", x**2 + y**2 - 4, x, y)
>>> block = Body("block", 1, 0, (0, 2), (0, 2), "particle", (), {}, True, "", 0, 0)
>>> scene = Scene({"block": block}, {}, (), (), (), (0, -1), {}, paths={"dome": dome})
>>> g = sympy.Symbol("g")
>>> motion, contact = on_circle(scene, {"g": g}, {g: sympy.Float(9.81)})
>>> contact.side, contact.radius, round(contact.normal(0.0, 0.0), 6)  # at rest on top: N = m g
(-1, 2.0, 9.81)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import sympy

from dynsolve.model.scene import Path, Scene
from dynsolve.model.states import Placement
from dynsolve.simulate.compiled import float_function
from dynsolve.simulate.equations import NotSimulable, OneDof, Q, _applied, _build

TANGENT = 1e-9  # a start velocity's part across the path, relative to its size, taken as 0


@dataclass(frozen=True)
class Contact:
    """The circular path a particle moves on, and what its push depends on."""

    path: str
    body: str
    centre: tuple[float, float]
    radius: float
    side: int  # +1: pushes toward the centre (inside, a loop); −1: away (outside, a dome)
    phi_0: float  # the start angle of G about the centre (from +x, ccw)
    mass: float
    up: tuple[float, float] | None  # unit vector against gravity (None without gravity)
    applied: Callable[[float], tuple[float, float]]  # F(q): weight, forces and springs

    @property
    def name(self) -> str:
        """The normal force's name, as in the scene's solve (``N_dome``)."""
        return f"N_{self.path}"

    def outward(self, q: float) -> tuple[float, float]:
        """ê: the unit vector from the centre to the particle at turn q."""
        return math.cos(self.phi_0 + q), math.sin(self.phi_0 + q)

    def normal(self, q: float, qd: float) -> float:
        """N = side · (m R q'² + F·ê): the path's push, positive while it holds."""
        e = self.outward(q)
        F = self.applied(q)
        return self.side * (self.mass * self.radius * qd * qd + F[0] * e[0] + F[1] * e[1])

    def from_top(self, q: float) -> float | None:
        """The particle's angle from the top of the circle (rad, 0 … π), or None."""
        if self.up is None:
            return None
        e = self.outward(q)
        return math.acos(max(-1.0, min(1.0, e[0] * self.up[0] + e[1] * self.up[1])))

    def rise(self, q: float) -> float | None:
        """How far G has risen since the start (up positive), or None without gravity."""
        if self.up is None:
            return None
        e0, e = self.outward(0.0), self.outward(q)
        d = (e[0] - e0[0], e[1] - e0[1])
        return self.radius * (d[0] * self.up[0] + d[1] * self.up[1])


def circular_path(scene: Scene) -> tuple[str, Path] | None:
    """(the lone particle, the circular path through its G), or None when the scene is not
    a single particle on a circle with nothing else guiding it."""
    if not scene.paths:
        return None
    from dynsolve.principles.until import _circle_of

    particles = [n for n, b in scene.bodies.items() if b.particle]
    alone = len(particles) == 1 and len(scene.bodies) == 1
    if not alone or scene.links or scene.supports or scene.movers:  # a mover's speed is given
        return None
    body = scene.bodies[particles[0]]
    for path in scene.paths.values():
        circle = _circle_of(path.curve, path.x, path.y)
        if circle is None:
            continue
        (cx, cy), R = circle
        off = sympy.Integer(0) + (body.G[0] - cx) ** 2 + (body.G[1] - cy) ** 2 - R**2
        if off.is_number and abs(float(off)) <= 1e-12 * max(float(R) ** 2, 1e-300):
            return particles[0], path
    return None


def on_circle(
    scene: Scene, symbols: Mapping[str, sympy.Expr], values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[OneDof, Contact] | None:
    """The equation of motion of a lone particle on a circular path (the scene with its
    numbers put in), and its contact; None when the scene is not one."""
    from dynsolve.principles.until import _circle_of

    found = circular_path(scene)
    if found is None:
        return None
    name, path = found
    body = scene.bodies[name]
    (cx, cy), R = _circle_of(path.curve, path.x, path.y)  # type: ignore[misc]
    C = (float(cx), float(cy))
    radius = float(R)
    G = (float(body.G[0]), float(body.G[1]))
    phi_0 = math.atan2(G[1] - C[1], G[0] - C[0])
    angle = sympy.Float(phi_0, 17) + Q
    shift = (
        sympy.Float(C[0] - G[0], 17) + sympy.Float(radius, 17) * sympy.cos(angle),
        sympy.Float(C[1] - G[1], 17) + sympy.Float(radius, 17) * sympy.sin(angle),
    )
    placements = {name: Placement(shift, sympy.Integer(0), 1, 0)}
    what = f"turn of {name} about the centre of {path.name} (ccw)"
    motion = _build(scene, placements, {}, symbols, values, what, "rad", simplify=True)
    force = _applied(scene, placements, name, symbols)
    numeric = [(sympy.Integer(0) + f).xreplace(dict(values)) for f in force]
    left = set().union(*(f.free_symbols for f in numeric)) - {Q}
    if left:
        raise NotSimulable(f"symbolic givens ({', '.join(sorted(map(str, left)))}) have no values")
    applied = float_function([Q], numeric)
    mass = float((sympy.Integer(0) + body.mass).xreplace(dict(values)))
    up = None
    side = 1  # level with the centre, or no gravity: only the inside can turn it there
    if scene.gravity is not None:
        down = (float(scene.gravity[0]), float(scene.gravity[1]))
        up = (-down[0], -down[1])
        pressed = down[0] * (G[0] - C[0]) + down[1] * (G[1] - C[1])
        if abs(pressed) > 1e-12 * radius:
            side = 1 if pressed > 0 else -1  # weight away from the centre: inside a loop
    contact = Contact(path.name, name, C, radius, side, phi_0, mass, up, applied)
    _check_tangent(scene, contact, values)
    return motion, contact


def _check_tangent(
    scene: Scene, contact: Contact, values: Mapping[sympy.Symbol, sympy.Expr]
) -> None:
    """A start velocity must be along the path (a part across it would leave or hit it)."""
    v = scene.velocities.get(contact.body)
    if v is None:
        return
    vx, vy = (float((sympy.Integer(0) + c).xreplace(dict(values))) for c in v)
    e = contact.outward(0.0)
    across = vx * e[0] + vy * e[1]
    if abs(across) > TANGENT * math.hypot(vx, vy):
        raise NotSimulable(
            f"the velocity of {contact.body} has a part across {contact.path} "
            f"({across:.6g} along the radius): a particle on a path moves along it"
        )


def loss_report(contact: Contact, t: float, q: float, qd: float) -> dict[str, float | None]:
    """Where the contact is lost: the time, the angle turned from the start and from the
    top of the circle (deg), the speed and the rise of G (up positive) there."""
    top = contact.from_top(q)
    return {
        "t": t,
        "q": q,
        "angle_turned_deg": math.degrees(abs(q)),
        "angle_from_top_deg": None if top is None else math.degrees(top),
        "speed": contact.radius * abs(qd),
        "rise": contact.rise(q),
    }
