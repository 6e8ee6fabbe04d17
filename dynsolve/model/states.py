"""Where a one-degree-of-freedom scene is in state 2, and how fast each part moves there.

Each body's state-2 placement is its displacement Δr_G and rotation Δθ from the scene
as described (state 1); each link's is its rotation. The supports, links and motions
of the scene give the position constraints (a pin's point stays put, a rolling disk's
centre moves r Δθ, a contact point stays on its surface, a link keeps its length, a cord
keeps its length and its direction: :func:`cord_end_shifts`), and the ``travel`` lines
fix the state. Writing cos Δθ and sin Δθ as unknowns of their own
makes every constraint linear; they are solved together and each angle recovered from
its sine and cosine. A rotation that only the closure of a loop would fix (a general
four-bar linkage: circle conditions, several assemblies) is refused with a hint.
The velocities in state 2 are the constraints' time derivatives at the state-2
geometry: a homogeneous linear system whose one-dimensional null space gives every
velocity as a multiple of the rate of travel.

>>> import sympy
>>> from dynsolve.model.scene import Body, Scene, Support, Travel
>>> r, s = sympy.symbols("r s", positive=True)
>>> disk = Body("disk", 1, 1, (0, r), (0, r), "disk", (r,), {}, False, "", 0, 0)
>>> rolls = Support("rolls", "C", "disk", (0, 0), (0, 1))
>>> scene = Scene({"disk": disk}, {}, (rolls,), (), (), None, {},
...               travels={"disk": Travel("disk", "by", distance=s, direction=(1, 0))})
>>> change = state_change(scene)
>>> change.placements["disk"].turn
-s/r
>>> change.rates.omega["disk"]
-1/r
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import sympy

from dynsolve.model.scene import Body, Cord, Scene, Support, Travel, Vec
from dynsolve.numbers import float_functions, real_value, tidy, tidying_lightly
from dynsolve.solver.roots import sign_of

ZERO: Vec = (sympy.Integer(0), sympy.Integer(0))


@dataclass(frozen=True)
class Placement:
    """A body's state 2 relative to state 1: its G moved by ``shift``, turned by ``turn``."""

    shift: Vec
    turn: sympy.Expr  # ccw positive
    cos: sympy.Expr
    sin: sympy.Expr


@dataclass(frozen=True)
class Rates:
    """Velocities in state 2 per unit rate of travel (the rate is positive along the travel)."""

    v_G: Mapping[str, Vec]
    omega: Mapping[str, sympy.Expr]
    link_omega: Mapping[str, sympy.Expr]


@dataclass(frozen=True)
class StateChange:
    """The scene in state 2: placements, link rotations, velocity ratios, and how."""

    placements: Mapping[str, Placement]
    link_turns: Mapping[str, sympy.Expr]
    rates: Rates
    rate_name: str  # what the rate of travel measures, e.g. "ω of disk" or "speed of G"
    relations: tuple[str, ...]  # the kinematic relations used, for the derivation
    initial: Rates  # the velocities in state 1 per unit of some rate


def turned(cos: sympy.Expr, sin: sympy.Expr, vector: Vec) -> Vec:
    """``vector`` rotated by the angle with this cosine and sine.

    >>> turned(0, 1, (1, 0))
    (0, 1)
    """
    return (cos * vector[0] - sin * vector[1], sin * vector[0] + cos * vector[1])


def point_after(body: Body, placement: Placement, P: Vec) -> Vec:
    """Where the material point of ``body`` that was at ``P`` in state 1 is in state 2.

    >>> import sympy
    >>> bar = Body("bar", 1, 1, (1, 0), (0, 0), "rod", (2,), {}, False, "", 0, 0)
    >>> half_turn = Placement((0, 0), sympy.pi, -1, 0)
    >>> point_after(bar, half_turn, (2, 0))
    (0, 0)
    """
    rho = turned(placement.cos, placement.sin, (P[0] - body.G[0], P[1] - body.G[1]))
    return tuple(  # type: ignore[return-value]
        tidy(body.G[i] + placement.shift[i] + rho[i]) for i in range(2)
    )


def wound_after(body: Body, placement: Placement, P: Vec) -> Vec:
    """Where the end of a cord wound on ``body`` and leaving it at ``P`` is in state 2.

    The cord leaves at the same place relative to G throughout, so its end moves with
    the velocity of the body point there, v_G + ω × (P − G), with P − G constant:
    Δr = Δr_G + Δθ k × (P − G). For a disk rolling a distance s, the top moves 2 s.

    >>> import sympy
    >>> r, s = sympy.symbols("r s", positive=True)
    >>> disk = Body("disk", 1, 1, (0, r), (0, r), "disk", (r,), {}, False, "", 0, 0)
    >>> wound_after(disk, Placement((s, 0), -s / r, 1, 0), (0, 2 * r))
    (2*s, 2*r)
    """
    rho = (P[0] - body.G[0], P[1] - body.G[1])
    turn = placement.turn
    return (
        tidy(P[0] + placement.shift[0] - turn * rho[1]),
        tidy(P[1] + placement.shift[1] + turn * rho[0]),
    )


