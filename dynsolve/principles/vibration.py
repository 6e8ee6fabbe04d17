"""The free vibration of a one-degree-of-freedom scene about its equilibrium: ω_n, f_n, τ.

The scene is displaced by one coordinate q (the turn θ of a pinned body or of a link, or
a particle's distance x along its guide or its springs' line): every body's placement as
a function of q comes from :func:`dynsolve.model.states.placements_of`, the machinery of
work and energy. The equation of motion is the textbook's: the sum of the moments about
the pin (or of the forces along the line) of the weights, springs and loads in the
displaced position, M q̈ = Q(q) (ΣM_O = I_O α, ΣF_x = m a_x; the supports do no work).
Linearised about the equilibrium q_e (Q(q_e) = 0; sin θ ≈ θ): M q̈ = Q'(q_e) (q − q_e),
so q̈ + ω_n² (q − q_e) = 0 with ω_n² = −Q'(q_e)/M; τ = 2π/ω_n, f_n = 1/τ. The energy
method (T + V = const, T = ½ M q̇²: ω_n² = V''(q_e)/M) is the second method, and where the
scene has numbers, the period measured from the integrated motion is the third. A scene
with other than one degree of freedom, or whose equilibrium is not stable (ω_n² ≤ 0: an
inverted pendulum), is refused with the reason, never given a period.

>>> from dynsolve.model.scene import Body, Scene, Spring
>>> m, k = sympy.symbols("m k", positive=True)
>>> block = Body("block", m, 0, (0, -1), (0, -1), "particle", (), {}, True, "", 0, 0)
>>> spring = Spring("S", "block", (0, -1), "", (0, 0), k, sympy.Integer(1))
>>> scene = Scene({"block": block}, {}, (), (), (), None, {}, springs=(spring,))
>>> vibration_of(scene, "block", {}).omega_n
sqrt(k)/sqrt(m)
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace

import sympy

from dynsolve.model.scene import Body, Scene, Travel, Vec
from dynsolve.model.states import Placement, initial_rates, placements_of, point_after
from dynsolve.names import pretty
from dynsolve.numbers import real_value, tidy
from dynsolve.results import Check
from dynsolve.spec.ast import Spec
from dynsolve.units import Dim

VIBRATION_FINDS = frozenset({"omega_n", "f_n", "period", "for_period"})
AGREEMENT = 1e-6  # relative: the energy method and the simulation against ω_n
Q = sympy.Symbol("q")


@dataclass(frozen=True)
class Vibration:
    """A scene's small free oscillation in its coordinate q about the equilibrium."""

    coordinate: str  # what q measures, in words
    name: str  # the coordinate's letter: θ or x
    unit: str  # "rad" or "m"
    inertia: sympy.Expr  # M at the equilibrium: I_O, m, or Σ m |dr_G/dq|² + I_G (dθ/dq)²
    force: sympy.Expr  # Q(q): the generalized force of the weights, springs and loads
    potential: sympy.Expr  # V(q), V = 0 as drawn
    stiffness: sympy.Expr  # −Q'(q_e)
    omega_n: sympy.Expr
    principle: str  # "ΣM_O = I_O α", "ΣF = m a along x", …
    offset: bool  # drawn away from the equilibrium (a spring–mass drawn unstretched)
    direction: Vec | None = None  # a lone particle's line (its springs'), else None

    @property
    def period(self) -> sympy.Expr:
        """τ = 2π/ω_n."""
        return 2 * sympy.pi / self.omega_n

    @property
    def frequency(self) -> sympy.Expr:
        """f_n = ω_n/(2π) = 1/τ."""
        return self.omega_n / (2 * sympy.pi)


