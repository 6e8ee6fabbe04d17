"""Work and energy of a particle between two states: T1 + ΣU(1→2) = T2.

State 1 is the scene as described (velocity from a ``velocity`` line, else rest);
state 2 puts the particle's G where a ``travel`` line says. The work of the weight,
of springs (from their stretch in both states) and of constant applied forces is
summed; smooth contacts and guides do no work and are named as such.

>>> import sympy
>>> from dynsolve.model.scene import Scene, Body
>>> m, g, h = sympy.symbols("m g h", positive=True)
>>> ball = Body("ball", m, sympy.Integer(0), (0, h), (0, h), "particle", (), {}, True, "", 0, 0)
>>> scene = Scene({"ball": ball}, {}, (), (), (), (0, -1), {}, travels={"ball": (0, 0)})
>>> equation, speed, _ = energy_equation(scene, "ball", {"g": g})
>>> sympy.solve(equation.lhs - equation.rhs, speed)
[-sqrt(2)*sqrt(g)*sqrt(h), sqrt(2)*sqrt(g)*sqrt(h)]
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy

from dynsolve.model.scene import Scene, Vec
from dynsolve.numbers import tidy
from dynsolve.system import Equation


def _dot(a: Vec, b: Vec) -> sympy.Expr:
    return a[0] * b[0] + a[1] * b[1]


def _length(a: Vec, b: Vec) -> sympy.Expr:
    return tidy(sympy.sqrt((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2))


def energy_equation(
    scene: Scene, body_name: str, symbols: Mapping[str, sympy.Expr]
) -> tuple[Equation, sympy.Symbol, tuple[str, ...]]:
    """T1 + ΣU = T2 for one travelling particle; its speed in state 2; forces doing no work."""
    body = scene.bodies[body_name]
    G1, G2 = body.G, scene.travels[body_name]
    shift = (G2[0] - G1[0], G2[1] - G1[1])
    m = body.mass
    v1 = scene.velocities.get(body_name, (sympy.Integer(0), sympy.Integer(0)))
    T1 = m * _dot(v1, v1) / 2
    speed = sympy.Symbol(f"v2_{body_name}", real=True)
    work: list[sympy.Expr] = []
    notes: list[str] = []
    if scene.gravity is not None:
        work.append(m * symbols["g"] * _dot(scene.gravity, shift))
        notes.append("U_W = W·Δr")
    for spring in scene.springs:
        if body_name not in (spring.body, spring.other):
            continue
        if spring.body == body_name and spring.other:
            raise ValueError(f"spring {spring.name} joins two bodies: not supported between states")
        end = spring.other_point
        s1 = _length(G1, end) - spring.unstretched
        s2 = _length(G2, end) - spring.unstretched
        work.append(-spring.k * (s2**2 - s1**2) / 2)
        notes.append(f"U_{spring.name} = −½k(s2² − s1²)")
    for load in scene.loads:
        if load.body == body_name and load.kind == "force":
            magnitude = symbols.get(load.name)
            if magnitude is None:
                raise ValueError(f"the work of the unknown force {load.name} is not known")
            work.append(magnitude * _dot(load.direction, shift))
            notes.append(f"U_{load.name} = F·Δr")
    idle = []
    for support in scene.supports:
        if support.body != body_name:
            continue
        if not support.smooth:
            raise ValueError(f"friction at {support.name} does work: not supported between states")
        idle.append(f"N_{support.name}")
    T2 = m * speed**2 / 2
    note = "T1 + ΣU(1→2) = T2 (" + "; ".join(notes) + ")"
    if idle:
        note += f"; no work: {', '.join(idle)} (normal to the motion)"
    equation = Equation(T1 + sympy.Add(*work), T2, "energy", 0, note)
    return equation, speed, tuple(idle)
