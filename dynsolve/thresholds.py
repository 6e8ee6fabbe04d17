"""Thresholds: the value of a load that puts an assumption of the scene at its limit.

``tips(C, P)`` is the size of the load (or given) P at which the resultant normal force
on base C reaches an edge of the base (the body is about to tip); ``slips(C, P)`` the
size at which the friction at contact C reaches μs N (about to slip); ``slack(T, P)``
the size at which cord T's tension falls to zero; ``lifts(A, P)`` the size at which the
normal force at contact A falls to zero (about to lift off). The scene is solved with P
left as a letter, and the condition solved for P: the smallest positive root, then the
regime re-checked at that root (a body that slides before it could tip is followed
sliding to the load that tips it; one that tips before it slips has no slip load).

>>> THRESHOLDS
('tips', 'slips', 'slack', 'lifts')
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import Any

import sympy

from dynsolve.errors import Position, SpecError
from dynsolve.numbers import real_value, tidy
from dynsolve.principles.newton_euler import dot
from dynsolve.units import Dim, with_unit

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


@dataclass(frozen=True)
class Threshold:
    """A threshold's value (None: refused, ``checks`` say why), the regime it was solved
    in, the derivation's lines (name, formula, dimension; no name: the load's root) and
    the checks of the regime at the value found (name, passed, detail)."""

    value: sympy.Expr | None
    note: str = ""
    lines: tuple[tuple[str | None, sympy.Expr, Dim | None], ...] = ()
    checks: tuple[tuple[str, bool, str], ...] = ()


LENGTH, FORCE = Dim(1, 0, 0), Dim(1, 1, -2)


def threshold(problem: Any, target: sympy.Expr, options: Any) -> Threshold:
    """The smallest positive size of the load at which the condition of ``target`` holds,
    re-checked for the regime at that size: a body that slides before it could tip is
    followed sliding (F = μk N) to the load that tips it; one that tips before it slips
    has no slip load (refused, with the reason)."""
    function = type(target).__name__
    element_symbol, load = target.args
    limit = _Limit(problem, element_symbol.name, load, options)
    if function == "tips":
        return limit.tips()
    if function == "slips":
        return limit.slips()
    reactions = problem.formulation.reactions
    element = element_symbol.name
    force = reactions[element][0] if function == "slack" else reactions[f"N_{element}"][0]
    solved = limit.solve(problem.formulation, [force])
    found = limit.root([force], solved)
    what = f"{element}'s tension" if function == "slack" else f"N_{element}"
    if found is None:
        return limit.refused(f"no positive size of {load} brings {what} to zero")
    root, _ = found
    return Threshold(root, f"{what} = 0 solved for {load}", limit.root_line(force, solved, root))


def base_edges(scene: Any, support: Any) -> tuple[sympy.Expr, sympy.Expr]:
    """The edges of a base from its body's G line, along the base: where x_C may lie."""
    assert support.end is not None
    body = scene.bodies[support.body]
    along = support.tangent
    foot = dot((body.G[0] - support.point[0], body.G[1] - support.point[1]), along)
    length = dot((support.end[0] - support.point[0], support.end[1] - support.point[1]), along)
    return -foot, length - foot


