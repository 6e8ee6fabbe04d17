"""Thresholds: the value of a load that puts an assumption of the scene at its limit.

``tips(C, P)`` is the size of the load (or given) P at which the resultant normal force
on base C reaches an edge of the base (the body is about to tip); ``slips(C, P)`` the
size at which the friction at contact C reaches μs N (about to slip); ``slack(T, P)``
the size at which cord T's tension falls to zero; ``lifts(A, P)`` the size at which the
normal force at contact A falls to zero (about to lift off). The scene is solved with P
left as a letter, and the condition solved for P: the smallest positive root.

>>> THRESHOLDS
('tips', 'slips', 'slack', 'lifts')
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from typing import Any

import sympy

from dynsolve.errors import Position, SpecError
from dynsolve.numbers import real_value, tidy
from dynsolve.principles.newton_euler import dot

THRESHOLDS = ("tips", "slips", "slack", "lifts")

_WHAT = {
    "tips": "a base C (tips(C, P): the size of P at which the body on base C is about to tip)",
    "slips": "a rough contact C with mu_s (slips(C, P): the size of P at which it is about to "
    "slip)",
    "slack": "a cord T (slack(T, P): the size of P at which its tension falls to zero)",
    "lifts": "a contact A (lifts(A, P): the size of P at which its normal force falls to zero)",
}


def threshold_target(
    function: str,
    args: tuple[str, ...],
    scene: Any,
    formulation: Any,
    symbols: Mapping[str, sympy.Symbol],
    where: Position,
) -> sympy.Expr:
    """The target's expression ``function(element, load)``, after checking both names."""
    if len(args) != 2:
        raise SpecError(f"{function} takes two names", where, hint="e.g. " + _WHAT[function])
    element, load = args
    supports = {s.name: s for s in scene.supports}
    shared = [s.name for s in scene.supports if s.at == element]
    if element not in supports and len(shared) == 1:  # G for the one renamed G_A
        element = shared[0]
    ok = {
        "tips": element in supports and supports[element].kind == "base",
        "slips": element in supports
        and supports[element].mu_s is not None
        and f"F_{element}" in formulation.reactions,
        "slack": any(c.name == element for c in scene.cords),
        "lifts": element in supports and f"N_{element}" in formulation.reactions,
    }[function]
    if not ok:
        raise SpecError(
            f"'{element}' is not what {function} needs", where, hint="name " + _WHAT[function]
        )
    if load not in symbols or symbols[load] in formulation.unknowns:
        raise SpecError(
            f"'{load}' is not a given or load of the scene",
            where,
            hint="name the force (or given) whose size sets the threshold, e.g. P",
        )
    return sympy.Function(function)(sympy.Symbol(element), symbols[load])


def threshold(problem: Any, target: sympy.Expr, options: Any) -> sympy.Expr | None:
    """The smallest positive size of the load at which the condition of ``target`` holds
    (None when there is none)."""
    from dynsolve.solver import solve_system
    from dynsolve.system import EquationSystem

    function = type(target).__name__
    element_symbol, load = target.args
    element = element_symbol.name
    formulation, scene = problem.formulation, problem.scene
    knowns = {s: v for s, v in problem.system.knowns.items() if s != load}
    reactions = formulation.reactions
    support = next((s for s in scene.supports if s.name == element), None)
    if function == "tips":
        assert support is not None and support.end is not None
        x = sympy.Symbol(f"x_{element}", real=True)
        body = scene.bodies[support.body]
        along = support.tangent
        foot = dot((body.G[0] - support.point[0], body.G[1] - support.point[1]), along)
        length = dot((support.end[0] - support.point[0], support.end[1] - support.point[1]), along)
        conditions = [x + foot, x - (length - foot)]  # x at either edge
        needed = [x]
    elif function == "slips":
        F, N = reactions[f"F_{element}"][0], reactions[f"N_{element}"][0]
        assert support is not None and support.mu_s is not None
        conditions = [F - support.mu_s * N, F + support.mu_s * N]
        needed = [F, N]
    elif function == "slack":
        conditions = [reactions[element][0]]
        needed = conditions
    else:
        conditions = [reactions[f"N_{element}"][0]]
        needed = conditions
    wanted = tuple(
        s for e in needed for s in (sympy.Integer(0) + e).free_symbols if s in formulation.unknowns
    )
    system = EquationSystem(
        formulation.equations, tuple(formulation.unknowns), knowns, wanted=wanted
    )
    # the load stays a letter, so the solve is symbolic in any mode; numeric mode's floats
    # beside it only slow sympy down (crate_push_tips: 2.4x the exact solve)
    quiet = replace(options, show_formulas=False, mode="exact")
    solved = solve_system(system, quiet).values
    best: sympy.Expr | None = None
    best_value = None
    for condition in conditions:
        expr = (sympy.Integer(0) + condition).xreplace(solved).xreplace(knowns)
        expr = expr if expr.has(sympy.Float) else tidy(expr)  # floats never cancel exactly
        if expr.free_symbols - {load}:
            continue
        try:
            roots = sympy.solve(expr, load, simplify=False)
        except (NotImplementedError, ValueError):
            continue
        for root in roots:
            value = real_value(root, {})
            if value is not None and value > 0 and (best_value is None or value < best_value):
                best, best_value = root, value
    return best
