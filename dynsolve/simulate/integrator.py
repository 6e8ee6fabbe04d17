"""The one integrator: a one-coordinate equation of motion in time with scipy's solve_ivp.

The state is (q, q', U_f): the coordinate, its rate and the work done so far by kinetic
friction, so that T + V − U_f is an invariant whose drift measures the integration's
accuracy. Events are functions of (q, q'); the run stops at a terminal one.

>>> from dynsolve.simulate.equations import Q, OneDof
>>> fall = OneDof("drop", "m", ("ball",), (1, 0, 9.81, 0, -9.81 * Q), (0, -Q, 0, 0, -1, 0))
>>> run = integrate(fall, 0.0, 0.0, 10.0, [Event("q = 2 m", lambda q, qd: q - 2.0, 1)])
>>> run.stopped_by, round(float(run.qd[-1]), 9)  # v = √(2 g h) = √39.24 = 6.264183905
('q = 2 m', 6.264183905)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_ivp

from dynsolve.simulate.equations import OneDof

METHODS = ("RK45", "DOP853", "Radau", "LSODA", "RK23", "BDF")
IMPLICIT = ("Radau", "BDF", "LSODA")  # given the analytic Jacobian
TIGHT_RTOL, TIGHT_ATOL = 1e-10, 1e-12


@dataclass(frozen=True)
class Event:
    """A condition g(q, q') = 0 crossed in ``direction`` (+1 rising, −1 falling, 0 either)."""

    name: str
    function: Callable[[float, float], float]
    direction: int = 0
    terminal: bool = True


@dataclass(frozen=True)
class Run:
    """A time history and the events met."""

    t: np.ndarray
    q: np.ndarray
    qd: np.ndarray
    friction_work: np.ndarray
    events: tuple[tuple[str, float, float, float], ...]  # (name, t, q, q') in time order
    stopped_by: str  # the terminal event's name, or "" at the end time
    method: str
    rtol: float
    atol: float | np.ndarray  # a scalar, or one per state (the cross-check)
    evaluations: int
    drift: float = field(default=0.0)  # max |E(t) − E(0)| / scale, E = T + V − U_f
    last: tuple[float, float, float, float] | None = None  # (t, q, q', U_f) at a terminal event


def value_at_start(start: float, after: Callable[[], float]) -> float:
    """An event condition's value at the start, never 0: the start is never an event, so a
    condition that is 0 there takes the sign it has just after (``after()``), e.g. a
    pendulum released from rest is not at a maximum of its swing.

    >>> value_at_start(0.0, lambda: -2.0) < 0, value_at_start(3.0, lambda: -2.0)
    (True, 3.0)
    """
    if start != 0:
        return start
    later = after()
    return math.copysign(1e-300, later) if later != 0 else 1e-300


def integrate(
    motion: OneDof,
    q0: float,
    qd0: float,
    t_end: float,
    events: Sequence[Event] = (),
    method: str = "DOP853",
    rtol: float = TIGHT_RTOL,
    atol: float | np.ndarray = TIGHT_ATOL,
    max_step: float = np.inf,
    t_eval: np.ndarray | None = None,
) -> Run:
    """Integrate from (q0, q'0) at t = 0 until ``t_end`` or a terminal event.

    With kinetic friction the run goes from one stop (q' = 0) to the next: there the
    friction force changes sense, and where static friction can hold the body
    (:meth:`OneDof.holds`) it stays at rest to the end (the event "at rest"), instead of
    chattering about q' = 0 with ever smaller steps.
    """
    if method not in METHODS:
        raise ValueError(f"unknown method {method!r}: use one of {', '.join(METHODS)}")
    fast = motion.right_hand_side() if motion.frictionless else None
    jac = motion.jacobian() if method in IMPLICIT and fast is not None else None
    if fast is not None:  # (q, q') only: U_f stays 0
        rhs = fast
    else:

        def rhs(_t: float, y: np.ndarray) -> list[float]:
            qd = float(y[1])
            qdd, power = motion.rates(float(y[0]), qd)
            return [qd, qdd, power]

    state = [q0, qd0] if fast is not None else [q0, qd0, 0.0]
    t0, evaluations = 0.0, 0
    pieces: list[tuple[np.ndarray, np.ndarray]] = []
    met: list[tuple[str, float, float, float]] = []
    stopped, last = "", None
    peak = [0.0]  # the segment's largest speed (friction: its stop is judged against it)
    for _ in range(MAX_STOPS):
        if fast is None and state[1] == 0 and motion.holds(state[0]):
            met.append((AT_REST, t0, state[0], 0.0))
            pieces.append(_at_rest(state, t0, t_end, t_eval))
            break
        watched = list(events)
        if fast is None:  # friction: this segment ends where it slows to nearly q' = 0
            peak[0] = abs(state[1])
            watched.append(_stop_event(motion, state, peak))
        grid = None if t_eval is None else t_eval[t_eval >= t0]
        solution = solve_ivp(
            rhs,
            (t0, t_end),
            state,
            method=method,
            rtol=rtol,
            atol=atol,
            events=_conditions(watched, motion, t0, state, t_end) or None,
            max_step=max_step,
            t_eval=grid,
            dense_output=False,
            **({"jac": jac} if jac is not None else {}),
        )
        if solution.status == -1:
            raise ValueError(f"the integration failed: {solution.message}")
        evaluations += int(solution.nfev)
        pieces.append((solution.t, solution.y))
        at_stop = None
        for event, times, states in zip(
            watched, solution.t_events or [], solution.y_events or [], strict=False
        ):
            for t, y in zip(times, states, strict=True):
                if event.name == _STOP:
                    at_stop = (float(t), y)
                    continue
                met.append((event.name, float(t), float(y[0]), float(y[1])))
                if event.terminal and solution.status == 1:
                    stopped = event.name
                    last = (float(t), float(y[0]), float(y[1]), float(y[2]) if len(y) > 2 else 0.0)
        if stopped or solution.status != 1 or at_stop is None:
            break
        t0, y = _stopped(motion, *at_stop)  # friction changes sense here, or holds the body
        before = float(at_stop[1][1])
        turns = _turns(events, met, t0, float(y[0]), before)
        met += turns
        state = [float(y[0]), 0.0, float(y[2])]
        pieces.append((np.array([t0]), np.array([[state[0]], [0.0], [state[2]]])))
        terminal = [e.name for e in events if e.terminal and e.name in {n for n, *_ in turns}]
        if terminal:  # the --until event is this stop (a maximum of q)
            stopped, last = terminal[0], (t0, state[0], 0.0, state[2])
            break
    met.sort(key=lambda item: item[1])
    t = np.concatenate([p[0] for p in pieces])
    ys = np.concatenate([p[1] for p in pieces], axis=1)
    order = np.argsort(t, kind="stable")
    t, ys = t[order], ys[:, order]
    q, qd = ys[0], ys[1]
    uf = ys[2] if ys.shape[0] > 2 else np.zeros_like(t)
    T, V = motion.energies(q, qd)
    invariant = T + V - uf
    scale = max(float(T.max()), float(np.ptp(V)), float(np.abs(uf).max()), 1e-300)
    drift = float(np.max(np.abs(invariant - invariant[0]))) / scale
    return Run(t, q, qd, uf, tuple(met), stopped, method, rtol, atol, evaluations, drift, last)


_STOP = "q' = 0 (friction turns)"
SLOW = 1e-7  # a segment under friction ends at this fraction of its largest speed


def _stop_event(motion: OneDof, state: Sequence[float], peak: list[float]) -> Event:
    """Where a segment under friction stops: its speed falls to :data:`SLOW` of its largest.

    Not at q' = 0 itself: there kinetic friction's sense flips, and where static friction
    holds the body the right-hand side jumps back and forth across q' = 0, so an
    integrator's steps shrink toward it without end (a block on a spring that stops on
    the side it came from ran for minutes). The last bit, at the constant deceleration
    there, is added in closed form (:func:`_stopped`).
    """
    q0, qd0 = state[0], state[1]
    sense = math.copysign(1.0, qd0 if qd0 else motion.acceleration(q0, 0.0))

    def slowing(q: float, qd: float) -> float:  # at accepted steps (not trial stages)
        peak[0] = max(peak[0], abs(qd))
        return sense * qd - SLOW * peak[0]

    return Event(_STOP, slowing, -1, True)


def _stopped(motion: OneDof, t: float, y: np.ndarray) -> tuple[float, np.ndarray]:
    """The time and state where a body slowed to ``y`` at ``t`` comes to rest, at the
    deceleration a it has there: Δt = |q'|/|a|, Δq = q'²/(2a) (with the friction's work)."""
    q, qd = float(y[0]), float(y[1])
    qdd, power = motion.rates(q, qd)
    if qd == 0 or qdd == 0 or qd * qdd > 0:
        return t, np.array([q, 0.0, float(y[2])])
    dt = -qd / qdd
    return t + dt, np.array([q + 0.5 * qd * dt, 0.0, float(y[2]) + 0.5 * power * dt])


AT_REST = "at rest"  # static friction holds the body where it stopped
MAX_STOPS = 100_000  # stops of a body under friction in one run (each a new solve_ivp)


def _conditions(
    events: Sequence[Event], motion: OneDof, t0: float, state: Sequence[float], t_end: float
) -> list[Callable[[float, np.ndarray], float]]:
    """solve_ivp's event functions, each never an event at the start ``t0``: a condition
    that is 0 there takes the sign it has just after (a pendulum released from rest is
    not at a maximum of its swing)."""
    q0, qd0 = state[0], state[1]
    h = 1e-7 * t_end
    a0 = motion.acceleration(q0, qd0)
    ahead = (q0 + h * qd0 + 0.5 * h * h * a0, qd0 + h * a0)
    wrapped = []
    for event in events:
        start = value_at_start(event.function(q0, qd0), lambda f=event.function: f(*ahead))

        def condition(
            t: float, y: np.ndarray, f: Callable = event.function, at_start: float = start
        ) -> float:
            return at_start if t == t0 else f(float(y[0]), float(y[1]))

        condition.terminal = event.terminal  # type: ignore[attr-defined]
        condition.direction = event.direction  # type: ignore[attr-defined]
        wrapped.append(condition)
    return wrapped


def _turns(
    events: Sequence[Event],
    met: Sequence[tuple[str, float, float, float]],
    t: float,
    q: float,
    before: float,
) -> list[tuple[str, float, float, float]]:
    """The events of q' = 0 (a maximum, a minimum) at a stop under friction that solve_ivp
    may have left out beside the stop itself: each once."""
    crossing = -1 if before > 0 else 1  # q' falls to 0 from above: a maximum of q
    out = []
    for event in events:
        if event.direction not in (0, crossing) or event.function(q, 0.0) != 0:
            continue
        if any(
            name == event.name and abs(time - t) <= 1e-9 * max(1.0, t) for name, time, *_ in met
        ):
            continue
        out.append((event.name, t, q, 0.0))
    return out


def _at_rest(
    state: Sequence[float], t0: float, t_end: float, t_eval: np.ndarray | None
) -> tuple[np.ndarray, np.ndarray]:
    """The samples of a body held at rest from ``t0`` to the end."""
    times = np.array([t0, t_end]) if t_eval is None else t_eval[t_eval >= t0]
    if times.size == 0 or times[0] != t0:
        times = np.concatenate([[t0], times])
    rows = [np.full(times.shape, state[0]), np.zeros(times.shape)]
    if len(state) > 2:
        rows.append(np.full(times.shape, state[2]))
    return times, np.vstack(rows)