class _Limit:
    """One threshold's solves: the scene with the load left a letter, in each regime."""

    def __init__(self, problem: Any, element: str, load: sympy.Symbol, options: Any) -> None:
        self.problem, self.element, self.load = problem, element, load
        self.knowns = {s: v for s, v in problem.system.knowns.items() if s != load}
        # the load stays a letter, so the solve is symbolic in any mode; numeric mode's
        # floats beside it only slow sympy down (crate_push_tips: 2.4x the exact solve)
        self.options = replace(options, show_formulas=False, mode="exact")
        # slack(T, P) names a cord: no support (its methods are never called)
        self.support = next((s for s in problem.scene.supports if s.name == element), None)

    def solve(self, formulation: Any, needed: list[sympy.Expr]) -> dict:
        """The unknowns ``needed`` depends on, solved with the load a letter."""
        from dynsolve.solver import solve_system
        from dynsolve.system import EquationSystem

        wanted = tuple(
            s
            for e in needed
            for s in (sympy.Integer(0) + e).free_symbols
            if s in formulation.unknowns
        )
        # solved in the givens' letters: the derivation shows the load's formula
        system = EquationSystem(
            formulation.equations, tuple(formulation.unknowns), {}, wanted=wanted
        )
        return dict(solve_system(system, self.options).values)

    def at(self, expr: sympy.Expr, solved: Mapping, size: sympy.Expr) -> float | None:
        """``expr`` of the solved scene at the load's size ``size``."""
        value = (sympy.Integer(0) + expr).xreplace(solved).xreplace(self.knowns)
        return real_value(value.xreplace({self.load: size}), {})

    def root(
        self, conditions: list[sympy.Expr], solved: Mapping
    ) -> tuple[sympy.Expr, sympy.Expr] | None:
        """The smallest positive load where one of ``conditions`` is 0, and that condition."""
        best: tuple[sympy.Expr, sympy.Expr] | None = None
        best_value = None
        for condition in conditions:
            expr = (sympy.Integer(0) + condition).xreplace(solved).xreplace(self.knowns)
            expr = expr if expr.has(sympy.Float) else tidy(expr)  # floats never cancel
            if expr.free_symbols - {self.load}:
                continue
            try:
                roots = sympy.solve(expr, self.load, simplify=False)
            except (NotImplementedError, ValueError):
                continue
            for root in roots:
                value = real_value(root, {})
                if value is not None and value > 0 and (best_value is None or value < best_value):
                    best, best_value = (root, condition), value
        return best

    def root_line(
        self, condition: sympy.Expr, solved: Mapping, root: sympy.Expr
    ) -> tuple[tuple[str | None, sympy.Expr, Dim | None], ...]:
        """The load's root in the givens' letters (its numbers where sympy cannot)."""
        letters = tidy(
            (sympy.Integer(0) + condition).xreplace(solved).xreplace({self.load: self.load})
        )
        value = real_value(root, {})
        try:
            roots = sympy.solve(letters, self.load)
        except (NotImplementedError, ValueError):
            roots = []
        for candidate in roots:
            number = real_value(candidate, self.knowns)
            if (
                number is not None
                and value is not None
                and abs(number - value) <= 1e-9 * abs(value)
            ):
                return ((None, tidy(candidate), None),)
        return ((None, root, None),)

    def shown(self, value: float, kind: str | Dim) -> str:
        """A value in base units with its unit in the problem's system, as a check states it."""
        return with_unit(value, kind, self.problem.spec.system)

    def load_size(self, value: float) -> str:
        """The load's size with its unit (its dimension as the spec's units gave it)."""
        dim = self.problem.dims.dims.get(self.load.name)
        return self.shown(value, dim) if dim is not None else f"{value:.4g}"

    def refused(self, reason: str) -> Threshold:
        return Threshold(None, checks=(("refused", False, reason),))

    def edges(self) -> list[sympy.Expr]:
        """x_C at either edge of the base, as conditions (zero there)."""
        x = sympy.Symbol(f"x_{self.element}", real=True)
        return [x - edge for edge in base_edges(self.problem.scene, self.support)]

    def sliding(self) -> bool:
        """Whether the scene as written states the contact sliding (``slides right``)."""
        state = self.problem.slipping.get(self.element)
        return state is None and self.support.friction_sense is not None

    def at_rest(self) -> Any:
        """The scene with the contact not slipping: as solved, or, where the given load
        made it slip (a re-solve), formulated again without that slide (the threshold
        may lie below the given load)."""
        if not self.problem.slipping.get(self.element):
            return self.problem.formulation
        slipping = {k: v for k, v in self.problem.slipping.items() if k != self.element}
        return self.slid(None, slipping)

    def slid(self, sense: int | None, slipping: Mapping[str, int] | None = None) -> Any:
        """The scene with the contact sliding, kinetic friction along ``sense`` (None:
        the contacts sliding as ``slipping`` says)."""
        from dynsolve.principles.newton_euler import formulate

        symbols = {g.name: g.symbol for g in self.problem.givens}
        if slipping is None:
            slipping = {**self.problem.slipping, self.element: sense}
        return formulate(self.problem.scene, symbols, slipping)

    def tips(self) -> Threshold:
        """tips(C, P): N at an edge of the base, in the regime the body is in at that load."""
        C, P = self.element, self.load
        x = sympy.Symbol(f"x_{C}", real=True)
        formulation = self.problem.formulation if self.sliding() else self.at_rest()
        friction = formulation.reactions.get(f"F_{C}")
        if self.sliding() or friction is None:
            solved = self.solve(formulation, [x])
            found = self.root(self.edges(), solved)
            if found is None:
                return self.refused(f"no positive size of {P} brings N_{C} to an edge of base {C}")
            root, condition = found
            how = "sliding (F = μk N, as the scene states)" if self.sliding() else "smooth"
            return Threshold(
                root,
                f"x_{C} at the edge of the base, solved for {P}; regime: {how}",
                (
                    (f"x_{C}", tidy(x.xreplace(solved)), LENGTH),
                    *self.root_line(condition, solved, root),
                ),
            )
        F, N = friction[0], formulation.reactions[f"N_{C}"][0]
        solved = self.solve(formulation, [x, F, N])
        found = self.root(self.edges(), solved)
        if found is None:
            return self.refused(f"no positive size of {P} brings N_{C} to an edge of base {C}")
        root, condition = found
        mu_s, mu_k = self.support.mu_s, self.support.mu_k
        F_tip, N_tip = self.at(F, solved, root), self.at(N, solved, root)
        size = real_value(root, {})
        lines = (
            (f"x_{C}", tidy(x.xreplace(solved)), LENGTH),
            *self.root_line(condition, solved, root),
        )
        if mu_s is None and mu_k is None:
            return Threshold(
                root,
                f"x_{C} at the edge of the base, solved for {P}, at rest; no mu_s given: "
                "whether it slides before it tips is NOT checked",
                lines,
            )
        mu = real_value(mu_s if mu_s is not None else mu_k, self.knowns)
        if F_tip is None or N_tip is None or mu is None or size is None:
            return self.refused(f"friction at {C} at the tipping load could not be evaluated")
        holds = abs(F_tip) <= mu * N_tip * (1 + 1e-9)
        bound = "μs N" if mu_s is not None else "μk N (≤ μs N)"
        detail = f"at {P} = {self.load_size(size)}: |F| = {self.shown(abs(F_tip), 'force')} " + (
            f"≤ {bound} = {self.shown(mu * N_tip, 'force')}"
            if holds
            else f"> {bound} = {self.shown(mu * N_tip, 'force')}"
        )
        if holds:
            return Threshold(
                root,
                f"x_{C} at the edge of the base, solved for {P}; regime: at rest (no slip at "
                f"{C}, checked at that load)",
                lines,
                (("no slip at the tipping load", True, detail),),
            )
        if mu_s is None:
            return self.refused(
                detail + ": with no mu_s given it may slide before it tips; give mu_s"
            )
        slip = self.root([F - mu_s * N, F + mu_s * N], solved)
        slip_size = real_value(slip[0], {}) if slip is not None else None
        if slip is None or slip_size is None:
            return self.refused(detail + ": it slides first, and its slip load was not found")
        first = f"{detail}: it slides first, at {P} = {self.load_size(slip_size)} (|F| = μs N)"
        if mu_k is None:
            return self.refused(first + "; give mu_k to follow it sliding to the load that tips it")
        sense = 1 if (self.at(F, solved, slip[0]) or 0) > 0 else -1
        return self._tips_sliding(sense, slip_size, first)

    def _tips_sliding(self, sense: int, slip_size: float, first: str) -> Threshold:
        """The load that tips the body while it slides (F = μk N against the slide)."""
        C, P = self.element, self.load
        x = sympy.Symbol(f"x_{C}", real=True)
        moving = self.slid(sense)
        kin = moving.kinematics.get(self.support.body)
        a_G = tuple(kin.a_G) if kin is not None else ()
        solved = self.solve(moving, [x, *a_G])
        found = self.root(self.edges(), solved)
        if found is None:
            return self.refused(first + f"; sliding, no size of {P} brings N_{C} to an edge")
        root, condition = found
        size = real_value(root, {})
        along = self.at(dot(a_G, self.support.tangent), solved, root) if len(a_G) == 2 else None
        if size is None or size < slip_size:
            return self.refused(
                first + f"; sliding, N_{C} is already past the edge as it starts to slide"
            )
        if along is None or along * sense > 0:
            return self.refused(first + "; the slide's sense at the tipping load is not borne out")
        return Threshold(
            root,
            f"x_{C} at the edge of the base while it slides (F = μk N), solved for {P}; "
            f"at rest it would tip at a larger push than the one that starts the slide",
            (
                (f"x_{C}", tidy(x.xreplace(solved)), LENGTH),
                *self.root_line(condition, solved, root),
            ),
            (
                ("slides before it tips", True, first),
                (
                    "sliding at the tipping load",
                    True,
                    f"at {P} = {self.load_size(size)} ≥ {self.load_size(slip_size)}: sliding, "
                    f"a_G along the base = {self.shown(abs(along), 'acceleration')} against "
                    "kinetic friction",
                ),
            ),
        )

    def slips(self) -> Threshold:
        """slips(C, P): |F| = μs N, with every base of the body checked at that load."""
        C, P = self.element, self.load
        formulation = self.at_rest()
        F, N = formulation.reactions[f"F_{C}"][0], formulation.reactions[f"N_{C}"][0]
        mu_s = self.support.mu_s
        assert mu_s is not None
        bases = [
            s
            for s in self.problem.scene.supports
            if s.kind == "base" and s.body == self.support.body and s.end is not None
        ]
        xs = [sympy.Symbol(f"x_{b.name}", real=True) for b in bases]
        solved = self.solve(formulation, [F, N, *xs])
        found = self.root([F - mu_s * N, F + mu_s * N], solved)
        if found is None:
            return self.refused(f"no positive size of {P} brings |F_{C}| to μs N")
        root, condition = found
        size = real_value(root, {})
        checks = []
        for base, x in zip(bases, xs, strict=True):
            edges = [self.at(e, {}, root) for e in base_edges(self.problem.scene, base)]
            place = self.at(x, solved, root)
            if place is None or None in edges:
                return self.refused(f"tipping on base {base.name} at the slip load not evaluated")
            lo, hi = min(edges), max(edges)  # type: ignore[type-var]
            inside = lo - 1e-9 * (hi - lo) <= place <= hi + 1e-9 * (hi - lo)
            detail = (
                f"at {P} = {self.load_size(size)}: N_{base.name} acts at x = "
                f"{self.shown(place, 'length')} from G's line, "
                + ("within" if inside else "outside")
                + f" [{lo:.4g}, {self.shown(hi, 'length')}]"
            )
            if not inside:
                return self.refused(detail + ": it tips before it slips")
            checks.append((f"no tipping on base {base.name} at the slip load", True, detail))
        return Threshold(
            root,
            f"|F_{C}| = μs N solved for {P}; regime: at rest up to that load",
            ((f"F_{C}", tidy(F.xreplace(solved)), FORCE), *self.root_line(condition, solved, root)),
            tuple(checks),
        )
