"""``dynsolve simulate``: a scene's motion in time from its state, with events and the period.

The scene's one coordinate q is its ``travel`` line's (a turn or a distance), else the
turn of its first body or link that fixes every placement, else a guided particle's
distance along its guide. The run starts from the scene as written (``velocity`` and
``omega`` lines give the start rate), records every turning point of q (its maxima and
minima: the period of an oscillation), stops at an ``until`` event, and reports the
drift of T + V − U_f. Where the motion oscillates about a stable equilibrium q*, the
period of small oscillations 2π √(M(q*)/V''(q*)) (for a pendulum 2π √(I_O/(m g d)))
is shown beside the simulated one. A lone particle on a circular ``path`` is simulated in
its turn about the centre, with the path's normal force in the history and the event
``lost(PATH)`` where that force falls through zero (:mod:`dynsolve.simulate.contact`).

>>> from dynsolve.spec.parser import parse_spec
>>> text = ("given:\\n  m = 1 kg\\n  L = 1 m\\nscene:\\n  point O: (0, 0)\\n"
...         "  body bar: mass m, rod L, at (L/2, 0)\\n  pin bar at O\\n  gravity\\n")
>>> history = simulate_spec(parse_spec(text, "bar.dyn"), until="min", t_end=10.0)
>>> history.stopped_by, round(history.events[-1][2], 6)  # swings cw to the far side: −π
('min', -3.141593)
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass, replace
from fractions import Fraction

import numpy as np

from dynsolve.budget import SIMULATING, step
from dynsolve.errors import Position, SpecError
from dynsolve.model.scene import Scene, build_scene
from dynsolve.modes.equation_mode import givens_of
from dynsolve.simulate.chain_run import ChainHistory
from dynsolve.simulate.contact import Contact, on_circle
from dynsolve.simulate.crosscheck import start_rate
from dynsolve.simulate.equations import (
    NotSimulable,
    OneDof,
    numeric_scene,
)
from dynsolve.simulate.integrator import TIGHT_ATOL, TIGHT_RTOL, Event, Run, integrate
from dynsolve.simulate.motion import motion_of
from dynsolve.spec.ast import Spec
from dynsolve.units import Dim

QUANTITIES = {  # until-quantity: (dimension, meaning)
    "q": (None, "the coordinate"),
    "theta": (Dim(), "the turn of B from the scene as drawn (ccw positive)"),
    "x": (Dim(1, 0, 0), "x of B's mass centre"),
    "y": (Dim(1, 0, 0), "y of B's mass centre"),
    "omega": (Dim(0, 0, -1), "B's angular velocity (ccw positive)"),
    "speed": (Dim(1, 0, -1), "the speed of B's mass centre"),
}
UNTIL = re.compile(
    r"^\s*(?:(?P<extreme>max|min)|(?P<name>[A-Za-z_]+)\s*(?:\(\s*(?P<body>[A-Za-z_][A-Za-z_0-9]*)"
    r"\s*\))?\s*=\s*(?P<number>[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(?P<unit>[^\s].*)?)\s*$"
)
QUANTITY = re.compile(
    r"^\s*(?P<number>[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(?P<unit>[^\s].*?)?\s*$"
)
MAX_SAMPLES = 1_000_000


@dataclass(frozen=True)
class History:
    """A simulated time history, its events and what was measured from it."""

    file: str
    title: str
    system: str
    motion: OneDof
    run: Run
    stopped_by: str
    events: tuple[tuple[str, float, float, float], ...]  # (name, t, q, q')
    period: float | None  # from the turning points of q
    small_period: float | None  # 2π √(M/V'') about the equilibrium it oscillates about
    equilibrium: float | None
    # (q'', largest |q − (q'₀ t + ½ q'' t²)| over the largest |q|) where q'' is constant
    constant_acceleration: tuple[float, float] | None = None
    contact: Contact | None = None  # a particle on a circular path: its normal force
    missed: str = ""  # why the --until event was not met ("" when it was, or none asked)

    def columns(self) -> tuple[str, ...]:
        """The history's column names, with units."""
        length = "ft" if self.system == "FPS" else "m"
        unit = length if self.motion.unit == "m" else "rad"
        names = ["t [s]", f"q [{unit}]", f"q_dot [{unit}/s]"]
        for b in self.motion.bodies:
            names += [f"x_{b} [{length}]", f"y_{b} [{length}]", f"theta_{b} [rad]"]
            names += [f"vx_{b} [{length}/s]", f"vy_{b} [{length}/s]", f"omega_{b} [rad/s]"]
        if self.contact is not None:
            names.append(f"{self.contact.name} [{'lb' if self.system == 'FPS' else 'N'}]")
        energy = "ft*lb" if self.system == "FPS" else "J"
        return (*names, f"T [{energy}]", f"V [{energy}]", f"U_friction [{energy}]")

    def rows(self) -> list[tuple[float, ...]]:
        """One row per time sample, in the order of :meth:`columns`."""
        out = []
        run, motion = self.run, self.motion
        for t, q, qd, uf in zip(run.t, run.q, run.qd, run.friction_work, strict=True):
            row = [float(t), float(q), float(qd)]
            for p in motion.places(float(q)).values():
                row += [p[0], p[1], p[2], p[3] * qd, p[4] * qd, p[5] * qd]
            if self.contact is not None:
                row.append(self.contact.normal(float(q), float(qd)))
            T = motion.kinetic(q, qd)
            row += [T, motion.energy(q, qd) - T, float(uf)]
            out.append(tuple(float(v) for v in row))
        return out


