"""Which travels of a solved scene the simulation cross-check integrates; notes for the rest.

Light on purpose: numpy and scipy (:mod:`dynsolve.simulate.crosscheck`) are imported only
when a travel is to be integrated, so a scene at an instant, with symbolic givens, or with
only ``until``/``for`` travels costs no import of them.

>>> sorted(SIMULATED_KINDS)
['by', 'to', 'turns']
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

import sympy

from dynsolve.model.scene import Scene, Travel
from dynsolve.results import Check

if TYPE_CHECKING:
    from dynsolve.modes.scene_mode import SceneProblem

SIMULATED_KINDS = frozenset(("to", "by", "turns"))  # the travels with an end to integrate to


@dataclass(frozen=True)
class Leg:
    """One travel to simulate: the moving part of the scene, from the travel's start state
    (its ``velocities``/``omegas``), and what the principle found at its end."""

    label: str
    scene: Scene
    travel: Travel
    speeds: Mapping[str, sympy.Expr]  # |v_G| at the end, per body
    spins: Mapping[str, sympy.Expr]  # ω at the end (ccw positive), per body
    turn: sympy.Expr | None = None  # an until event's angle turned round its circle


def simulation_checks(
    problem: SceneProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Check, ...]:
    """A check per travel of a solved scene problem (a note where it cannot be simulated)."""
    formulation, scene = problem.formulation, problem.scene
    substitution = {**problem.system.knowns, **values}
    symbols, system = problem.symbols, problem.spec.system
    legs: list[Leg] = []
    notes: list[Check] = []
    if formulation.stages:
        for record in formulation.stages:
            event = record.stage.event
            if not isinstance(event, Travel):
                continue
            label = f"stage {record.stage.number}"
            if record.scene is None:
                notes.append(Check.not_run(f"simulation: {label}", "not simulated: " + _why(event)))
                continue
            end = formulation.states[record.stage.number]
            legs.append(
                Leg(
                    label,
                    record.scene,
                    event,
                    {n: sympy.sqrt(v[0] ** 2 + v[1] ** 2) for n, v in end.velocities.items()},
                    dict(end.omegas),
                    formulation.turns.get(event.body) if event.kind == "until" else None,
                )
            )
    elif len(scene.travels) == 1:
        (travel,) = scene.travels.values()
        if travel.kind == "for":
            notes.append(Check.not_run("simulation", "not simulated: " + _why(travel)))
        else:
            turn = formulation.turns.get(travel.body)
            legs.append(Leg("", scene, travel, formulation.speeds, formulation.spins, turn))
    symbolic = sorted(g.name for g in problem.givens if g.value is None and g.given is not None)
    if symbolic:  # nothing to integrate: said once per travel, without building anything
        why = f"not simulated: symbolic givens ({', '.join(symbolic)}) have no values"
        return tuple(notes) + tuple(
            Check.not_run(f"simulation: {leg.label}" if leg.label else "simulation", why)
            for leg in legs
        )
    return tuple(notes) + tuple(_checked(leg, symbols, substitution, system) for leg in legs)


def _why(travel: Travel) -> str:
    if travel.kind == "for":
        return (
            "an interval of constant forces (impulse and momentum) is not integrated; "
            "work and energy checks it instead"
        )
    return "the moving part of the scene was not recorded"


def _checked(
    leg: Leg,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    system: str,
) -> Check:
    """The leg integrated and compared, or the note why not (without importing scipy)."""
    name = f"simulation: {leg.label}" if leg.label else "simulation"
    if leg.travel.kind == "until" and leg.turn is not None:  # a particle on a circle
        from dynsolve.simulate.circle import circle_check

        answers = (leg.turn, leg.speeds[leg.travel.body])
        return circle_check(name, leg.scene, leg.travel, answers, symbols, values, system)
    if leg.travel.kind not in SIMULATED_KINDS:
        return Check.not_run(name, f"not simulated: a travel '{leg.travel.kind}' is not simulated")
    from dynsolve.simulate.crosscheck import simulate_leg

    return simulate_leg(leg, symbols, values, system)
