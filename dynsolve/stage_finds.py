"""Finds of a scene followed through stages: kinetic energy, work, energy lost, impulse, speed.

States are numbered from 1 (the scene as described); stage k runs from state k to k + 1.

- ``T(B, k)``: ½ m v_G² + ½ I_G ω² of body B at state k (``T(B)``: the last state;
  ``T(k)``: the whole scene at state k);
- ``work(F, k)``: the work U(k→k+1) of the force, spring or couple F in travel stage k
  (``W_B`` is B's weight, ``gravity`` every weight, ``F_C`` the friction at C);
  ``work(F)`` when one travel stage moves it;
- ``energy_lost(k)``: T_k − T_{k+1} of the bodies in impact stage k (``energy_lost``
  alone when there is one impact);
- ``impulse(B, k)``: m (v_{k+1} − v_k) of body B over impact stage k, a vector;
- ``speed(B, k)``: |v_G| of B at state k;
- ``V(B, k)``: the potential energy of B's weight (datum y = 0) and of the springs on B
  at state k (``V(k)``: the whole scene), V₁ less the work they did in the stages before.

>>> STAGE_FUNCTIONS
('T', 'work', 'energy_lost', 'impulse')
"""

from __future__ import annotations

import difflib
from collections.abc import Callable, Mapping
from typing import Any

import sympy

from dynsolve.errors import Position, SpecError
from dynsolve.model.momentum_events import Clutch, Reshape
from dynsolve.model.scene import Impact, Pivot, Scene, Travel
from dynsolve.model.stages import StageRecord, State
from dynsolve.modes.scene_mode import _body
from dynsolve.numbers import tidy
from dynsolve.principles.newton_euler import Formulation, dot
from dynsolve.units import Dim

STAGE_FUNCTIONS = ("T", "work", "energy_lost", "impulse")
ENERGY, MOMENTUM, SPEED = Dim(2, 1, -2), Dim(1, 1, -1), Dim(1, 0, -1)

# a find as (kind, dimension, signed expression or None, vector or None)
Found = tuple[str, Dim, sympy.Expr | None, tuple[sympy.Expr, sympy.Expr] | None]


def stage_quantity(
    function: str,
    args: tuple[str, ...],
    scene: Scene,
    formulation: Formulation,
    where: Position,
) -> Found:
    """The value of ``function(args)`` for a scene followed through its stages."""
    if not formulation.states:
        raise SpecError(
            f"{function}(…) needs a scene with stages",
            where,
            hint="add a 'travel' or 'impact' line: states are numbered from 1, the scene as "
            "described",
        )
    finder: Callable[..., Found] = _FINDERS[function]
    return finder(args, scene, formulation, where)


def _state(text: str, formulation: Formulation, where: Position) -> State:
    hint = "(1 is the scene as described)"
    return _numbered(text, formulation.states, "state", hint, where)


def _stage(text: str, formulation: Formulation, where: Position) -> StageRecord:
    hint = "in the order of the travel and impact lines"
    return _numbered(text, formulation.stages, "stage", hint, where)


def _numbered(text: str, items: tuple[Any, ...], what: str, how: str, where: Position) -> Any:
    """The item numbered ``text`` (from 1), or an error saying which numbers exist."""
    if not text.isdigit() or not 1 <= int(text) <= len(items):
        raise SpecError(
            f"there is no {what} '{text}'",
            where,
            hint=f"the {what}s are numbered 1 to {len(items)}, {how}",
        )
    return items[int(text) - 1]