def parse_quantity(text: str, dim: Dim | None, system: str, what: str) -> float:
    """``"10 s"``, ``"30 deg"``, ``"0.5"``: a number and a unit of dimension ``dim``, in the
    system's base units (never evaluated: a number and a parsed unit only).

    >>> parse_quantity("90 deg", Dim(), "SI", "theta")
    1.5707963267948966
    >>> parse_quantity("2 min", Dim(0, 0, 1), "SI", "t")
    120.0
    """
    from dynsolve.quantities import resolve_unit
    from dynsolve.spec.parser import parse_unit
    from dynsolve.units import to_base

    found = QUANTITY.match(text)
    where = Position(what, 1, 1)
    if not found:
        raise SpecError(f"'{text}' is not a number with a unit", where, hint="e.g. '10 s'")
    unit_text = found["unit"]
    number = Fraction(found["number"])
    if unit_text:
        unit = resolve_unit(parse_unit(unit_text, what), what)
        if dim is not None and unit.dim != dim:
            raise SpecError(
                f"'{unit_text}' is not a unit of {dim.name}", where, hint="check the unit"
            )
        return float(to_base(number, unit, system))  # type: ignore[arg-type]
    if dim is not None and dim not in (Dim(),) and number != 0:
        raise SpecError(f"'{text}' needs a unit of {dim.name}", where, hint="e.g. '10 s'")
    return float(number)


def until_event(text: str, motion: OneDof, system: str) -> Event:
    """The terminal event an ``until`` text names: ``max``/``min`` (of q), ``q = VALUE``,
    ``theta(B) = VALUE``, ``x(B)``, ``y(B)``, ``omega(B)``, ``speed(B)``."""
    where = Position("--until", 1, 1)
    found = UNTIL.match(text)
    hint = "e.g. 'max', 'theta(bar) = 0 deg', 'x(bob) = 0 m' or 'q = 1 rad'"
    if not found:
        raise SpecError(f"cannot read the event '{text}'", where, hint=hint)
    if found["extreme"]:
        direction = -1 if found["extreme"] == "max" else 1
        return Event(found["extreme"], lambda q, qd: qd, direction)
    name, body = found["name"], found["body"]
    if name not in QUANTITIES or (name == "q") != (body is None):
        raise SpecError(f"'{name}' is not a quantity of the motion", where, hint=hint)
    if body is not None and body not in motion.bodies:
        known = ", ".join(motion.bodies)
        raise SpecError(f"no moving body '{body}'", where, hint=f"the bodies are {known}")
    dim = QUANTITIES[name][0]
    if name == "q":
        dim = Dim() if motion.unit == "rad" else Dim(1, 0, 0)
    quantity = f"{found['number']} {found['unit'] or ''}"
    value = parse_quantity(quantity, dim, system, "--until")
    index = list(motion.bodies).index(body) if body is not None else 0

    def measure(q: float, qd: float) -> float:
        if name == "q":
            return q - value
        place = motion.places(q)[motion.bodies[index]]
        reading = {
            "theta": place[2],
            "x": place[0],
            "y": place[1],
            "omega": place[5] * qd,
            "speed": math.hypot(place[3], place[4]) * abs(qd),
        }[name]
        return reading - value

    return Event(text.strip(), measure, 0)