def particle_shift(scene: Scene, travel: Travel) -> Vec | None:
    """Δr_G of a particle's travel ``to`` a position or ``by`` a distance (None otherwise).

    >>> import sympy
    >>> s = sympy.Symbol("s")
    >>> ball = Body("ball", 1, 0, (1, 2), (1, 2), "particle", (), {}, True, "", 0, 0)
    >>> scene = Scene({"ball": ball}, {}, (), (), (), None, {})
    >>> particle_shift(scene, Travel("ball", "to", position=(4, 6)))
    (3, 4)
    >>> particle_shift(scene, Travel("ball", "by", distance=s, direction=(0, -1)))
    (0, -s)
    """
    G = scene.bodies[travel.body].G
    if travel.kind == "to":
        assert travel.position is not None
        return (tidy(travel.position[0] - G[0]), tidy(travel.position[1] - G[1]))
    if travel.kind == "by":
        assert travel.distance is not None and travel.direction is not None
        d = travel.direction
        return (tidy(travel.distance * d[0]), tidy(travel.distance * d[1]))
    return None


def _rolling_radius(scene: Scene, support: Support) -> sympy.Expr:
    """The distance from a rolling body's centre to its contact point."""
    G, C = scene.bodies[support.body].G, support.point
    return tidy(sympy.sqrt((C[0] - G[0]) ** 2 + (C[1] - G[1]) ** 2))


def _cross_k(omega: sympy.Expr, r: Vec) -> Vec:
    """ω k × r."""
    return (-omega * r[1], omega * r[0])


def _minus(a: Vec, b: Vec) -> Vec:
    return (a[0] - b[0], a[1] - b[1])


def _dot(a: Vec, b: Vec) -> sympy.Expr:
    return a[0] * b[0] + a[1] * b[1]


def _cross(a: Vec, b: Vec) -> sympy.Expr:
    return a[0] * b[1] - a[1] * b[0]


def _same(a: Vec, b: Vec) -> bool:
    return tidy(a[0] - b[0]) == 0 and tidy(a[1] - b[1]) == 0


ROUND = ("disk", "ring", "hollow", "sphere", "shell")  # the table's shapes a cord winds on


def is_wound(scene: Scene, name: str, P: Vec, direction: Vec) -> bool:
    """Whether a cord leaving the body ``name`` at ``P`` along ``direction`` is wound on
    it: a round body (a drum given by its gyration or inertia, a disk, a ring …) that turns
    about its G (no pin elsewhere), the cord tangent at P to the circle about G through it
    (the rim). Its end then moves like :func:`wound_after`; any other end is a material
    point of the body.

    >>> import sympy
    >>> r = sympy.Symbol("r", positive=True)
    >>> drum = Body("drum", 1, 1, (0, 0), (0, 0), "disk", (r,), {}, False, "", 0, 0)
    >>> bar = Body("bar", 1, 1, (0, 0), (0, 0), "rod", (2 * r,), {}, False, "", 0, 0)
    >>> scene = Scene({"drum": drum, "bar": bar}, {}, (), (), (), None, {})
    >>> is_wound(scene, "drum", (r, 0), (0, -1)), is_wound(scene, "drum", (r, 0), (1, 0))
    (True, False)
    >>> is_wound(scene, "bar", (r, 0), (0, -1))  # a bar's end is a point of the bar
    False
    """
    from dynsolve.model.inertia import shape_named

    body = scene.bodies[name]
    rho = _minus(P, body.G)
    if body.particle or _same(P, body.G):
        return False
    if body.shape not in ("", "body"):  # "body": given by its gyration or inertia, a drum
        try:
            if shape_named(body.shape).key not in ROUND:
                return False
        except ValueError:  # a composite
            return False
    if any(
        s.body == name and s.kind == "pin" and not _same(s.point, body.G) for s in scene.supports
    ):
        return False
    return tidy(_dot(rho, direction)) == 0


def cord_end_shifts(
    scene: Scene,
    cord: Cord,
    shift: Callable[[str, Vec], Vec],
    turn: Mapping[str, sympy.Expr],
) -> tuple[Vec, Vec]:
    """How far each end of ``cord`` moves between the states: Δr_P of the end on
    ``cord.body`` and Δr_Q of the other (zero when fixed). ``shift(body, P)`` is the
    displacement of a material point; an end wound on a body moves like
    :func:`wound_after`, Δr_G + Δθ k × (P − G). The same with velocities (v_G, ω) for
    ``shift`` and ``turn`` gives the ends' velocities.

    >>> import sympy
    >>> r, phi = sympy.symbols("r phi")
    >>> drum = Body("drum", 1, 1, (0, 0), (0, 0), "disk", (r,), {}, False, "", 0, 0)
    >>> block = Body("block", 1, 0, (r, -2), (r, -2), "particle", (), {}, True, "", 0, 0)
    >>> cord = Cord("T", "drum", (r, 0), (0, -1), "block", (r, -2))
    >>> scene = Scene({"drum": drum, "block": block}, {}, (), (), (), None, {})
    >>> cord_end_shifts(scene, cord, lambda b, P: (0, 0), {"drum": phi, "block": 0})
    ((0, phi*r), (0, 0))
    """

    def end(name: str, P: Vec, direction: Vec) -> Vec:
        body = scene.bodies[name]
        if not is_wound(scene, name, P, direction):
            return shift(name, P)
        base = shift(name, body.G)
        spin = _cross_k(turn[name], _minus(P, body.G))
        return (base[0] + spin[0], base[1] + spin[1])

    shifts = [end(*e) for e in cord_ends(cord)]
    return shifts[0], shifts[1] if len(shifts) > 1 else ZERO