def kinetic_energy(scene: Scene, state: State, bodies: tuple[str, ...]) -> sympy.Expr:
    """T = Σ ½ m v_G² + ½ I_G ω² of ``bodies`` at ``state``.

    >>> from dynsolve.model.scene import Body
    >>> m, zero = sympy.Integer(2), sympy.Integer(0)
    >>> ball = Body("ball", m, zero, (0, 0), (0, 0), "particle", (), {}, True, "", 0, 0)
    >>> kinetic_energy(Scene({"ball": ball}, {}, (), (), (), None, {}),
    ...                State(1, {"ball": (3, 4)}, {"ball": 0}), ("ball",))
    25
    """
    total = sympy.Integer(0)
    for name in bodies:
        body = scene.bodies[name]
        v, w = state.velocities[name], state.omegas.get(name, 0)
        I_G = state.inertias.get(name, body.I_G)  # a change of inertia in a stage before
        total += body.mass * dot(v, v) / 2 + I_G * w**2 / 2
    return tidy(total)


def _T(args: tuple[str, ...], scene: Scene, f: Formulation, where: Position) -> Found:
    if len(args) == 1 and args[0].isdigit():
        state, bodies = _state(args[0], f, where), tuple(scene.bodies)
    elif args:
        bodies = (_body(args[0], scene, where),)
        state = _state(args[1], f, where) if len(args) == 2 else f.states[-1]
    else:
        state, bodies = f.states[-1], tuple(scene.bodies)
    return "magnitude", ENERGY, kinetic_energy(scene, state, bodies), None


def _speed(args: tuple[str, ...], scene: Scene, f: Formulation, where: Position) -> Found:
    body = _body(args[0], scene, where)
    v = _state(args[1], f, where).velocities[body]
    return "magnitude", SPEED, tidy(sympy.sqrt(dot(v, v))), None


def _work(args: tuple[str, ...], scene: Scene, f: Formulation, where: Position) -> Found:
    if not args:
        raise SpecError("work needs a force: work(F) or work(F, k)", where, "e.g. work(W_ram, 1)")
    force = args[0]
    travels = [r for r in f.stages if isinstance(r.stage.event, Travel)]
    if len(args) == 2:
        travels = [_stage(args[1], f, where)]
        if not isinstance(travels[0].stage.event, Travel):
            raise SpecError(
                f"stage {args[1]} is an impact: work is done over a travel",
                where,
                hint="name a travel stage, or ask energy_lost(k) for an impact",
            )
    if force == "gravity":
        found = [sum((u for n, u in r.works.items() if n.startswith("W_")), sympy.Integer(0))
                 for r in travels]  # fmt: skip
    else:
        found = [r.works[force] for r in travels if force in r.works]
    if len(found) != 1:
        names = sorted({n for r in travels for n in r.works} | {"gravity"})
        close = difflib.get_close_matches(force, names, n=1)
        hint = f"did you mean '{close[0]}'?" if close else "forces with work: " + ", ".join(names)
        if len(found) > 1:
            hint = "several travel stages move it: write work(F, k) with the stage number k"
        raise SpecError(f"no single work of '{force}' in the stages", where, hint)
    return "signed", ENERGY, found[0], None


def _impact_stage(args: tuple[str, ...], f: Formulation, where: Position) -> StageRecord:
    impacts = [r for r in f.stages if isinstance(r.stage.event, Impact | Pivot | Clutch | Reshape)]
    if args:
        record = _stage(args[-1], f, where)
        if not isinstance(record.stage.event, Impact | Pivot | Clutch | Reshape):
            raise SpecError(
                f"stage {args[-1]} is not an impact",
                where,
                hint="name an impact stage: " + ", ".join(str(r.stage.number) for r in impacts),
            )
        return record
    if len(impacts) != 1:
        raise SpecError(
            "say which impact: the stage number",
            where,
            hint="e.g. energy_lost(2) for the impact of stage 2",
        )
    return impacts[0]


def _energy_lost(args: tuple[str, ...], scene: Scene, f: Formulation, where: Position) -> Found:
    record = _impact_stage(args, f, where)
    k = record.stage.number
    before = kinetic_energy(scene, f.states[k - 1], record.bodies)
    after = kinetic_energy(scene, f.states[k], record.bodies)
    return "signed", ENERGY, tidy(before - after), None