SLACK = re.compile(r"^\s*slack\(\s*(?P<link>[A-Za-z_][A-Za-z_0-9]*)\s*\)\s*$")


def slack_event(
    text: str, scene: Scene, motion: OneDof, symbols: dict, values: dict
) -> Event | None:
    """``slack(CORD)``: the tension of a particle's cord (a ``link`` to a fixed point)
    falls through zero, T/m = v²/R + g·ê with ê from the fixed point to the particle;
    None when ``text`` names no such event (another until text)."""
    found = SLACK.match(text)
    if not found:
        return None
    where = Position("--until", 1, 1)
    name = found["link"]
    link = next((k for k in scene.links if k.name == name), None)
    if link is None or link.other or not scene.bodies[link.body].particle:
        raise SpecError(
            f"slack({name}) needs a link {name} from a particle to a fixed point",
            where,
            hint="e.g. 'link cord: bob at G to O' and --until 'slack(cord)'",
        )
    if scene.gravity is None or link.body not in motion.bodies:
        raise SpecError(f"slack({name}) needs gravity and {link.body} moving", where, hint="")
    number = _numbers(values)
    centre = (number(link.other_point[0]), number(link.other_point[1]))
    down = (number(scene.gravity[0]), number(scene.gravity[1]))
    g = number(symbols["g"])
    index = list(motion.bodies).index(link.body)

    def tension_per_mass(q: float, qd: float) -> float:
        place = motion.places(q)[motion.bodies[index]]
        r = (place[0] - centre[0], place[1] - centre[1])
        R = math.hypot(*r)
        v2 = (place[3] ** 2 + place[4] ** 2) * qd * qd
        return v2 / R + g * (down[0] * r[0] + down[1] * r[1]) / R

    return Event(f"slack({name})", tension_per_mass, -1)


LOST = re.compile(r"^\s*(?:lost\(\s*(?P<path>[A-Za-z_][A-Za-z_0-9]*)\s*\)|contact\s+lost)\s*$")


def lost_event(text: str, contact: Contact | None, qd0: float, system: str) -> Event | None:
    """``lost(PATH)`` (or ``contact lost``): the push N of a particle's circular path falls
    through zero (:meth:`~dynsolve.simulate.contact.Contact.normal`); None when ``text``
    names no such event. Refused when the path does not hold the particle at the start."""
    found = LOST.match(text)
    if not found:
        return None
    where = Position("--until", 1, 1)
    asked = found["path"] or "the contact"
    if contact is None:
        raise SpecError(
            f"lost({asked}) needs a lone particle on a circular path",
            where,
            hint="e.g. 'path dome: x^2 + y^2 = R^2', 'body block: particle, mass m, at (0, R)' "
            "and --until 'lost(dome)'",
        )
    if found["path"] and found["path"] != contact.path:
        raise SpecError(
            f"no circular path '{found['path']}' under {contact.body}",
            where,
            hint=f"{contact.body} is on {contact.path}: --until 'lost({contact.path})'",
        )
    N0 = contact.normal(0.0, qd0)
    if not N0 > 0:
        force = "lb" if system == "FPS" else "N"
        where_on = "inside" if contact.side > 0 else "outside"
        raise SpecError(
            f"{contact.name} = {N0:.6g} {force} at the start: {contact.path} does not hold "
            f"{contact.body} there ({where_on} the circle), so there is no contact to lose",
            where,
            hint="start it where the path presses on it (a dome: below the speed √(g R) at "
            "the top; a loop: fast enough at the bottom)",
        )
    return Event(f"lost({contact.path})", contact.normal, -1)


def _numbers(values: dict) -> Callable[[object], float]:
    """A reader of an expression's value as a float (a scene's numbers put in)."""
    from dynsolve.numbers import real_value

    def number(expr: object) -> float:
        found = real_value(0 + expr, values)  # type: ignore[operator]
        if found is None:
            raise SpecError("the scene has no numbers for the cord", Position("--until", 1, 1), "")
        return float(found)

    return number


