"""The end of an interval fixed by an event: a round body slides until it rolls.

``travel B: for t_1, until rolls`` describes a body whose contact point slips at state 1
(a bowling ball thrown with backspin, a disk set down spinning): kinetic friction
μk N opposes the slip, the forces stay constant, and the interval ends when the contact
point comes to rest, v_G + ω × r_P/G = 0 along the surface. That condition fixes the
unknown time t_1; the friction's sense is that of the slip at state 1, which holds
through the interval exactly when t_1 > 0 (the slip velocity changes linearly in time).

>>> import sympy
>>> from dynsolve.model.scene import Body, Support, WORDS
>>> m, r = sympy.symbols("m r", positive=True)
>>> disk = Body("disk", m, m * r**2 / 2, (0, r), (0, r), "disk", (r,), {}, False, "", 0, 0)
>>> C = Support("contact", "C", "disk", (0, 0), WORDS["up"], mu_k=sympy.Rational(1, 5))
>>> contact_slip(disk, C, (5, 0), 10)   # v_P = v_G + ω r = 5 + 10 r, along +x
10*r + 5
"""

from __future__ import annotations

import sympy

from dynsolve.model.scene import Body, Scene, Support, Travel, Vec
from dynsolve.numbers import real_value, tidy
from dynsolve.principles.newton_euler import dot


def contact_slip(body: Body, support: Support, v_G: Vec, omega: sympy.Expr) -> sympy.Expr:
    """The velocity of the body's point at the contact along the contact's tangent."""
    r = (support.point[0] - body.G[0], support.point[1] - body.G[1])
    v_P = (v_G[0] - omega * r[1], v_G[1] + omega * r[0])
    return tidy(dot(v_P, support.tangent))


def sliding_contact(scene: Scene, travel: Travel) -> Support:
    """The one rough contact of the travelling body that slides until it rolls."""
    rough = [
        s for s in scene.supports if s.body == travel.body and s.kind == "contact" and not s.smooth
    ]
    if len(rough) != 1 or rough[0].mu_k is None:
        raise UntilError(
            travel,
            f"'until rolls' needs {travel.body} on one rough contact with mu_k "
            f"(found {len(rough)} rough contacts)",
        )
    return rough[0]


def friction_sense(scene: Scene, travel: Travel, support: Support) -> int:
    """±1 along the tangent: kinetic friction opposes the slip of the contact point at
    state 1 (or the stated ``slides`` when the slip's sign depends on symbolic givens)."""
    body = scene.bodies[travel.body]
    zero = sympy.Integer(0)
    v_G = scene.velocities.get(travel.body, (zero, zero))
    slip = contact_slip(body, support, v_G, scene.omegas.get(travel.body, zero))
    value = real_value(slip, scene.values)
    if value is None:
        if support.friction_sense is not None:
            return support.friction_sense
        raise UntilError(
            travel,
            f"the sense of the slip at {support.name} depends on symbolic givens; state it "
            f"on the contact ('slides right')",
        )
    if value == 0:
        raise UntilError(
            travel,
            f"{travel.body} already rolls at state 1 (its contact point {support.name} does not "
            "slip): there is no slide to end",
        )
    return -1 if value > 0 else 1


class UntilError(ValueError):
    """An until event that cannot be followed, with the line of its travel."""

    def __init__(self, travel: Travel, message: str) -> None:
        super().__init__(message)
        self.line, self.column = travel.line, travel.column