def _impulse(args: tuple[str, ...], scene: Scene, f: Formulation, where: Position) -> Found:
    if not args or args[0].isdigit():
        raise SpecError(
            "impulse needs the body: impulse(B) or impulse(B, k)",
            where,
            hint="the impulse on B over its impact, m (v₂ − v₁)",
        )
    body = _body(args[0], scene, where)
    record = _impact_stage(args[1:], f, where) if len(args) == 2 else None
    if record is None:
        mine = [
            r for r in f.stages if isinstance(r.stage.event, Impact | Pivot) and body in r.bodies
        ]
        if len(mine) != 1:
            raise SpecError(
                f"{body} takes part in {len(mine)} impacts",
                where,
                hint="write impulse(B, k) with the impact's stage number k",
            )
        record = mine[0]
    if body not in record.bodies:
        raise SpecError(f"{body} takes no part in stage {record.stage.number}", where)
    k, m = record.stage.number, scene.bodies[body].mass
    v1, v2 = f.states[k - 1].velocities[body], f.states[k].velocities[body]
    return "vector", MOMENTUM, None, (tidy(m * (v2[0] - v1[0])), tidy(m * (v2[1] - v1[1])))


def potential_energy(scene: Scene, bodies: tuple[str, ...], g: sympy.Expr) -> sympy.Expr:
    """V = Σ W y_G (gravity, datum y = 0, the scene's origin) + Σ ½ k s² (the springs on
    ``bodies``) in the scene as described (state 1).

    >>> from dynsolve.model.scene import Body, Spring
    >>> m, zero = sympy.Integer(2), sympy.Integer(0)
    >>> ball = Body("ball", m, zero, (0, 3), (0, 3), "particle", (), {}, True, "", 0, 0)
    >>> spring = Spring("k1", "ball", (0, 3), "", (0, 0), sympy.Integer(100), sympy.Integer(2))
    >>> potential_energy(Scene({"ball": ball}, {}, (), (), (), (0, -1), {}, springs=(spring,)),
    ...                  ("ball",), sympy.Integer(10))  # 2·10·3 + ½·100·1²
    110
    """
    total = sympy.Integer(0)
    if scene.gravity is not None:
        for name in bodies:
            body = scene.bodies[name]
            total -= body.mass * g * dot(scene.gravity, body.G)
    for spring in scene.springs:
        if spring.body in bodies or spring.other in bodies:
            dx = spring.point[0] - spring.other_point[0]
            dy = spring.point[1] - spring.other_point[1]
            s = sympy.sqrt(dx**2 + dy**2) - spring.unstretched
            total += spring.k * s**2 / 2
    return tidy(total)


def _V(args: tuple[str, ...], scene: Scene, f: Formulation, where: Position) -> Found:
    """V(B, k) = V(B, 1) − Σ (work of B's weight and springs in the stages before k)."""
    if len(args) == 1 and args[0].isdigit():
        k, bodies = int(_state(args[0], f, where).number), tuple(scene.bodies)
    elif args:
        bodies = (_body(args[0], scene, where),)
        k = _state(args[1], f, where).number if len(args) == 2 else len(f.states)
    else:
        k, bodies = len(f.states), tuple(scene.bodies)
    g = next((s for s in scene.values if s.name == "g"), sympy.Symbol("g", positive=True))
    V = potential_energy(scene, bodies, g)
    conservative = {f"W_{b}" for b in bodies} | {
        s.name for s in scene.springs if s.body in bodies or s.other in bodies
    }
    for record in f.stages[: k - 1]:
        V -= sum((u for n, u in record.works.items() if n in conservative), sympy.Integer(0))
    return "signed", ENERGY, tidy(V), None


_FINDERS: Mapping[str, Callable[..., Found]] = {
    "T": _T,
    "work": _work,
    "energy_lost": _energy_lost,
    "impulse": _impulse,
    "speed": _speed,
    "V": _V,
}
