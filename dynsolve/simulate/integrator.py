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
    """Integrate from (q0, q'0) at t = 0 until ``t_end`` or a terminal event."""
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

    # the start is never an event: a condition that is 0 there takes the sign it has
    # just after (a pendulum released from rest is not at a maximum of its swing)
    h = 1e-7 * t_end
    a0 = motion.acceleration(q0, qd0)
    ahead = (q0 + h * qd0 + 0.5 * h * h * a0, qd0 + h * a0)
    wrapped = []
    for event in events:
        start = value_at_start(event.function(q0, qd0), lambda f=event.function: f(*ahead))

        def condition(
            t: float, y: np.ndarray, f: Callable = event.function, at_start: float = start
        ) -> float:
            return at_start if t == 0 else f(float(y[0]), float(y[1]))

        condition.terminal = event.terminal  # type: ignore[attr-defined]
        condition.direction = event.direction  # type: ignore[attr-defined]
        wrapped.append(condition)
    solution = solve_ivp(
        rhs,
        (0.0, t_end),
        [q0, qd0] if fast is not None else [q0, qd0, 0.0],
        method=method,
        rtol=rtol,
        atol=atol,
        events=wrapped or None,
        max_step=max_step,
        t_eval=t_eval,
        dense_output=False,
        **({"jac": jac} if jac is not None else {}),
    )
    if solution.status == -1:
        raise ValueError(f"the integration failed: {solution.message}")
    met: list[tuple[str, float, float, float]] = []
    stopped = ""
    last = None
    for event, times, states in zip(
        events, solution.t_events or [], solution.y_events or [], strict=False
    ):
        for t, y in zip(times, states, strict=True):
            met.append((event.name, float(t), float(y[0]), float(y[1])))
            if event.terminal and solution.status == 1:
                stopped = event.name
                last = (float(t), float(y[0]), float(y[1]), float(y[2]) if len(y) > 2 else 0.0)
    met.sort(key=lambda item: item[1])
    t, q, qd = solution.t, solution.y[0], solution.y[1]
    uf = solution.y[2] if len(solution.y) > 2 else np.zeros_like(t)
    T, V = motion.energies(q, qd)
    invariant = T + V - uf
    scale = max(float(T.max()), float(np.ptp(V)), float(np.abs(uf).max()), 1e-300)
    drift = float(np.max(np.abs(invariant - invariant[0]))) / scale
    return Run(
        t, q, qd, uf, tuple(met), stopped, method, rtol, atol, int(solution.nfev), drift, last
    )
