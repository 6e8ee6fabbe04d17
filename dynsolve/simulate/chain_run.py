"""A chain of bars in time: its history from solve_ivp, the ``until`` event and the energy drift.

The state is y = (θ_1 … θ_n, ω_1 … ω_n), each θ the bar's turn from the scene as drawn.
The run starts from the scene (``omega`` lines give the start rates; from rest without
them), stops at an ``until`` event (``theta(BAR) = …``, ``omega(BAR) = …``, ``x(P) = …``,
``y(P) = …`` of a joint), and reports the drift of T + V, which no friction changes.

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec('''
... given:
...   m = 1 kg
...   L = 1 m
... scene:
...   point O: (0, 0)
...   bar OA: O to A, length L, angle 0, mass m
...   gravity
... ''', "bar.dyn")
>>> history = simulate_chain(spec, "theta(OA) = -90 deg", 10.0)
>>> history.stopped_by, round(history.events[-1][3], 6)  # ω² = 3 g/L at the bottom: −5.424942
('theta(OA) = -90 deg', -5.424942)
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from dynsolve.budget import SIMULATING, step
from dynsolve.errors import Position, SpecError
from dynsolve.linkage.model import read_linkage
from dynsolve.linkage.position import place
from dynsolve.simulate.chain import Chain, chain_from
from dynsolve.simulate.equations import NotSimulable
from dynsolve.simulate.integrator import METHODS, Run, value_at_start
from dynsolve.simulate.loop import Loop, loop_from
from dynsolve.simulate.spin3d import Spin3D
from dynsolve.spec.ast import Spec
from dynsolve.units import Dim

UNTIL = re.compile(
    r"^\s*(?P<name>theta|omega|x|y)\s*\(\s*(?P<of>[A-Za-z_][A-Za-z_0-9]*)\s*\)\s*=\s*"
    r"(?P<quantity>.+?)\s*$"
)
DIMS = {"theta": Dim(), "omega": Dim(0, 0, -1), "x": Dim(1, 0, 0), "y": Dim(1, 0, 0)}


@dataclass(frozen=True)
class Coordinates:
    """What the chain's coordinates are (the part of a motion the output names)."""

    coordinate: str
    unit: str
    bodies: tuple[str, ...]


@dataclass(frozen=True)
class ChainHistory:
    """A simulated chain of bars: the time history, the events met and the energy drift."""

    file: str
    title: str
    system: str
    chain: Chain | Loop | Spin3D
    motion: Coordinates
    run: Run  # q and qd: one row per sample, one column per bar
    stopped_by: str
    events: tuple[tuple[str, float, float, float], ...]  # (name, t, θ, ω) of the named bar
    period: None = None  # an n-coordinate motion has no one period
    small_period: None = None
    equilibrium: None = None
    missed: str = ""  # why the --until event was not met ("" when it was, or none asked)

    @property
    def invariant(self) -> str:
        """What the drift is measured on: T + V, or T − Ω·H_O + V in a turning frame."""
        return "T - Omega.H_O + V" if isinstance(self.chain, Spin3D) else "T + V"

    def columns(self) -> tuple[str, ...]:
        """The history's column names, with units."""
        length = "ft" if self.system == "FPS" else "m"
        energy = "ft*lb" if self.system == "FPS" else "J"
        kinetic = "T - Omega.H_O" if isinstance(self.chain, Spin3D) else "T"
        names = ["t [s]"]
        names += [f"theta_{b} [rad]" for b in self.chain.bars]
        names += [f"omega_{b} [rad/s]" for b in self.chain.bars]
        for p in self.chain.joints:
            names += [f"x_{p} [{length}]", f"y_{p} [{length}]"]
        return (*names, f"{kinetic} [{energy}]", f"V [{energy}]", f"U_friction [{energy}]")

    def rows(self) -> list[tuple[float, ...]]:
        """One row per time sample, in the order of :meth:`columns`."""
        y = np.vstack([self.run.q.T, self.run.qd.T])
        places = self.chain.positions(self.run.q.T)
        T, V = self.chain.energies(y)
        table = np.vstack([self.run.t, y, places, T, V, np.zeros_like(T)])
        return [tuple(float(v) for v in row) for row in table.T]


def simulate_chain(
    spec: Spec,
    until: str | None = None,
    t_end: float = 10.0,
    method: str = "DOP853",
    rtol: float = 1e-10,
    atol: float = 1e-12,
    samples: int = 501,
) -> ChainHistory:
    """Integrate the spec's chain of bars from its state (see the module's docstring)."""
    where = Position(spec.file, spec.scene[0].line if spec.scene else 1, 1)
    from dynsolve.rigid3d.model import is_3d

    try:
        if is_3d(spec):
            from dynsolve.simulate.spin3d import spin_of

            chain = spin_of(spec)
        else:  # read and placed once: loop closure decides which model it is
            linkage = read_linkage(spec)
            placement = place(linkage)
            build = loop_from if placement.closure else chain_from
            chain = build(linkage, placement)
    except NotSimulable as exc:
        raise SpecError(str(exc), where, hint="see docs/simulate.md") from None
    event = _until_event(until, chain, spec.system) if until else None
    try:
        run = integrate_chain(chain, t_end, method, rtol, atol, samples, event)
    except ValueError as exc:
        locked = "lock" in str(exc) or "cannot close" in str(exc)
        raise SpecError(
            str(exc),
            Position("--until" if locked else "--method", 1, 1),
            hint="stop the run before it ('--until theta(BAR) = …' or a shorter --t-end)"
            if locked
            else "try --method Radau or a looser --rtol",
        ) from None
    coordinates = Coordinates(", ".join(f"turn of {b}" for b in chain.bars), "rad", chain.bars)
    end = float(run.t[-1]) if run.t.size else 0.0
    missed = (
        f"the event '{event[0]}' was not met by t = {end:.6g} s (the end time)"
        if event is not None and not run.stopped_by
        else ""
    )
    return ChainHistory(
        spec.file, spec.title or spec.file, spec.system, chain, coordinates, run,
        run.stopped_by, run.events, missed=missed,
    )  # fmt: skip