def vibration_target(
    function: str,
    body: str,
    scene: Scene,
    symbols: Mapping[str, sympy.Expr],
    args: tuple[str, ...] = (),
) -> tuple[sympy.Expr, tuple[tuple[str, sympy.Expr, Dim], ...]]:
    """The find ``omega_n``, ``f_n`` or ``period`` of ``body``'s vibration, with the rows
    its derivation states first (ω_n before τ and f_n), or ``for_period`` (``args``: the
    given X and the period T; X at which τ = T); ValueError (the reason) if none."""
    vibration = vibration_of(scene, body, scene.values, symbols)
    if function == "for_period":
        return _for_period(vibration, scene, symbols, args), (
            ("tau", vibration.period, Dim(0, 0, 1)),
        )
    turning = vibration.unit == "rad"
    inertia = "I_" + vibration.principle[3:].split(" ")[0] if turning else "m_eq"
    if not vibration.principle.startswith("ΣM_") or not inertia.isidentifier():
        inertia = "I_eq" if turning else "m_eq"
    before = (  # the textbook's I_O θ'' + k_θ θ = 0: its two coefficients, then ω_n
        (inertia, vibration.inertia, Dim(2, 1, 0) if turning else Dim(0, 1, 0)),
        ("k_eq", vibration.stiffness, Dim(2, 1, -2) if turning else Dim(0, 1, -2)),
    )
    if function == "omega_n":
        return vibration.omega_n, before
    before += (("omega_n", vibration.omega_n, Dim(0, 0, -1)),)
    if function == "f_n":
        return vibration.frequency, before
    return vibration.period, before


def _for_period(
    vibration: Vibration, scene: Scene, symbols: Mapping[str, sympy.Expr], args: tuple[str, ...]
) -> sympy.Expr:
    """The given X for which τ(X) equals the given T: the one positive root of τ(X) = T."""
    if len(args) != 2 or not all(name in symbols for name in args):
        raise ValueError(
            "write for_period(B, X, T): X and T givens (a length or a stiffness, a period)"
        )
    unknown, period = symbols[args[0]], symbols[args[1]]
    if unknown not in vibration.period.free_symbols:
        raise ValueError(f"the period does not depend on {args[0]}")
    others = {s: v for s, v in scene.values.items() if s != unknown}
    roots = []
    for root in sympy.solve(sympy.Eq(vibration.period, period), unknown):
        value = real_value(root, others)
        if value is None or value > 0:
            roots.append(tidy(root))
    if len(roots) != 1:
        raise ValueError(
            f"τ = {args[1]} gives {len(roots)} positive values of {args[0]}: none is chosen"
        )
    return roots[0]


def vibration_notes(
    spec: Spec, scene: Scene, symbols: Mapping[str, sympy.Expr]
) -> tuple[tuple[str, str], ...]:
    """The derivation of each vibration the find list asks for, once per body."""
    bodies = _asked(spec)
    names = {
        s: sympy.Symbol(pretty(s.name)) for s in symbols.values() if isinstance(s, sympy.Symbol)
    }
    shown = _distinct(scene, bodies, symbols)
    return tuple(
        (f"vibration of {body}", derivation(vibration, names, scene.values))
        for body, vibration in shown.items()
    )


def _asked(spec: Spec) -> dict[str, None]:
    """The bodies whose vibration the find list asks for, in order."""
    return dict.fromkeys(
        item.ref.args[0]
        for item in spec.finds
        if item.ref is not None and item.ref.function in VIBRATION_FINDS and item.ref.args
    )


def _distinct(
    scene: Scene, bodies: Mapping[str, None], symbols: Mapping[str, sympy.Expr]
) -> dict[str, Vibration]:
    """The vibrations asked for, one per coordinate (a drum and its block share one)."""
    found: dict[str, Vibration] = {}
    for body in bodies:
        if body not in scene.bodies:
            continue
        vibration = vibration_of(scene, body, scene.values, symbols)
        if all(v.coordinate != vibration.coordinate for v in found.values()):
            found[body] = vibration
    return found