def cord_ends(cord: Cord) -> list[tuple[str, Vec, Vec]]:
    """Each end of ``cord`` on a body: (body, point, the direction the cord pulls it)."""
    ends = [(cord.body, cord.point, cord.direction)]
    if cord.other and cord.other_point is not None:
        ends.append((cord.other, cord.other_point, (-cord.direction[0], -cord.direction[1])))
    return ends


def _refuse_swing(scene: Scene, cord: Cord) -> None:
    """A cord whose direction would change between the states: from a fixed point to a
    point of a body (it swings about the fixed point), or tied to a point off G of a body
    that turns (the point goes round G), not wound on it."""
    for name, P, d in cord_ends(cord):
        body = scene.bodies[name]
        if is_wound(scene, name, P, d):
            continue
        if not cord.other:
            raise _at_cord(
                cord,
                f"the cord {cord.name} ties a point of {name} to a fixed point, so between "
                "the states it swings about it and its direction changes: write it as a "
                f"link to that point ('link {cord.name}: {name} at … to O'), which turns "
                f"with it (then travel along the circle, or 'travel {name}: until "
                f"{cord.name} slack')",
            )
        turns = not body.particle and scene.motions.get(name) != "translation"
        turns = turns and not any(s.body == name and s.kind == "base" for s in scene.supports)
        if turns and not _same(P, body.G):
            raise _at_cord(
                cord,
                f"the cord {cord.name} is tied to a point of {name}, which turns: the point "
                "goes round G, so the cord's direction would change between the states; "
                "between two states a cord must be wound on a round body turning about its "
                f"G (leaving the rim tangentially), or tied at G or to a body that does not "
                f"turn (or write it as a link, 'link {cord.name}: … to …', which may turn)",
            )


def _at_cord(cord: Cord, message: str) -> ValueError:
    """A ValueError pointing at the cord's line in the spec."""
    error = ValueError(message)
    error.line, error.column = cord.line, cord.column  # type: ignore[attr-defined]
    return error