def integrate_chain(
    chain: Chain | Loop | Spin3D,
    t_end: float,
    method: str = "DOP853",
    rtol: float = 1e-10,
    atol: float = 1e-12,
    samples: int | None = 501,
    event: tuple[str, object, int] | None = None,
) -> Run:
    """Integrate the chain from its drawn state for ``t_end`` (or until the terminal
    ``event``), sampled at ``samples`` even times (every step when None); the drift of
    T + V over the samples. ValueError when solve_ivp fails or the method is unknown."""
    from scipy.integrate import solve_ivp

    if method not in METHODS:
        raise ValueError(f"unknown method {method!r}: use one of {', '.join(METHODS)}")
    n = chain.size
    y0 = [0.0] * n + list(chain.qd0)
    conditions = None
    if event:
        conditions = [_not_at_start(event[1], chain.right_hand_side(), y0, 1e-7 * t_end)]
    with step(SIMULATING):
        solution = solve_ivp(
            chain.right_hand_side(),
            (0.0, t_end),
            y0,
            method=method,
            rtol=rtol,
            atol=atol,
            t_eval=np.linspace(0.0, t_end, samples) if samples else None,
            events=conditions,
        )
    if solution.status == -1:
        raise ValueError(f"the integration failed: {solution.message}")
    t, y = solution.t, solution.y
    met: list[tuple[str, float, float, float]] = []
    stopped = ""
    if event and solution.t_events and len(solution.t_events[0]):
        name, _, column = event
        t_hit, y_hit = float(solution.t_events[0][0]), solution.y_events[0][0]
        met.append((name, t_hit, float(y_hit[column]), float(y_hit[n + column])))
        if solution.status == 1:
            stopped = name
            t, y = np.append(t, t_hit), np.hstack([y, y_hit.reshape(-1, 1)])
    T, V = chain.energies(y)
    invariant = T + V
    scale = max(float(T.max()), float(np.ptp(V)), 1e-300)
    drift = float(np.max(np.abs(invariant - invariant[0]))) / scale
    return Run(
        t, y[:n].T, y[n:].T, np.zeros_like(t), tuple(met), stopped, method, rtol, atol,
        int(solution.nfev), drift,
    )  # fmt: skip


def _until_event(text: str, chain: Chain | Loop | Spin3D, system: str) -> tuple[str, object, int]:
    """The terminal event of an ``--until`` text: (its name, solve_ivp's condition, the
    column of the bar whose θ and ω the event reports)."""
    from dynsolve.simulate.run import parse_quantity

    where = Position("--until", 1, 1)
    hint = "e.g. 'theta(AB) = 0 deg', 'omega(AB) = 0 rad/s' or 'y(B) = 0 m' (a joint)"
    found = UNTIL.match(text)
    if not found:
        raise SpecError(f"cannot read the event '{text}' for a chain of bars", where, hint=hint)
    name, of = found["name"], found["of"]
    value = parse_quantity(found["quantity"], DIMS[name], system, "--until")
    n = chain.size
    if name in ("theta", "omega"):
        if of not in chain.bars:
            raise SpecError(
                f"no moving bar '{of}'", where, hint=f"the bars are {', '.join(chain.bars)}"
            )
        column = chain.bars.index(of)
        offset = column if name == "theta" else n + column

        def condition(_t: float, y: np.ndarray) -> float:
            return float(y[offset]) - value

    else:
        if of not in chain.joints:
            raise SpecError(
                f"no moving joint '{of}'", where, hint=f"the joints are {', '.join(chain.joints)}"
            )
        index = 2 * chain.joints.index(of) + (name == "y")
        column = 0

        def condition(_t: float, y: np.ndarray) -> float:
            return chain.joints_at(y[:n])[index] - value

    condition.terminal = True  # type: ignore[attr-defined]
    return text.strip(), condition, column


def _not_at_start(
    condition: Callable[[float, np.ndarray], float],
    rates: Callable[[float, Sequence[float]], list[float]],
    y0: list[float],
    h: float,
) -> Callable[[float, np.ndarray], float]:
    """The event's condition, except that the start is never an event (see
    :func:`dynsolve.simulate.integrator.value_at_start`); "just after" is the state a
    second-order step h ahead: q + h q' + ½ h² q'', q' + h q''."""
    n = len(y0) // 2

    def after() -> float:
        q, qd, qdd = y0[:n], y0[n:], rates(0.0, y0)[n:]
        ahead = [a + h * b + 0.5 * h * h * c for a, b, c in zip(q, qd, qdd, strict=True)]
        ahead += [b + h * c for b, c in zip(qd, qdd, strict=True)]
        return condition(h, np.asarray(ahead))

    start = value_at_start(condition(0.0, np.asarray(y0)), after)

    def wrapped(t: float, y: np.ndarray) -> float:
        return start if t == 0 else condition(t, y)

    wrapped.terminal = True  # type: ignore[attr-defined]
    return wrapped