def scene_vibration_checks(
    problem: object, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Check, ...]:
    """The second methods of each vibration a solved scene's find list asks for."""
    spec: Spec = problem.spec  # type: ignore[attr-defined]
    scene: Scene = problem.scene  # type: ignore[attr-defined]
    symbols = problem.symbols  # type: ignore[attr-defined]
    bodies = _asked(spec)
    checks: list[Check] = []
    for body, vibration in _distinct(scene, bodies, symbols).items():
        motion, why_not = _motion(scene, body, vibration, symbols, values)
        checks += vibration_checks(vibration, values, motion, why_not)
    for item in spec.finds:
        if item.ref is not None and item.ref.function == "for_period":
            checks.append(_period_back(item.ref.args, scene, symbols, values))
    return tuple(checks)


def _period_back(
    args: tuple[str, ...],
    scene: Scene,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> Check:
    """The period of the scene with X = for_period(B, X, T) put back: T again."""
    body, name, period = args
    name_check = f"period back: τ({name}) = {period}"
    found, _ = vibration_target("for_period", body, scene, symbols, (name, period))
    unknown = symbols[name]
    vibration = vibration_of(scene, body, scene.values, symbols)
    others = {s: v for s, v in values.items() if s != unknown}
    size = real_value(found, others)
    back = real_value(vibration.period.xreplace({unknown: found}), others)
    wanted = real_value(symbols[period], values)
    if size is None or back is None or wanted is None:
        return Check.not_run(name_check, "the givens have no values")
    gap = abs(back - wanted) / wanted
    return Check(
        name_check,
        gap <= AGREEMENT,
        f"with {name} = {size:.7g} the period is {back:.7g} s ({period} = {wanted:.7g} s; "
        f"relative difference {gap:.1e})",
    )


def _motion(
    scene: Scene,
    body: str,
    vibration: Vibration,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> tuple[object | None, str]:
    """The scene's integrable equation of motion (:mod:`dynsolve.simulate`), or why not."""
    from dynsolve.simulate.equations import NotSimulable, numeric_scene, straight_line
    from dynsolve.simulate.motion import motion_of

    numbers = {k: v for k, v in values.items() if real_value(v) is not None}
    try:
        if vibration.direction is not None:
            numeric = numeric_scene(scene, numbers)
            line = tuple(sympy.Float(real_value(d, numbers), 17) for d in vibration.direction)
            return straight_line(numeric, body, line, dict(symbols), numbers), ""  # type: ignore[arg-type]
        return motion_of(scene, dict(symbols), numbers), ""
    except (NotSimulable, ValueError, TypeError) as exc:
        return None, str(exc) or "the scene cannot be simulated"


# one solve asks the same vibration for its target, its notes and its checks: kept per
# scene object (the scene held too, so its id is not reused), a few at a time
_CACHE: dict[tuple[int, str], tuple[Scene, Vibration]] = {}


def vibration_of(
    scene: Scene,
    body: str,
    values: Mapping[sympy.Symbol, sympy.Expr],
    symbols: Mapping[str, sympy.Expr] | None = None,
) -> Vibration:
    """The small oscillation of the scene about its equilibrium, in the coordinate of
    ``body`` (its turn, or its distance along its line); ValueError (the reason) when the
    scene has not one degree of freedom or no stable equilibrium. ``symbols``: the givens'
    symbols by name (g, the loads' sizes)."""
    cached = _CACHE.get((id(scene), body))
    if cached is not None and cached[0] is scene:
        return cached[1]
    found = _vibration(scene, body, values, dict(symbols or {}))
    if len(_CACHE) > 16:
        _CACHE.clear()
    _CACHE[(id(scene), body)] = (scene, found)
    return found


def _vibration(
    scene: Scene,
    body: str,
    values: Mapping[sympy.Symbol, sympy.Expr],
    symbols: dict[str, sympy.Expr],
) -> Vibration:
    if scene.travels or scene.impacts or scene.pivots or scene.movers:
        raise ValueError(
            "a vibration is asked of the scene at rest in its equilibrium: leave out "
            "travel, impact and moves lines"
        )
    for spring in scene.springs:
        if spring.wound or spring.tension_only or spring.compression_only:
            raise ValueError(
                f"the spring {spring.name} is wound or one-sided: its vibration is not "
                "written here (use a plain spring)"
            )
    for support in scene.supports:
        rough = support.mu_k is not None or support.mu_s is not None or support.slides
        if support.kind in ("contact", "base") and rough:
            raise ValueError(
                f"the contact {support.name} is rough: its friction would damp the motion "
                "(Coulomb damping is not written here; make it smooth for the free vibration)"
            )
    placements, coordinate, name, unit, principle = _coordinate(scene, body, values)
    direction = None
    if coordinate.endswith("springs' line"):
        direction = tuple(sympy.diff(placements[body].shift[i], Q) for i in range(2))
    inertia_q = sympy.Integer(0)
    for moved, placement in placements.items():
        model = scene.bodies[moved]
        dx, dy = (sympy.diff(placement.shift[i], Q) for i in range(2))
        dtheta = sympy.diff(placement.turn, Q)
        inertia_q += model.mass * (dx**2 + dy**2) + model.I_G * dtheta**2
    symbols.setdefault("g", sympy.Symbol("g", positive=True))
    force = _generalized_force(scene, placements, symbols)
    potential = _potential(scene, placements, symbols)
    inertia = tidy(inertia_q.subs(Q, 0))
    at_rest = tidy(force.subs(Q, 0))
    slope = tidy(sympy.diff(force, Q).subs(Q, 0))
    offset = _off_equilibrium(force, inertia_q, at_rest, slope, values, coordinate)
    omega2 = tidy(-slope / inertia)
    value = real_value(omega2, values)
    if value is None and omega2.is_positive is not True:
        raise ValueError(
            f"the sign of ω_n² = {sympy.sstr(omega2)} is not known: give the givens values"
        )
    if value is not None and value <= 0:
        kind = "neutral" if value == 0 else "unstable"
        raise ValueError(
            f"the equilibrium is {kind} (ω_n² = −Q'/M = {value:.4g} 1/s² ≤ 0: displaced, the "
            "scene does not come back, like an inverted pendulum): it has no period"
        )
    omega_n = tidy(sympy.sqrt(omega2))
    return Vibration(
        coordinate,
        name,
        unit,
        inertia,
        force,
        potential,
        tidy(-slope),
        omega_n,
        principle,
        offset,
        direction,  # type: ignore[arg-type]
    )


def _off_equilibrium(
    force: sympy.Expr,
    inertia: sympy.Expr,
    at_rest: sympy.Expr,
    slope: sympy.Expr,
    values: Mapping[sympy.Symbol, sympy.Expr],
    coordinate: str,
) -> bool:
    """Whether the scene is drawn off its equilibrium (Q(0) ≠ 0); ValueError when it is
    and its stiffness or inertia differs at the equilibrium (only a linear scene, a
    spring–mass drawn unstretched, has the same ω_n there)."""
    if at_rest == 0:
        return False
    rest, stiff = real_value(at_rest, values), real_value(slope, values)
    if rest is None or stiff is None:  # letters only: the scene must be linear in q
        if sympy.simplify(at_rest) == 0:
            return False
        curved = sympy.simplify(sympy.diff(force, Q, 2)) != 0
        if curved or sympy.simplify(sympy.diff(inertia, Q)) != 0:
            raise _not_drawn(sympy.sstr(at_rest), coordinate)
        return True
    if stiff == 0 or abs(rest / stiff) <= 1e-10:  # within 1e-10 rad (or m) of it
        return False
    numeric_force = sympy.lambdify(Q, sympy.diff(force, Q).xreplace(dict(values)), "math")
    numeric_inertia = sympy.lambdify(Q, inertia.xreplace(dict(values)), "math")
    force_at = sympy.lambdify(Q, force.xreplace(dict(values)), "math")
    q = 0.0
    for _ in range(60):  # Newton's method on Q(q) = 0 from the scene as drawn
        step = force_at(q) / numeric_force(q)
        q -= step
        if abs(step) <= 1e-14 * max(abs(q), 1e-300):
            break
    same = abs(numeric_force(q) - stiff) <= 1e-9 * abs(stiff)
    if not same or abs(numeric_inertia(q) - numeric_inertia(0.0)) > 1e-9 * numeric_inertia(0.0):
        raise _not_drawn(f"{rest:.4g}", coordinate)
    return True


def _not_drawn(rest: str, coordinate: str) -> ValueError:
    return ValueError(
        f"the scene is not drawn at its equilibrium (Q = {rest} at q = 0 along the "
        f"{coordinate}) and its stiffness changes on the way there: draw it at rest in its "
        "equilibrium position (a pendulum hanging straight down, a spring stretched by the "
        "static load)"
    )


def _coordinate(
    scene: Scene, body: str, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[dict[str, Placement], str, str, str, str]:
    """Each body's placement in terms of q, what q is, its letter, unit and the principle."""
    model = scene.bodies[body]
    supported = any(s.body == body for s in scene.supports) or any(
        body in (link.body, link.other) for link in scene.links
    )
    if model.particle and not supported and not scene.cords and len(scene.bodies) == 1:
        return _along_springs(scene, body)
    try:
        initial_rates(scene, values)
    except ValueError as exc:
        what = str(exc).split(";")[0].removeprefix("the scene ")
        raise ValueError(f"a vibration needs one degree of freedom, and the scene {what}") from None
    pinned = [s for s in scene.supports if s.kind == "pin" and s.body == body]
    candidates: list[tuple[str, str]] = []  # (who turns, in words)
    if not model.particle:
        candidates.append((body, f"turn θ of {body} (ccw)"))
    candidates += [
        (link.name, f"turn θ of the link {link.name} (ccw)")
        for link in scene.links
        if body in (link.body, link.other)
    ]
    candidates += [  # a block hanging from a drum moves with the drum's turn
        (other, f"turn θ of {other} (ccw)")
        for other, model_other in scene.bodies.items()
        if other != body and not model_other.particle
    ]
    for turner, words in candidates:
        try:
            placements, _ = placements_of(
                replace(scene, travels={turner: Travel(turner, "turns", angle=Q)})
            )
        except ValueError:
            continue
        links = [link for link in scene.links if link.name == turner]
        rolling = [s for s in scene.supports if s.kind == "rolls" and s.body == turner]
        if pinned and len(placements) == 1 and turner == body and not model.particle:
            principle = f"ΣM_{pinned[0].name} = I_{pinned[0].name} α"
        elif rolling and len(placements) == 1:
            contact = rolling[0].name
            principle = f"ΣM_{contact} = I_{contact} α about the contact point (rolling, no slip)"
        elif links and len(placements) == 1:
            centre = scene.point_names.get(links[0].other_point, "the link's fixed end")
            principle = (
                f"ΣM_{centre} = I_{centre} α, I_{centre} = m ℓ² (the link's pull has no moment)"
            )
        else:
            principle = (
                "Newton–Euler for each body, the forces of pins, cords and rolling contacts "
                "eliminated (they do no work)"
            )
        return placements, words, "θ", "rad", principle
    guides = [s for s in scene.supports if s.body == body and s.kind == "contact"]
    alone = len(scene.bodies) == 1
    if alone and model.particle and len(guides) == 1 and (0 + guides[0].normal_acceleration) == 0:
        tangent = guides[0].tangent
        placement = Placement((Q * tangent[0], Q * tangent[1]), sympy.Integer(0), 1, 0)
        words = f"distance x of {body} along its surface at {guides[0].name}"
        return {body: placement}, words, "x", "m", "ΣF_x = m a_x along the surface"
    raise ValueError(
        f"the motion of {body} is not one coordinate dynsolve can write here (a pinned "
        "body, a particle on a link, a lone particle on one straight surface or on springs"
        + ("; the scene has other moving bodies" if not alone else "")
        + ")"
    )


def _along_springs(scene: Scene, body: str) -> tuple[dict[str, Placement], str, str, str, str]:
    """A lone particle held by springs along one line (the textbook's guided block)."""
    springs = [s for s in scene.springs if body in (s.body, s.other)]
    if not springs:
        raise ValueError(f"{body} is held by nothing: it has no equilibrium to vibrate about")
    first = springs[0]
    line = (first.other_point[0] - first.point[0], first.other_point[1] - first.point[1])
    length = sympy.sqrt(line[0] ** 2 + line[1] ** 2)
    unit = (tidy(line[0] / length), tidy(line[1] / length))
    for spring in springs[1:]:
        d = (spring.other_point[0] - spring.point[0], spring.other_point[1] - spring.point[1])
        if tidy(d[0] * unit[1] - d[1] * unit[0]) != 0:
            raise ValueError(
                f"the springs on {body} do not lie on one line: it has two degrees of freedom"
            )
    loads = [load for load in scene.loads if load.body == body and load.kind == "force"]
    across = [scene.gravity] if scene.gravity is not None else []
    across += [load.direction for load in loads]
    for direction in across:
        if tidy(direction[0] * unit[1] - direction[1] * unit[0]) != 0:
            raise ValueError(
                f"a load on {body} acts across its springs' line and nothing guides it: it "
                "has two degrees of freedom (add a smooth guide: 'contact … smooth, guide')"
            )
    placement = Placement((Q * unit[0], Q * unit[1]), sympy.Integer(0), 1, 0)
    words = f"distance x of {body} along its springs' line"
    return {body: placement}, words, "x", "m", "ΣF_x = m a_x along the springs' line"


def _moved(scene: Scene, placements: Mapping[str, Placement], body: str, P: Vec) -> Vec:
    placement = placements.get(body)
    if placement is None:
        return P
    return point_after(scene.bodies[body], placement, P)


def _spring_ends(
    scene: Scene, placements: Mapping[str, Placement]
) -> list[tuple[sympy.Expr, sympy.Expr, Vec, Vec]]:
    """(k, L0, a(q), b(q)) of each spring with an end that moves."""
    ends = []
    for spring in scene.springs:
        if spring.body not in placements and spring.other not in placements:
            continue
        a = _moved(scene, placements, spring.body, spring.point)
        b = _moved(scene, placements, spring.other, spring.other_point) if spring.other else None
        ends.append((spring.k, spring.unstretched, a, b or spring.other_point))
    return ends


def _generalized_force(
    scene: Scene, placements: Mapping[str, Placement], symbols: Mapping[str, sympy.Expr]
) -> sympy.Expr:
    """Q(q) = Σ F·dr_P/dq + Σ M dθ/dq of the weights, springs, torsion springs and loads
    (for one pinned body, ΣM about the pin; for a particle on a line, ΣF along it)."""
    total, g = sympy.Integer(0), symbols["g"]
    for name, placement in placements.items():
        model: Body = scene.bodies[name]
        if scene.gravity is not None:
            velocity = tuple(sympy.diff(placement.shift[i], Q) for i in range(2))
            total += (
                model.mass * g * (scene.gravity[0] * velocity[0] + scene.gravity[1] * velocity[1])
            )
    for k, free, a, b in _spring_ends(scene, placements):
        d = (b[0] - a[0], b[1] - a[1])
        length = sympy.sqrt(d[0] ** 2 + d[1] ** 2)
        pull = k * (length - free) / length  # on end a, toward b, per unit of d
        rate = [sympy.diff(a[i] - b[i], Q) for i in range(2)]
        total += pull * (d[0] * rate[0] + d[1] * rate[1])
    for torsion in scene.torsions:  # M = −k Δθ
        placement = placements.get(torsion.body)
        if placement is not None:
            total -= torsion.k * placement.turn * sympy.diff(placement.turn, Q)
    for load in scene.loads:
        placement = placements.get(load.body)
        if placement is None:
            continue
        size = symbols.get(load.name, sympy.Symbol(load.name))
        if load.kind == "couple":
            total += size * load.sense * sympy.diff(placement.turn, Q)
        else:
            P = _moved(scene, placements, load.body, load.point)
            total += size * sum(load.direction[i] * sympy.diff(P[i], Q) for i in range(2))
    return total


def _potential(
    scene: Scene, placements: Mapping[str, Placement], symbols: Mapping[str, sympy.Expr]
) -> sympy.Expr:
    """V(q) of the weights, springs, torsion springs and loads, V = 0 as drawn."""
    total, g = sympy.Integer(0), symbols["g"]
    for name, placement in placements.items():
        if scene.gravity is not None:
            mass = scene.bodies[name].mass
            shift = placement.shift
            total -= mass * g * (scene.gravity[0] * shift[0] + scene.gravity[1] * shift[1])
    for k, free, a, b in _spring_ends(scene, placements):
        length = sympy.sqrt((b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2)
        total += k * (length - free) ** 2 / 2 - (k * (length - free) ** 2 / 2).subs(Q, 0)
    for torsion in scene.torsions:
        placement = placements.get(torsion.body)
        if placement is not None:
            total += torsion.k * placement.turn**2 / 2
    for load in scene.loads:
        placement = placements.get(load.body)
        if placement is None:
            continue
        size = symbols.get(load.name, sympy.Symbol(load.name))
        if load.kind == "couple":
            total -= size * load.sense * placement.turn
        else:
            P = _moved(scene, placements, load.body, load.point)
            total -= size * sum(load.direction[i] * (P[i] - load.point[i]) for i in range(2))
    return total


def unsquared(expr: sympy.Expr, values: Mapping[sympy.Symbol, sympy.Expr]) -> sympy.Expr:
    """``expr`` with each √(u²) written ±u, the sign u has near q = 0 (a spring's length
    as the textbook writes it: L0 − x, not √((L0 − x)²)).

    >>> L = sympy.Symbol("L", positive=True)
    >>> unsquared(sympy.sqrt((L - Q) ** 2), {L: sympy.Integer(2)})
    L - q
    """

    def signed(root: sympy.Expr) -> sympy.Expr:
        base = root.base.base
        sign = real_value(base.subs(Q, 0), values)
        if sign is None or sign == 0:
            return root
        return (base if sign > 0 else -base) ** (2 * root.exp)

    return expr.replace(
        lambda e: (
            e.is_Pow
            and e.exp in (sympy.S.Half, -sympy.S.Half)
            and e.base.is_Pow
            and e.base.exp == 2
        ),
        signed,
    )


def derivation(
    vibration: Vibration,
    names: Mapping[sympy.Symbol, sympy.Symbol],
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> str:
    """The textbook's three steps, in words: the equation of motion, linearised, in the
    standard form, ω_n read from it (``names``: the symbols as printed)."""
    q = sympy.Symbol(vibration.name)
    accel = f"{vibration.name}''"

    def text(expr: sympy.Expr) -> str:
        if sympy.count_ops(expr) <= 120:  # a big Q(q) is shown as built
            expr = tidy(unsquared(tidy(expr), values))
        shown = expr.xreplace({Q: q}).xreplace(names)
        return sympy.sstr(shown).replace("**", "^")

    small = "sin θ ≈ θ, cos θ ≈ 1" if vibration.unit == "rad" else "the first order in x"
    about = (
        "measured from the static equilibrium, where Q = 0 (the static forces cancel), "
        if vibration.offset
        else "about the equilibrium as drawn, "
    )
    return (
        f"q = {vibration.coordinate}. Equation of motion ({vibration.principle}) at a "
        f"displacement {vibration.name}: ({text(vibration.inertia)}) {accel} = "
        f"{text(vibration.force)}; linearised ({small}) {about}"
        f"({text(vibration.inertia)}) {accel} = −({text(vibration.stiffness)}) {vibration.name}; "
        f"standard form {accel} + ω_n² {vibration.name} = 0 with ω_n² = "
        f"{text(vibration.omega_n**2)}; τ = 2π/ω_n, f_n = 1/τ"
    )


def vibration_checks(
    vibration: Vibration,
    values: Mapping[sympy.Symbol, sympy.Expr],
    motion: object | None,
    why_not: str = "",
) -> tuple[Check, ...]:
    """The energy method, and the period of the integrated motion (``motion``: the
    scene's :class:`~dynsolve.simulate.equations.OneDof`, or None with ``why_not``)."""
    omega = real_value(vibration.omega_n, values)
    curvature = sympy.diff(vibration.potential, Q, 2).subs(Q, 0)
    if omega is None:  # letters only: the two ω_n² compared as formulas; nothing to integrate
        gap = sympy.simplify(curvature / vibration.inertia - vibration.omega_n**2)
        return (
            Check(
                "second method: energy (T + V = const)",
                gap == 0,
                f"T = ½ M {vibration.name}'², d(T + V)/dt = 0 → ω_n² = V''/M = "
                f"{sympy.sstr(tidy(curvature / vibration.inertia))} "
                f"({'the same formula' if gap == 0 else 'a different formula'}); the "
                "simulation did not run: the givens have no values",
            ),
            Check.not_run("simulation: period", "the givens have no values"),
        )
    checks = []
    energy = real_value(curvature / vibration.inertia, values)
    if energy is None or energy <= 0:
        checks.append(
            Check("second method: energy (T + V = const)", False, "V'' has no positive value")
        )
    else:
        gap = abs(math.sqrt(energy) - omega) / omega
        checks.append(
            Check(
                "second method: energy (T + V = const)",
                gap <= AGREEMENT,
                f"T = ½ M {vibration.name}'², d(T + V)/dt = 0 → ω_n = √(V''/M) = "
                f"{math.sqrt(energy):.7g} rad/s (equation of motion: {omega:.7g}; relative "
                f"difference {gap:.1e})",
            )
        )
    checks.append(_simulated(motion, omega, why_not))
    return tuple(checks)


def _simulated(motion: object | None, omega: float, why_not: str) -> Check:
    """The period measured from the motion integrated from a small displacement."""
    name = "simulation: period"
    if motion is None:
        return Check.not_run(name, why_not)
    from scipy.integrate import solve_ivp

    accelerate = motion.accelerator()  # type: ignore[attr-defined]
    expected = 2 * math.pi / omega
    equilibrium = _equilibrium(accelerate)
    if equilibrium is None:
        return Check.not_run(name, "no equilibrium found near the scene as drawn")
    amplitude = 1e-4 * (1.0 if motion.unit == "rad" else max(abs(equilibrium), 1e-3))  # type: ignore[attr-defined]

    def turning(_t: float, y: Sequence[float]) -> float:
        return float(y[1])

    turning.direction = 1  # type: ignore[attr-defined]
    run = solve_ivp(
        lambda _t, y: [y[1], accelerate(y[0], y[1])],
        (0.0, 2.6 * expected),
        [equilibrium + amplitude, 0.0],
        method="DOP853",
        rtol=1e-11,
        atol=1e-14 * max(amplitude, 1e-300),
        events=turning,
    )
    times = run.t_events[0]
    if len(times) < 2:
        return Check(name, False, "the integrated motion does not oscillate")
    measured = float(times[1] - times[0])
    gap = abs(measured - expected) / expected
    return Check(
        name,
        gap <= AGREEMENT * 10,
        f"integrated from {amplitude:.0e} {motion.unit} off the equilibrium: "  # type: ignore[attr-defined]
        f"τ = {measured:.7g} s (2π/ω_n = {expected:.7g} s; relative difference {gap:.1e})",
    )


def _equilibrium(accelerate: object) -> float | None:
    """Where q'' = 0 near q = 0 (Newton's method on the numbers; a linear scene drawn off
    its equilibrium, a spring–mass drawn unstretched, is one step away)."""
    q, previous = 0.0, math.inf
    for count in range(50):
        a = accelerate(q, 0.0)  # type: ignore[operator]
        h = 1e-6 * max(abs(q), 1e-3)
        slope = (accelerate(q + h, 0.0) - accelerate(q - h, 0.0)) / (2 * h)  # type: ignore[operator]
        if slope == 0:
            return None
        step = a / slope
        q -= step
        if abs(step) <= 1e-13 * max(abs(q), 1e-9):
            return q
        if count >= 3 and abs(step) >= 0.5 * previous:  # rounding's floor: no nearer
            return q
        previous = abs(step)
    return None