def _check_cord_lines(
    scene: Scene,
    placements: Mapping[str, Placement],
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> None:
    """Each cord keeps its direction between the states (its two ends move alike across
    it); one that would swing is refused."""
    turns = {n: p.turn for n, p in placements.items()}

    def shift(body: str, P: Vec) -> Vec:
        return _minus(point_after(scene.bodies[body], placements[body], P), P)

    for cord in scene.cords:
        near, far = cord_end_shifts(scene, cord, shift, turns)
        gap = _minus(far, near)
        across = real_value(_cross(gap, cord.direction), values)
        size = real_value(sympy.sqrt(_dot(near, near) + _dot(far, far)), values)
        if across is None or size is None or abs(across) <= 1e-9 * max(size, 1e-300):
            continue
        raise _at_cord(
            cord,
            f"the cord {cord.name} would change direction between the states (its ends move "
            "apart across it: it swings); a cord between two states must keep its "
            f"direction: hold its ends on its line, or write it as a link ('link {cord.name}: "
            "… to …') that may turn",
        )


def cord_free_length(
    scene: Scene, cord: Cord, placements: Mapping[str, Placement] | None = None
) -> sympy.Expr | None:
    """The straight (free) length of ``cord`` between its ends, (Q − P)·d, in state 1 or,
    with ``placements``, in state 2: an end wound on a drum leaves it at the same place
    relative to G (it moves with G, not with the turn), any other end is a material point.
    None when the far end is not given.

    >>> import sympy
    >>> drum = Body("drum", 1, 1, (0, 0), (0, 0), "disk", (1,), {}, False, "", 0, 0)
    >>> block = Body("block", 1, 0, (1, -3), (1, -3), "particle", (), {}, True, "", 0, 0)
    >>> cord = Cord("T", "drum", (1, 0), (0, -1), "block", (1, -3))
    >>> scene = Scene({"drum": drum, "block": block}, {}, (), (), (), None, {})
    >>> still, up = Placement((0, 0), 0, 1, 0), Placement((0, 4), 0, 1, 0)  # risen 4: past it
    >>> cord_free_length(scene, cord), cord_free_length(scene, cord, {"drum": still, "block": up})
    (3, -1)
    """
    if cord.other_point is None:
        return None

    def where(name: str, P: Vec, d: Vec) -> Vec:
        if not name or placements is None:
            return P
        body, placement = scene.bodies[name], placements[name]
        if is_wound(scene, name, P, d):
            return (P[0] + placement.shift[0], P[1] + placement.shift[1])
        return point_after(body, placement, P)

    d = cord.direction
    P = where(cord.body, cord.point, d)
    Q = where(cord.other, cord.other_point, (-d[0], -d[1]))
    return tidy(_dot(_minus(Q, P), d))


def _check_cord_lengths(
    scene: Scene,
    placements: Mapping[str, Placement],
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> None:
    """Each cord's free length stays positive in state 2: a travel that would pull an end
    past the other (a block through its drum or pulley) is refused with the numbers."""
    for cord in scene.cords:
        before = cord_free_length(scene, cord)
        after = cord_free_length(scene, cord, placements)
        L1 = None if before is None else real_value(before, values)
        L2 = None if after is None else real_value(after, values)
        if L1 is None or L2 is None or 1e-12 * max(abs(L1), 1e-300) < L2:
            continue
        between = f"{cord.body} and {cord.other}" if cord.other else cord.body
        raise _at_cord(
            cord,
            f"the cord {cord.name} between {between} would be {L2:.4g} long at state 2 "
            f"(its free length {L1:.4g} at state 1, in the spec's length unit): the travel "
            "takes an end past the other (through the drum or pulley); shorten the travel to "
            "less than the cord's free length",
        )


def held_only_by_cords(scene: Scene, name: str) -> bool:
    """Whether only cords hold the body ``name`` (no support or link): nothing but a cord
    keeps it from moving across the cord's line."""
    held = {s.body for s in scene.supports}
    held |= {n for link in scene.links for n in (link.body, link.other)}
    return name not in held


def _held_only_by_cords(scene: Scene, cord: Cord) -> bool:
    """Whether an end of ``cord`` is on a body that only cords hold."""
    return any(held_only_by_cords(scene, name) for name, _, _ in cord_ends(cord))


class _Unknowns:
    """The position and velocity unknowns of every body and link."""

    def __init__(self, scene: Scene):
        self.bodies = list(scene.bodies)
        self.links = [link.name for link in scene.links]
        sym = sympy.Symbol
        self.u = {b: sym(f"u_{b}", real=True) for b in self.bodies}
        self.w = {b: sym(f"w_{b}", real=True) for b in self.bodies}
        self.phi = {n: sym(f"phi_{n}", real=True) for n in self.bodies + self.links}
        self.c = {n: sym(f"c_{n}", real=True) for n in self.bodies + self.links}
        self.s = {n: sym(f"s_{n}", real=True) for n in self.bodies + self.links}
        self.vx = {b: sym(f"vx_{b}", real=True) for b in self.bodies}
        self.vy = {b: sym(f"vy_{b}", real=True) for b in self.bodies}
        self.om = {n: sym(f"om_{n}", real=True) for n in self.bodies + self.links}

    def positions(self) -> list[sympy.Symbol]:
        names = self.bodies + self.links
        return [
            *self.u.values(),
            *self.w.values(),
            *(self.phi[n] for n in names),
            *(self.c[n] for n in names),
            *(self.s[n] for n in names),
        ]

    def velocities(self) -> list[sympy.Symbol]:
        return [*self.vx.values(), *self.vy.values(), *self.om.values()]


def _position_constraints(scene: Scene, x: _Unknowns) -> tuple[list[sympy.Expr], list[str]]:
    """The scene's position constraints between states 1 and 2, each ``expr = 0``."""
    equations: list[sympy.Expr] = []
    relations: list[str] = []

    def after(body: str, P: Vec) -> Vec:
        G = scene.bodies[body].G
        rho = turned(x.c[body], x.s[body], (P[0] - G[0], P[1] - G[1]))
        return (G[0] + x.u[body] + rho[0], G[1] + x.w[body] + rho[1])

    def pair(a: Vec, b: Vec) -> None:
        equations.extend((a[0] - b[0], a[1] - b[1]))

    for name, body in scene.bodies.items():
        if body.particle:
            equations.append(x.phi[name])
    for support in scene.supports:
        b, n = support.body, support.normal
        if support.kind == "pin":
            pair(after(b, support.point), support.point)
            relations.append(f"{b} turns about the pin {support.name}")
        elif support.kind == "rolls":
            k_n = _cross_k(x.phi[b] * _rolling_radius(scene, support), n)
            pair((x.u[b], x.w[b]), k_n)
            relations.append(f"{b} rolls without slipping at {support.name}: Δs_G = r Δθ")
        elif support.kind == "base":
            equations += [x.phi[b], x.u[b] * n[0] + x.w[b] * n[1]]
            relations.append(f"{b} slides on its base {support.name} without turning")
        else:
            moved = after(b, support.point)
            equations.append(
                (moved[0] - support.point[0]) * n[0] + (moved[1] - support.point[1]) * n[1]
            )
            relations.append(f"the point {support.name} of {b} stays on its surface")
    for body, motion in scene.motions.items():
        if motion == "translation":
            equations.append(x.phi[body])
            relations.append(f"{body} translates: Δθ = 0")
    for link in scene.links:
        if link.other:
            start, end = after(link.body, link.point), after(link.other, link.other_point)
        else:
            start, end = after(link.body, link.point), link.other_point
        arm = turned(
            x.c[link.name],
            x.s[link.name],
            (link.point[0] - link.other_point[0], link.point[1] - link.other_point[1]),
        )
        pair((start[0] - end[0], start[1] - end[1]), arm)
        relations.append(f"the link {link.name} keeps its length")
    for cord in scene.cords:
        _refuse_swing(scene, cord)
        start, end = cord_end_shifts(scene, cord, lambda b, P: _minus(after(b, P), P), x.phi)
        gap = _minus(end, start)  # how much the cord's far end moved relative to the near
        equations.append(_dot(gap, cord.direction))
        relations.append(f"the cord {cord.name} keeps its length: (Δr_Q − Δr_P)·d = 0")
        if _held_only_by_cords(scene, cord):
            equations.append(_cross(gap, cord.direction))
            relations.append(f"the cord {cord.name} keeps its direction")
    for travel in scene.travels.values():
        b = travel.body
        if travel.kind == "to":
            assert travel.position is not None
            G = scene.bodies[b].G
            pair((G[0] + x.u[b], G[1] + x.w[b]), travel.position)
        elif travel.kind == "by":
            assert travel.distance is not None and travel.direction is not None
            d = travel.direction
            equations.append(x.u[b] * d[0] + x.w[b] * d[1] - travel.distance)
        else:
            equations.append(x.phi[b] - travel.angle)
    return equations, relations


def _tidiest(expr: sympy.Expr) -> sympy.Expr:
    """``expr`` tidied as in exact mode, in numeric mode too: a placement's parts are
    composed into every later form (work terms, velocity constraints, kinetic energies),
    and linsolve's raw cos θ/(sin²θ + cos²θ) made each of those cost more than this."""
    return tidy(expr, light=False)


def _solve_positions(
    equations: list[sympy.Expr],
    x: _Unknowns,
    tidy: Callable[[sympy.Expr], sympy.Expr] = _tidiest,
    numeric: bool = False,
) -> dict[sympy.Symbol, sympy.Expr]:
    """Solve the (linear in u, w, Δθ, cos Δθ, sin Δθ) constraints, each angle from its sine
    and cosine and back; a rotation left free by them is refused (see ``state_change``)."""
    names = x.bodies + x.links
    known: dict[sympy.Symbol, sympy.Expr] = {}
    unknowns = x.positions()
    for _ in range(4 * len(names) + 4):
        current = [sympy.expand(e.xreplace(known)) for e in equations]
        if numeric:  # a scene to integrate: cos(37.1234°) as a float, not an algebraic number
            current = [float_functions(e) for e in current]
        current = [e for e in current if e != 0]
        free = [v for v in unknowns if v not in known]
        if not current or not free:
            if numeric:  # what linsolve of them all would have found
                _consistent(current, unknowns)
            break
        if numeric:
            determined = _by_one_unknown(current, free) or _by_linsolve(current, free)
        elif tidying_lightly():  # numeric mode's state 2, in letters: exact mode's values
            determined = _by_elimination(current, free)
        else:
            determined = _by_linsolve(current, free)
        progress = False
        for var, value in determined.items():
            known[var] = tidy(value)
            progress = True
        for n in names:
            phi, c, s = x.phi[n], x.c[n], x.s[n]
            if phi in known and c not in known:
                known[c], known[s] = tidy(sympy.cos(known[phi])), tidy(sympy.sin(known[phi]))
                progress = True
            elif c in known and s in known and phi not in known:
                known[phi] = tidy(sympy.atan2(known[s], known[c]))
                progress = True
        if not progress:
            break
    turning = [n for n in names if x.phi[n] not in known]
    if turning:
        raise ValueError(
            f"the turn of {', '.join(turning)} between the states follows from the closure "
            "of a loop, which needs the circle conditions solved: say how it moves instead "
            f"('motion {turning[0]}: translation', or a travel that turns it)"
        )
    return known


def _by_linsolve(equations: list[sympy.Expr], free: list[sympy.Symbol]) -> dict:
    """The unknowns of ``free`` that the linear ``equations`` fix (sympy's linsolve);
    ValueError when they contradict each other."""
    solution = sympy.linsolve(equations, free)
    if solution == sympy.EmptySet:
        raise ValueError("the travel asks for a state the scene's supports cannot reach")
    (values,) = tuple(solution)
    unfixed = set(free)
    return {v: x for v, x in zip(free, values, strict=True) if not (x.free_symbols & unfixed)}


def _by_one_unknown(equations: list[sympy.Expr], free: list[sympy.Symbol]) -> dict:
    """Each unknown of ``free`` that an equation holds alone, solved for from it (a x + b
    = 0: x = −b/a): a scene with its numbers in, parametrized by its travel, needs no
    more (a pin, a link to a fixed point, a travel's line), and sympy's linsolve over an
    expression domain took ten times as long. Empty when no equation has one unknown.

    >>> u, w, q = sympy.symbols("u w q")
    >>> _by_one_unknown([u - 3 * sympy.cos(q), 2 * w + u], [u, w])
    {u: 3*cos(q)}
    """
    unfixed, found = set(free), {}
    for equation in equations:
        (unknown, *others) = (equation.free_symbols & unfixed) or (None, None)
        if unknown is None or others or unknown in found:
            continue
        slope = sympy.diff(equation, unknown)
        if slope == 0 or slope.has(unknown):  # not of the first degree in it
            continue
        found[unknown] = -equation.xreplace({unknown: 0}) / slope
    return found


def _consistent(equations: list[sympy.Expr], unknowns: list[sympy.Symbol]) -> None:
    """Equations left without an unknown must hold: ValueError where one does not (as
    linsolve finds when they are solved with the rest)."""
    if equations and sympy.linsolve(equations, unknowns) == sympy.EmptySet:
        raise ValueError("the travel asks for a state the scene's supports cannot reach")


def _velocity_constraints(
    scene: Scene, x: _Unknowns, placements: Mapping[str, Placement]
) -> list[sympy.Expr]:
    """The time derivatives of the position constraints at the state-2 geometry."""
    equations: list[sympy.Expr] = []

    def at(body: str, P: Vec) -> Vec:
        return point_after(scene.bodies[body], placements[body], P)

    def velocity(body: str, P: Vec) -> Vec:
        G2 = at(body, scene.bodies[body].G)
        spin = _cross_k(x.om[body], (P[0] - G2[0], P[1] - G2[1]))
        return (x.vx[body] + spin[0], x.vy[body] + spin[1])

    for name, body in scene.bodies.items():
        if body.particle:
            equations.append(x.om[name])
    for support in scene.supports:
        b, n = support.body, support.normal
        if support.kind == "pin":
            equations += list(velocity(b, support.point))
        elif support.kind == "rolls":
            k_n = _cross_k(x.om[b] * _rolling_radius(scene, support), n)
            equations += [x.vx[b] - k_n[0], x.vy[b] - k_n[1]]
        elif support.kind == "base":
            equations += [x.om[b], x.vx[b] * n[0] + x.vy[b] * n[1]]
        else:
            v = velocity(b, at(b, support.point))
            equations.append(v[0] * n[0] + v[1] * n[1])
    for body, motion in scene.motions.items():
        if motion == "translation":
            equations.append(x.om[body])
    for link in scene.links:
        start = at(link.body, link.point)
        v_start = velocity(link.body, start)
        if link.other:
            end = at(link.other, link.other_point)
            v_end = velocity(link.other, end)
        else:
            end, v_end = link.other_point, ZERO
        spin = _cross_k(x.om[link.name], (start[0] - end[0], start[1] - end[1]))
        equations += [v_start[0] - v_end[0] - spin[0], v_start[1] - v_end[1] - spin[1]]
    for cord in scene.cords:  # a wound end leaves at the same P − G in state 2
        v_P, v_Q = cord_end_shifts(scene, cord, lambda b, P: velocity(b, at(b, P)), x.om)
        gap = _minus(v_Q, v_P)
        equations.append(_dot(gap, cord.direction))
        if _held_only_by_cords(scene, cord):
            equations.append(_cross(gap, cord.direction))
    return [sympy.expand(e) for e in equations if e != 0]


ONE = -1  # the column of a row's constant term (its unknown is 1)


def _eliminated_rows(
    rows: list[dict[int, sympy.Expr]], columns: int
) -> tuple[list[tuple[int, dict[int, sympy.Expr]]], list[dict[int, sympy.Expr]]]:
    """Sparse elimination of the linear rows Σ a_j x_j = 0 (column :data:`ONE` a constant
    term): the columns 0 … ``columns`` − 1 taken in order, as a row echelon form takes
    them, each by the sparsest row that holds it (a pin, a cord, a rolling contact each
    ties two or three unknowns). Returns the pivots, x_c = Σ coefficient_j x_j in the
    order found, and the rows left without an unknown (their constants). The entries are
    tidied as in exact mode as they form (the parts of the rates and placements that
    everything later is composed of), and one is 0 where :func:`tidy` finds it so, as
    every zero test of numeric mode."""
    rows = [row for row in rows if row]
    pivots: list[tuple[int, dict[int, sympy.Expr]]] = []
    for column in range(columns):
        holding = [row for row in rows if column in row]
        if not holding:
            continue  # a free column
        row = min(holding, key=lambda r: (len(r), not r[column].is_number))
        rows.remove(row)
        solved = {j: _tidiest(-e / row[column]) for j, e in row.items() if j != column}
        pivots.append((column, solved))
        rows = [left for other in rows if (left := _substituted(other, column, solved))]
    return pivots, rows


def _substituted(
    row: dict[int, sympy.Expr], column: int, solved: dict[int, sympy.Expr]
) -> dict[int, sympy.Expr]:
    """``row`` with x_column replaced by its ``solved`` combination; the entries that
    :func:`tidy` finds 0 dropped."""
    row = dict(row)
    b = row.pop(column, None)
    if b is None:
        return row
    for j, e in solved.items():
        row[j] = row.get(j, 0) + b * e
    return {j: t for j, e in row.items() if (t := _tidiest(e)) != 0}


def _back_substituted(
    pivots: list[tuple[int, dict[int, sympy.Expr]]], x: dict[int, sympy.Expr]
) -> dict[int, sympy.Expr]:
    """Every unknown from the free ones in ``x`` (and x_ONE = 1), the last pivot first."""
    x = {**x, ONE: sympy.Integer(1)}
    for column, solved in reversed(pivots):
        x[column] = _tidiest(sympy.Add(*(e * x[j] for j, e in solved.items())))
    return x


def _null_space(A: sympy.Matrix) -> list[sympy.Matrix]:
    """A basis of the null space of the velocity constraints ``A`` (numeric mode), one
    vector per free column with that column 1, as sympy's nullspace gives it, by
    :func:`_eliminated_rows` (sympy's nullspace, simplifying every pivot, took ten times
    as long on a pulley's); the count of the degrees of freedom is exact mode's.

    >>> r, t = sympy.symbols("r theta", positive=True)
    >>> A = sympy.Matrix([[1, 0, -r], [sympy.cos(t), sympy.sin(t), 0]])
    >>> [list(v) for v in _null_space(A)]  # x = r z, y = −x cos θ/sin θ
    [[r, -r/tan(theta), 1]]
    """
    rows = [{j: A[i, j] for j in range(A.cols) if A[i, j] != 0} for i in range(A.rows)]
    pivots, _ = _eliminated_rows(rows, A.cols)
    fixed = {c for c, _ in pivots}
    basis = []
    for free in (j for j in range(A.cols) if j not in fixed):
        x = {j: sympy.Integer(1 if j == free else 0) for j in range(A.cols) if j not in fixed}
        x = _back_substituted(pivots, x)
        basis.append(sympy.Matrix([x[j] for j in range(A.cols)]))
    return basis


def _by_elimination(equations: list[sympy.Expr], free: list[sympy.Symbol]) -> dict:
    """The unknowns of ``free`` that the linear ``equations`` fix, as :func:`_by_linsolve`
    finds them (the same echelon form), by :func:`_eliminated_rows`; linsolve's own forms
    (cos θ/(sin²θ + cos²θ)) cost more to tidy than the elimination takes. ValueError when
    they contradict each other.

    >>> u, c, s, L, t = sympy.symbols("u c s L theta")
    >>> C, S = sympy.cos(t), sympy.sin(t)
    >>> _by_elimination([u - 2, L * c * S - L * s * C, L * c * C + L * s * S - L], [u, c, s])
    {u: 2, c: cos(theta), s: sin(theta)}
    """
    try:
        A, b = sympy.linear_eq_to_matrix(equations, free)
    except ValueError:  # not linear after all (sympy's NonlinearError)
        return _by_linsolve(equations, free)
    rows = []
    for i in range(A.rows):
        row = {j: A[i, j] for j in range(A.cols) if A[i, j] != 0}
        if b[i] != 0:
            row[ONE] = -b[i]
        rows.append(row)
    pivots, left = _eliminated_rows(rows, len(free))
    if left:  # 0 = a constant that is not 0
        raise ValueError("the travel asks for a state the scene's supports cannot reach")
    fixed = {c for c, _ in pivots}
    values = _back_substituted(pivots, {j: v for j, v in enumerate(free) if j not in fixed})
    unfixed = {v for j, v in enumerate(free) if j not in fixed}
    return {free[c]: values[c] for c, _ in pivots if not (values[c].free_symbols & unfixed)}


def _rates(
    scene: Scene,
    x: _Unknowns,
    placements: Mapping[str, Placement],
    given_values: Mapping[sympy.Symbol, sympy.Expr],
    oriented: bool = True,
) -> tuple[Rates, str]:
    """Velocities per unit rate of travel at ``placements``; ``oriented``: signed to move
    toward state 2 and scaled to the travelling body's |ω| or speed."""
    equations = _velocity_constraints(scene, x, placements)
    unknowns = x.velocities()
    if equations:
        A, _ = sympy.linear_eq_to_matrix(equations, unknowns)
        basis = _null_space(A) if tidying_lightly() else A.nullspace(simplify=True)
    else:
        basis = [sympy.eye(len(unknowns))[:, i] for i in range(len(unknowns))]
    if len(basis) != 1:
        what = "cannot move" if not basis else f"has {len(basis)} degrees of freedom"
        raise ValueError(
            f"the scene {what}; work–energy between two states needs one degree of "
            "freedom (add or remove supports, links or 'motion B: translation')"
        )
    vector = dict(zip(unknowns, basis[0], strict=True))
    if not oriented:
        scale, rate_name = sympy.Integer(1), "rate of travel"
    elif (travel := next(iter(scene.travels.values()))).kind == "turns":
        b = travel.body
        omega = vector[x.om[b]]
        scale = sign_of(omega * travel.angle, given_values) / omega
        rate_name = f"|ω| of {b}"
    else:
        b = travel.body
        placement = placements[b]
        v = (vector[x.vx[b]], vector[x.vy[b]])
        speed = tidy(sympy.sqrt(v[0] ** 2 + v[1] ** 2), light=False)
        along = v[0] * placement.shift[0] + v[1] * placement.shift[1]
        extent = travel.distance
        if isinstance(extent, sympy.Symbol) and extent not in given_values:
            along = along.xreplace({extent: 1})  # shift = d·direction, d unknown and > 0
        scale = sign_of(along, given_values) / speed
        rate_name = f"speed of G of {b}"
    # tidied in numeric mode too: the kinetic energies and speeds are composed of these
    # (and tidied as in exact mode), which costs ten times as much from untidy parts
    values = {k: tidy(v * scale, light=False) for k, v in vector.items()}
    rates = Rates(
        v_G={n: (values[x.vx[n]], values[x.vy[n]]) for n in x.bodies},
        omega={n: values[x.om[n]] for n in x.bodies},
        link_omega={n: values[x.om[n]] for n in x.links},
    )
    return rates, rate_name


def state_change(
    scene: Scene, given_values: Mapping[sympy.Symbol, sympy.Expr] | None = None
) -> StateChange:
    """The scene in the state its ``travel`` lines describe; ValueError if it is not one."""
    if len(scene.travels) != 1:
        raise ValueError("describe state 2 with one travel line (the scene moves as one)")
    values = dict(given_values or {})
    for cord in scene.cords:
        _refuse_swing(scene, cord)
    initial = initial_rates(scene, values)  # refuses a scene without one degree of freedom
    x = _Unknowns(scene)
    equations, relations = _position_constraints(scene, x)
    known = _solve_positions(equations, x)
    missing = [n for n in x.bodies if not {x.u[n], x.w[n], x.phi[n]} <= set(known)]
    missing += [n for n in x.links if x.phi[n] not in known]
    if missing:
        raise ValueError(
            f"the position of {', '.join(missing)} in state 2 is not fixed by the scene "
            "(add supports or links)"
        )
    placements = {
        n: Placement((known[x.u[n]], known[x.w[n]]), known[x.phi[n]], known[x.c[n]], known[x.s[n]])
        for n in x.bodies
    }
    _check_cord_lines(scene, placements, {**scene.values, **values})
    _check_cord_lengths(scene, placements, {**scene.values, **values})
    link_turns = {n: known[x.phi[n]] for n in x.links}
    rates, rate_name = _rates(scene, x, placements, values)
    return StateChange(placements, link_turns, rates, rate_name, tuple(relations), initial)


def placements_of(
    scene: Scene, simplify: bool = True
) -> tuple[dict[str, Placement], dict[str, sympy.Expr]]:
    """Each body's placement and each link's turn in the state the ``travel`` line gives,
    without the velocities: the travel may be a free parameter (a simulation's coordinate);
    ``simplify=False`` skips sympy's simplify (for a numeric scene, to be lambdified).

    >>> import sympy
    >>> from dynsolve.model.scene import Body, Support, Travel
    >>> r, q = sympy.symbols("r q", positive=True)
    >>> disk = Body("disk", 1, 1, (0, r), (0, r), "disk", (r,), {}, False, "", 0, 0)
    >>> rolls = Support("rolls", "C", "disk", (0, 0), (0, 1))
    >>> scene = Scene({"disk": disk}, {}, (rolls,), (), (), None, {},
    ...               travels={"disk": Travel("disk", "turns", angle=q)})
    >>> placements, _ = placements_of(scene)
    >>> placements["disk"].shift
    (-q*r, 0)
    """
    x = _Unknowns(scene)
    equations, _ = _position_constraints(scene, x)
    known = _solve_positions(
        equations, x, _tidiest if simplify else sympy.Integer(0).__add__, numeric=not simplify
    )
    missing = [n for n in x.bodies if not {x.u[n], x.w[n], x.phi[n]} <= set(known)]
    missing += [n for n in x.links if x.phi[n] not in known]
    if missing:
        raise ValueError(f"the position of {', '.join(missing)} is not fixed by the scene")
    placements = {
        n: Placement((known[x.u[n]], known[x.w[n]]), known[x.phi[n]], known[x.c[n]], known[x.s[n]])
        for n in x.bodies
    }
    return placements, {n: known[x.phi[n]] for n in x.links}


def initial_rates(
    scene: Scene, given_values: Mapping[sympy.Symbol, sympy.Expr] | None = None
) -> Rates:
    """The velocities in state 1 per unit of some rate (their ratios are what counts);
    ValueError when the scene has not exactly one degree of freedom.

    >>> import sympy
    >>> from dynsolve.model.scene import Body, Support
    >>> disk = Body("disk", 1, 1, (0, 2), (0, 2), "disk", (2,), {}, False, "", 0, 0)
    >>> rolls = Support("rolls", "C", "disk", (0, 0), (0, 1))
    >>> rates = initial_rates(Scene({"disk": disk}, {}, (rolls,), (), (), None, {}))
    >>> rates.v_G["disk"][0] / rates.omega["disk"]  # v_G = −ω r: rolling
    -2
    """
    x = _Unknowns(scene)
    still = Placement(ZERO, sympy.Integer(0), sympy.Integer(1), sympy.Integer(0))
    placements = {name: still for name in scene.bodies}
    rates, _ = _rates(scene, x, placements, dict(given_values or {}), oriented=False)
    return rates