def simulate_spec(
    spec: Spec,
    until: str | None = None,
    t_end: float = 10.0,
    method: str = "DOP853",
    rtol: float = TIGHT_RTOL,
    atol: float = TIGHT_ATOL,
    samples: int = 501,
) -> History | ChainHistory:
    """Integrate the spec's scene from its state; SpecError (with a hint) on bad input.
    A linkage (``bar`` lines) is integrated as an open chain of bars, in every bar's turn
    (:mod:`dynsolve.simulate.chain_run`)."""
    where = Position(spec.file, spec.scene[0].line if spec.scene else 1, 1)
    if not spec.scene:
        raise SpecError("nothing to simulate: the spec has no scene", where, hint="add 'scene:'")
    if not (t_end > 0 and math.isfinite(t_end)):
        raise SpecError("the end time must be positive", Position("--t-end", 1, 1), "e.g. 10s")
    if not 2 <= samples <= MAX_SAMPLES:
        raise SpecError(f"samples must be 2 … {MAX_SAMPLES}", Position("--samples", 1, 1), "")
    from dynsolve.linkage.model import is_linkage
    from dynsolve.rigid3d.model import is_3d

    if is_linkage(spec) or is_3d(spec):
        from dynsolve.simulate.chain_run import simulate_chain

        return simulate_chain(spec, until, t_end, method, rtol, atol, samples)
    givens = givens_of(spec)
    symbols = {g.name: g.symbol for g in givens}
    values = {g.symbol: g.value for g in givens if g.value is not None}
    try:
        scene = build_scene(spec, symbols, {g.name: g.dim for g in givens}, values)
    except SpecError as error:
        raise _travel_hint(error, spec) from None
    contact = None
    try:
        guided = any(t.kind not in ("for", "until") for t in scene.travels.values())
        on_path = None if guided else on_circle(numeric_scene(scene, values), symbols, values)
        if on_path is not None:
            motion, contact = on_path
        else:
            motion = motion_of(scene, symbols, values)
        qd0 = start_rate(motion, replace(scene, travels={}), values)
    except NotSimulable as exc:
        raise SpecError(str(exc), where, hint="see docs/simulate.md") from None
    events = [Event("max", lambda q, qd: qd, -1, False), Event("min", lambda q, qd: qd, 1, False)]
    until = until or _travel_event(scene, contact)
    stop = None
    if until:
        stop = (
            lost_event(until, contact, qd0, spec.system)
            or slack_event(until, scene, motion, symbols, values)
            or until_event(until, motion, spec.system)
        )
        events = [e for e in events if e.name != stop.name] + [stop]
    if contact is not None and (stop is None or not stop.name.startswith("lost(")):
        # a surface would let go here: shown, never passed over (the run holds it, a bead)
        events.append(Event(f"{contact.name} = 0", contact.normal, 0, False))
    grid = np.linspace(0.0, t_end, samples)
    try:
        with step(SIMULATING):
            run = integrate(motion, 0.0, qd0, t_end, events, method, rtol, atol, t_eval=grid)
    except ValueError as exc:
        raise SpecError(str(exc), Position("--method", 1, 1), hint="see docs/simulate.md") from None
    run = _with_last(run)
    missed = "" if stop is None or run.stopped_by else _missed(stop.name, run, contact, spec)
    period = _period(run.events)
    small, equilibrium = _small_oscillations(motion, run)
    constant = _constant_acceleration(motion, qd0, run)
    return History(
        spec.file,
        spec.title or spec.file,
        spec.system,
        motion,
        run,
        run.stopped_by,
        run.events,
        period,
        small,
        equilibrium,
        constant,
        contact,
        missed,
    )


def _travel_hint(error: SpecError, spec: Spec) -> SpecError:
    """A name that is not a given on a travel line: a simulation has nothing to put there
    (``solve`` finds it), so the hint says what to do instead."""
    line = error.position.line if error.position is not None else 0
    on_travel = any(s.kind == "travel" and s.line == line for s in spec.scene or ())
    if not on_travel or "is not a given" not in error.message:
        return error
    return SpecError(
        error.message,
        error.position,
        hint="a simulation starts from the scene's state and needs no travel: leave the "
        "travel line out (or give its extent a value), and stop the run with --until",
    )


def _travel_event(scene: Scene, contact: Contact | None) -> str:
    """The event a ``travel B: until …`` line names, as an until text ("" for none)."""
    for travel in scene.travels.values():
        if travel.kind == "until" and travel.until == "slack":
            return f"slack({travel.until_name})"
        if travel.kind == "until" and travel.until == "lost" and contact is not None:
            return f"lost({contact.path})"
    return ""


