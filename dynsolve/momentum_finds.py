"""Momentum finds of a scene: H(B[, P][, k]), angular momentum, and p(B[, k]), linear momentum.

``H(B)`` is I_G ω about B's mass centre, ``H(B, P)`` is I_G ω + r_G/P × m v_G about the
point P (ccw positive, kg·m²/s or slug·ft²/s), ``p(B)`` is m v_G; at the instant of a scene
without stages, else at the last state, or at state k (``H(B, P, k)``, ``H(B, k)``,
``p(B, k)``).

>>> MOMENTUM_FUNCTIONS
('H', 'p')
"""

from __future__ import annotations

import sympy

from dynsolve.errors import Position, SpecError
from dynsolve.model.scene import Scene, Travel, Vec
from dynsolve.principles.angular_momentum import (
    ANGULAR_MOMENTUM,
    LINEAR_MOMENTUM,
    angular_momentum,
    linear_momentum,
    turning,
)
from dynsolve.principles.newton_euler import Formulation
from dynsolve.units import Dim

MOMENTUM_FUNCTIONS = ("H", "p")


def motion_at(
    body: str, state: str | None, scene: Scene, formulation: Formulation, where: Position
) -> tuple[Vec, sympy.Expr, sympy.Expr, str]:
    """B's v_G, ω and I_G at state ``state`` (its number), the last state of a chain of
    stages, or the instant of a scene without stages; with the words for where that is."""
    states = formulation.states
    if state is not None:
        if not states or not state.isdigit() or not 1 <= int(state) <= len(states):
            raise SpecError(
                f"there is no state '{state}'",
                where,
                hint=f"the states are numbered 1 to {len(states)}, 1 the scene as described"
                if states
                else "a scene without stages has one state: leave the number out",
            )
        chosen, when = states[int(state) - 1], f"at state {state}"
    elif states:
        chosen, when = states[-1], "at the last state"
    if states:
        I_G = chosen.inertias.get(body, scene.bodies[body].I_G)  # after a change of inertia
        return chosen.velocities[body], chosen.omegas.get(body, 0), I_G, when
    v = scene.velocities.get(body, (sympy.Integer(0), sympy.Integer(0)))
    kinematics = formulation.kinematics.get(body)
    omega = kinematics.omega if kinematics is not None else scene.omegas.get(body, 0)
    pin = kinematics.pin if kinematics is not None else None
    if pin is not None and body not in scene.velocities:  # G turns about the pin
        G = scene.bodies[body].G
        v = turning(omega, (G[0] - pin.point[0], G[1] - pin.point[1]))
    return v, omega, scene.bodies[body].I_G, "at the instant"


def momentum_quantity(
    function: str,
    body: str,
    point: tuple[str, Vec] | None,
    state: str | None,
    scene: Scene,
    formulation: Formulation,
    where: Position,
) -> tuple[str, sympy.Expr | None, Vec | None, str]:
    """``H`` (about ``point``, or G when None) or ``p`` of ``body``: (kind, expression,
    vector, what it is in words)."""
    model = scene.bodies[body]
    v, omega, I_G, when = motion_at(body, state, scene, formulation, where)
    if function == "p":
        return "vector", None, linear_momentum(model.mass, v), f"p = m v_G of {body} {when}"
    name, P = point if point is not None else ("G", model.G)
    k = int(state) if state is not None else len(formulation.states)
    if point is not None and any(
        isinstance(r.stage.event, Travel) for r in formulation.stages[: max(k - 1, 0)]
    ):
        raise SpecError(
            f"H({body}, {name}) at state {k} needs where {body} is there, which is not "
            "followed after a travel",
            where,
            hint=f"ask H({body}) about its mass centre, or at a state before the travel",
        )
    H = angular_momentum(model.mass, I_G, v, sympy.Integer(0) + omega, model.G, P)
    how = "I_G ω" if point is None else f"I_G ω + r_G/{name} × m v_G"
    if model.particle:
        how = f"r_G/{name} × m v" if point is not None else "0 (a particle)"
    return "rotation", H, None, f"H_{name} = {how} of {body} {when}, ccw positive"


def momentum_dimension(function: str) -> Dim:
    """The dimension of ``H`` or ``p``."""
    return ANGULAR_MOMENTUM if function == "H" else LINEAR_MOMENTUM