def _missed(name: str, run: Run, contact: Contact | None, spec: Spec) -> str:
    """Why the until event was not met: the run reached its end time first."""
    end = float(run.t[-1]) if run.t.size else 0.0
    text = f"the event '{name}' was not met by t = {end:.6g} s (the end time)"
    if contact is None or not name.startswith("lost("):
        return text
    normals = [contact.normal(float(q), float(qd)) for q, qd in zip(run.q, run.qd, strict=True)]
    force = "lb" if spec.system == "FPS" else "N"
    turned = float(np.max(np.abs(run.q))) if run.q.size else 0.0
    how = (
        f"it hardly moves from where it starts (at most {turned:.2g} rad): at rest at an "
        "equilibrium, it needs a nudge (a 'velocity' line)"
        if turned <= 1e-6
        else "N does not change: it never will"
        if max(normals) - min(normals) <= 1e-9 * max(abs(n) for n in normals)
        else "it goes round and round"
        if turned >= 2 * math.pi
        else "it swings back and forth below where it would leave"
        if any(n for n in run.events if n[0] in ("max", "min"))
        else "it has not got there yet: a longer --t-end may find it"
    )
    return (
        f"contact with {contact.path} is never lost by t = {end:.6g} s: {contact.name} stays "
        f"between {min(normals):.6g} and {max(normals):.6g} {force} ({how})"
    )


def _constant_acceleration(motion: OneDof, qd0: float, run: Run) -> tuple[float, float] | None:
    """Where M and Q do not depend on q (no friction: a body sliding down a smooth slope, a
    wheel rolling down it, a flywheel under a constant couple), q'' = Q/M is constant and
    the closed form is q = q'₀ t + ½ q'' t² (Hibbeler 12.2, 16.3): (q'', the largest
    difference from the run over the largest |q|); None for any other motion."""
    import sympy

    from dynsolve.simulate.equations import Q as q_symbol

    M, dM, Qc, friction = motion.terms[:4]
    if friction != 0 or any((sympy.Integer(0) + e).has(q_symbol) for e in (M, dM, Qc)):
        return None
    if sympy.Integer(0) + dM != 0:
        return None
    accel = float(Qc / M)
    t = np.asarray(run.t, float)
    closed = qd0 * t + accel * t**2 / 2
    q = np.asarray(run.q, float)
    size = max(float(np.max(np.abs(closed))), float(np.max(np.abs(q))), 1e-300)
    return accel, float(np.max(np.abs(q - closed))) / size


def _with_last(run: Run) -> Run:
    """Add the state at a terminal event as the last sample."""
    if run.last is None or (run.t.size and run.t[-1] >= run.last[0]):
        return run
    t, q, qd, uf = run.last
    return replace(
        run,
        t=np.append(run.t, t),
        q=np.append(run.q, q),
        qd=np.append(run.qd, qd),
        friction_work=np.append(run.friction_work, uf),
    )


def _period(events: tuple[tuple[str, float, float, float], ...]) -> float | None:
    """The period from the turning points of q: two maxima (or minima) apart, or twice the
    time from a maximum to the next minimum."""
    for kind in ("max", "min"):
        times = [t for name, t, _, _ in events if name == kind]
        if len(times) >= 2:
            return times[1] - times[0]
    turns = sorted(t for name, t, _, _ in events if name in ("max", "min"))
    return 2 * (turns[1] - turns[0]) if len(turns) >= 2 else None


def _small_oscillations(motion: OneDof, run: Run) -> tuple[float | None, float | None]:
    """2π √(M(q*)/k), k = −dQ/dq at the equilibrium q* between the extremes of the run
    (None when there is none, or it is not stable, or friction acts)."""
    from scipy.optimize import brentq

    if float(np.max(np.abs(run.friction_work))) > 0:
        return None, None
    low, high = float(np.min(run.q)), float(np.max(run.q))
    force = lambda q: motion.generalized_force(q, 0.0)  # noqa: E731
    if high <= low or force(low) * force(high) > 0:
        return None, None
    q_star = brentq(force, low, high, xtol=1e-14, rtol=1e-14)
    h = 1e-5 * max(1.0, abs(q_star))
    k = -(force(q_star + h) - force(q_star - h)) / (2 * h)
    M = 2 * motion.kinetic(q_star, 1.0)
    if k <= 0 or M <= 0:
        return None, q_star
    return 2 * math.pi * math.sqrt(M / k), q_star
