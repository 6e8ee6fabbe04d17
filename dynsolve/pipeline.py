"""The one-way flow for a spec file: parse → build → solve → check → a :class:`Solution`.

>>> import pathlib, tempfile
>>> path = pathlib.Path(tempfile.mkdtemp()) / "w.dyn"
>>> text = "given:\\n  m = 2 kg\\nequations:\\n  W = m*g\\nfind: W\\nanswers:\\n  W = 19.6 N\\n"
>>> _ = path.write_text(text)
>>> solution = solve_file(path)
>>> solution.answers[0].shown, solution.passed
('19.6 N', True)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import replace
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

import sympy
from sympy.core.function import AppliedUndef

from dynsolve.answer_key import compare, compare_magnitude, sense_word
from dynsolve.budget import step
from dynsolve.dimensions import DimensionReport
from dynsolve.errors import DynsolveError, Position, SpecError
from dynsolve.format import NOT_FINITE, latex_number, latex_unit, pretty_unit, sig
from dynsolve.format import quantity as format_quantity
from dynsolve.magnitude import OutOfRange
from dynsolve.modes.equation_mode import GivenInfo, Target, build_problem, check_find_names
from dynsolve.names import latex_name, pretty
from dynsolve.numbers import abs_resolved, real_value, tidy, tidying_lightly
from dynsolve.quantities import convert
from dynsolve.results import (
    AnswerRow,
    Assumption,
    Check,
    EnergyTerm,
    EquationRow,
    Formula,
    FreeBody,
    GivenRow,
    KeyComparison,
    LimitRemark,
    Remark,
    Solution,
    Step,
    Trial,
)
from dynsolve.shown import formula_latex, formula_text, presentable
from dynsolve.solver import solve_system
from dynsolve.solver.outcome import Outcome
from dynsolve.solver.roots import truth
from dynsolve.spec.ast import Spec
from dynsolve.spec.parser import parse_file, parse_spec
from dynsolve.suspicious import suspicious_notes
from dynsolve.system import EquationSystem, SolveOptions
from dynsolve.units import BASE_UNITS, Dim, natural_unit

if TYPE_CHECKING:
    from dynsolve.modes.scene_mode import SceneProblem
    from dynsolve.rigid3d.problem import Problem3D

RESIDUAL_LIMIT = 1e-9
NAMED_UNKNOWNS = 12  # the structure check names this many unknowns


class SolvableProblem(Protocol):
    """What the pipeline needs of a problem, whichever front end built it
    (:class:`~dynsolve.modes.equation_mode.Problem`, ``SceneProblem``, ``KinematicsProblem``)."""

    spec: Spec
    givens: tuple[GivenInfo, ...]
    system: EquationSystem
    dims: DimensionReport
    targets: tuple[Target, ...]
    symbols: Mapping[str, sympy.Symbol]
    rows: tuple[EquationRow, ...]
    steps: tuple[Step, ...]
    notes: tuple[tuple[str, str], ...]
    mode: str


def solve_file(path: str | Path, options: SolveOptions | None = None) -> Solution:
    """Parse, solve and check one ``.dyn`` file (equation mode, or scene mode with a scene)."""
    with step("parsing the spec"):
        spec = parse_file(path)
    return solve_spec(spec, options)


def solve_text(text: str, name: str = "<spec>", options: SolveOptions | None = None) -> Solution:
    """Parse, solve and check a spec's text (from stdin or a string); ``name`` in positions.

    >>> solve_text("given:\\n  m = 2 kg\\nequations:\\n  W = m*g\\nfind: W\\n").answers[0].shown
    '19.6 N'
    """
    with step("parsing the spec"):
        spec = parse_spec(text, name)
    return solve_spec(spec, options)


def solve_spec(spec: Spec, options: SolveOptions | None = None) -> Solution:
    """Solve and check a parsed spec: kinematics, scene or equation mode, by its sections.

    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("given:\\n  m = 2 kg\\nequations:\\n  W = m*g\\nfind: W\\n")
    >>> solve_spec(spec).answers[0].shown
    '19.6 N'
    """
    if options is not None and options.mode == "auto":
        from dynsolve.precision import solve_auto

        return solve_auto(spec, options, solve_spec)
    from dynsolve.numbers import light_tidying

    try:
        with (
            step("building the equations"),
            light_tidying(options is not None and options.mode == "numeric"),
        ):
            if spec.kinematics or spec.scene:
                check_find_names(spec)
            if spec.kinematics:
                options = options or SolveOptions()
                return solve_problem(_kinematics_problem(spec, options), options)
            if spec.scene:
                return solve_scene(spec, options or SolveOptions())
            return solve_problem(build_problem(spec), options or SolveOptions())
    except OutOfRange as error:  # raised where the file is not known
        columns = {s.line: s.column for s in (*spec.equations, *spec.kinematics)}
        raise error.located(spec.file, columns) from None


def _kinematics_problem(spec: Spec, options: SolveOptions) -> SolvableProblem:
    """One-line kinematics: in numeric mode with the numbers put in first, and, should
    that fail (a relation sympy inverts with letters but not with numbers), as in exact mode."""
    from dynsolve.errors import SpecError
    from dynsolve.modes.kinematics_mode import build_kinematics_problem

    if options.mode == "numeric":
        try:
            return build_kinematics_problem(spec, numbers_first=True)
        except SpecError:
            pass
    return build_kinematics_problem(spec)


def _simulation_checks(
    problem: SceneProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Check, ...]:
    """The simulation cross-checks of a scene's travels (:mod:`dynsolve.simulate.legs`)."""
    if not (problem.scene.travels or problem.formulation.stages):
        return ()
    from dynsolve.simulate.legs import simulation_checks

    return simulation_checks(problem, values)


def solve_scene(spec: Spec, options: SolveOptions) -> Solution:
    """Solve a scene: assume no slip, check, and re-solve with kinetic friction if it fails."""
    from dynsolve.linkage.model import is_linkage
    from dynsolve.rigid3d.model import is_3d

    if is_3d(spec):
        from dynsolve.rigid3d.problem import build_3d_problem, moment_check
        from dynsolve.rigid3d.problem import second_moment_rows as moment_rows_3d

        problem3d = build_3d_problem(spec)
        solved = solve_system(problem3d.system, options)
        checks = moment_check(problem3d, solved.values)
        solution = solve_problem(problem3d, options, solved, second_methods=checks)
        return replace(
            solution,
            energy=_energy_terms_3d(problem3d, solved, options),
            second_moments=moment_rows_3d(problem3d),
        )
    if is_linkage(spec):
        from dynsolve.linkage.problem import build_linkage_problem, figure, reversed_teeth
        from dynsolve.linkage.problem import cross_checks as linkage_checks

        linkage = build_linkage_problem(spec)
        solved = solve_system(linkage.system, options)
        flipped = reversed_teeth(linkage, solved.values)
        if flipped:  # a tooth force came out the other way: its radial push is |F| tan φ
            linkage = build_linkage_problem(spec, flipped)
            solved = solve_system(linkage.system, options)
        checks = linkage_checks(linkage, solved.values)
        solution = solve_problem(linkage, options, solved, second_methods=checks)
        return replace(solution, linkage=figure(linkage))
    from dynsolve.modes.scene_mode import (
        assess,
        build_scene_problem,
        cross_checks,
        free_bodies,
        second_moment_rows,
    )

    problem = build_scene_problem(spec)
    outcome = solve_system(problem.system, options)
    assumptions, slips = _assessed(assess, problem, outcome.values)
    trial: Mapping[sympy.Symbol, sympy.Expr] = {}
    trial_targets = problem.targets  # trial(X) reads X as the first trial defined it
    failed: tuple[Assumption, ...] = ()
    trials: list[tuple[SolvableProblem, Outcome, tuple[Assumption, ...]]] = []
    slipping: dict[str, int] = {}
    released: dict[str, str] = {}  # cords found slack, contacts found lost
    for _ in range(RESOLVES):  # a slide contradicted, then a stick that slips the other way
        releases = _releases(assumptions)
        if (not slips or slips.items() <= slipping.items()) and not releases:
            break
        trial = trial or outcome.values
        rejected = tuple(a for a in assumptions if _resolved(a))
        trials.append((problem, outcome, rejected))
        failed += rejected
        slipping |= slips
        released |= releases
        problem = build_scene_problem(spec, slipping, released)
        problem = replace(
            problem,
            targets=tuple(
                old if old.trial else new
                for old, new in zip(trial_targets, problem.targets, strict=True)
            ),
        )
        outcome = solve_system(problem.system, options)
        assumptions, slips = _assessed(assess, problem, outcome.values)
    assumptions = failed + assumptions
    solution = solve_problem(
        problem,
        options,
        outcome,
        trial,
        assumptions,
        free_bodies(problem, outcome.values),
        cross_checks(problem, outcome.values)
        + (_simulation_checks(problem, outcome.values) if options.simulate else ()),
    )
    unchecked = _unchecked_starts(problem, outcome.values)
    if unchecked:
        solution = replace(solution, warnings=solution.warnings + unchecked)
    shown = tuple(
        replace(
            _trial(*each, outcome, options),
            second_moments=second_moment_rows(each[0]),  # type: ignore[arg-type]
        )
        for each in trials
    )
    energy = _energy_terms(problem, outcome, options)
    from dynsolve.modes.scene_sketch import sketch_of

    return replace(
        solution,
        trials=shown,
        energy=energy,
        second_moments=second_moment_rows(problem),
        sketch=sketch_of(problem.scene),
    )


ENERGY = Dim(2, 1, -2)
_ENERGY_MEANINGS = {"T1": "kinetic energy in state 1", "T2": "kinetic energy in state 2"}


def _energy_terms(
    problem: SceneProblem, outcome: Outcome, options: SolveOptions
) -> tuple[EnergyTerm, ...]:
    """A scene's work–energy equation term by term, as the textbook writes it: T1, each
    U(1→2) with its value, T2 (with the solved speed put in)."""
    terms = problem.formulation.energy_terms
    if not terms:
        return ()
    energy_unit = natural_unit(ENERGY, problem.spec.system)
    speed_unit = natural_unit(SPEED, problem.spec.system)
    works = [expr for label, expr in terms if label.startswith("U")]
    if len(works) > 1:  # the textbook's U(1→2) = U_S + U_M = −5 + 9.375 = 4.375, before T2
        total = ("U_12 = ΣU(1→2), the work of all the forces", sympy.Add(*works))
        last = max(i for i, (label, _) in enumerate(terms) if label.startswith("U"))
        terms = (*terms[: last + 1], total, *terms[last + 1 :])
    speeds = _kinematic_relations(problem)
    if speeds:  # the notes' "kinematic relation: v_O = r ω = 0.4 ω", just before T2
        terms = (*terms[:-1], *speeds, terms[-1])
    rows = tuple(
        (label, expr, _energy_row_unit(label, speed_unit, energy_unit, problem.spec.system))
        for label, expr in terms
    )
    values = {**problem.system.knowns, **outcome.values}
    return energy_rows(_View(problem, outcome, {}, options), rows, values)


def _energy_row_unit(label: str, speed: str, energy: str, system: str) -> str:
    """The unit of a work–energy table row: a speed (v_G), an angular velocity (ω₂) or an
    energy."""
    if label.startswith("v_G"):
        return speed
    if label.startswith("omega_2"):
        return natural_unit(Dim(0, 0, -1), system)
    return energy


def _energy_terms_3d(
    problem: Problem3D, outcome: Outcome, options: SolveOptions
) -> tuple[EnergyTerm, ...]:
    """A 3D scene's T1 + ΣU1-2 = T2 term by term (:func:`dynsolve.rigid3d.energy.energy_table`),
    printed as the planar work–energy table is; none for a scene at an instant."""
    if problem.energy is None:
        return ()
    from dynsolve.rigid3d.energy import energy_table

    values = {**problem.system.knowns, **outcome.values}
    rows, defined = energy_table(problem.scene, problem.energy, values, problem.spec.system)
    view = _View(problem, outcome, {}, options)
    return energy_rows(view, rows, {**values, **defined})


def energy_rows(
    view: _View,
    rows: tuple[tuple[str, sympy.Expr, str], ...],
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> tuple[EnergyTerm, ...]:
    """Each (``"name = meaning"``, formula, unit) as a row of the work–energy table: its
    formula in the givens' symbols (none for a number) and its value with ``values`` put
    in (none while a symbol is left, as in a symbolic problem)."""
    terms = []
    for label, expr, unit in rows:
        name, _, meaning = label.partition(" = ")
        meaning = meaning or _ENERGY_MEANINGS.get(name, "")
        number = real_value(expr, values)
        shown = format_quantity(number, unit) if number is not None else ""
        symbolic = bool((sympy.Integer(0) + expr).free_symbols)
        terms.append(
            EnergyTerm(
                name,
                meaning,
                view.text(expr) if symbolic else "",
                view.latex(expr) if symbolic else "",
                shown,
                f"{latex_number(number)}\\,{latex_unit(unit)}" if number is not None else "",
            )
        )
    return tuple(terms)


SPEED = Dim(1, 0, -1)


def _kinematic_relations(problem: SceneProblem) -> tuple[tuple[str, sympy.Expr], ...]:
    """The speed of each body's G in state 2 where the travel's kinematics gives it from
    another unknown (a wheel's v_G = r ω, a platform's v_G = l ω_AB), as (label, v_G)."""
    speeds = problem.formulation.speeds
    found = []
    for body, speed in speeds.items():
        speed = sympy.Integer(0) + speed
        if speed.is_Symbol or not speed.free_symbols & set(problem.system.unknowns):
            continue
        name = "v_G" if len(speeds) == 1 else f"v_G_{body}"
        found.append((f"{name} = speed of G of {body} in state 2 (kinematic relation)", speed))
    spins = problem.formulation.spins
    for body, spin in spins.items():  # a disk rolling: ω₂ = v₂/r, before T2 uses it
        spin = sympy.Integer(0) + spin
        if spin.is_Symbol or not spin.free_symbols & set(problem.system.unknowns):
            continue
        name = "omega_2" if len(spins) == 1 else f"omega_2_{body}"
        found.append((f"{name} = ω of {body} in state 2, ccw + (kinematic relation)", spin))
    return tuple(found)


def _trial(
    problem: SolvableProblem,
    outcome: Outcome,
    rejected: tuple[Assumption, ...],
    final: Outcome,
    options: SolveOptions,
) -> Trial:
    """A rejected trial as the derivation shows it, with a remark for each unknown whose
    sign the re-solve reversed (α turning the other way once the wheel slips)."""
    view = _View(problem, outcome, {}, options)
    steps = tuple(view.step(i, b) for i, b in enumerate(outcome.blocks, start=1))
    after = {symbol.name: value for symbol, value in final.values.items()}
    remarks = []
    for symbol, value in outcome.values.items():
        before_value, after_value = real_value(value), real_value(after.get(symbol.name, 0))
        if before_value and after_value and (before_value > 0) != (after_value > 0):
            before_text = view.shown(symbol.name, value)[0]
            after_text = view.shown(symbol.name, after[symbol.name])[0]
            remarks.append(
                f"{pretty(symbol.name)} changes sign: {before_text} in the trial, "
                f"{after_text} after the re-solve"
            )
    return Trial(
        " and ".join(a.name for a in rejected),
        view.equation_rows(),
        steps,
        "; ".join(a.detail for a in rejected),
        tuple(remarks),
    )


def _undefined_equations(system: EquationSystem) -> tuple[Check, ...]:
    """A failed check for each equation the model wrote with an undefined term (nan, ±∞:
    a division by zero in building it), which no solve can make hold.

    >>> import sympy
    >>> from dynsolve.system import Equation
    >>> x = sympy.Symbol("x")
    >>> bad = EquationSystem((Equation(sympy.nan, sympy.Integer(0), "eq. 3"),), (x,))
    >>> [c.detail for c in _undefined_equations(bad)]
    ['eq. 3 reads nan = 0: a term was divided by zero in writing it; no answer can be trusted']
    """
    undefined = (sympy.nan, sympy.zoo, sympy.oo, -sympy.oo)
    return tuple(
        Check(
            "defined",
            False,
            f"{e.label} reads {e.lhs} = {e.rhs}: a term was divided by zero in writing it; "
            "no answer can be trusted",
        )
        for e in system.equations
        if any(e.lhs.has(u) or e.rhs.has(u) for u in undefined)
    )


def _unchecked_starts(
    problem: SceneProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[str, ...]:
    """Stages that start from rest on a contact with no mu_s: that static friction cannot
    hold the body is assumed, NOT checked (a warning, never a pass)."""
    from dynsolve.principles.stage_chain import from_rest

    substitution = {**problem.system.knowns, **values}
    return tuple(
        w
        for record in problem.formulation.stages
        for w in from_rest(record, substitution, problem.spec.system)[1]
    )


def _assessed(
    assess: Callable[..., Any], problem: SceneProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> Any:
    """Scene mode's assumption checks; velocities given that contradict the scene (found
    when state 1 is written for them) are a spec error at the first velocity line."""
    from dynsolve.principles.newton_euler import VelocityConflict

    try:
        return assess(problem, values)
    except VelocityConflict as conflict:
        spec = problem.spec
        line = next((s.line for s in spec.scene if s.kind in ("velocity", "omega")), 1)
        raise SpecError(
            str(conflict), Position(spec.file, line, 1), hint="check the velocity and omega lines"
        ) from None


def solve_problem(
    problem: SolvableProblem,
    options: SolveOptions,
    outcome: Outcome | None = None,
    trial: Mapping[sympy.Symbol, sympy.Expr] | None = None,
    assumptions: tuple[Assumption, ...] = (),
    free_body: tuple[FreeBody, ...] = (),
    second_methods: tuple[Check, ...] = (),
) -> Solution:
    """Solve a built problem (unless ``outcome`` is given) and assemble what renderers show;
    ``second_methods`` are checks of the answers by another principle."""
    with step("solving the equations"):
        outcome = outcome or solve_system(problem.system, options)
    view = _View(problem, outcome, trial or {}, options)
    with step("simplifying the answers and comparing them with the key"):
        answers = tuple(view.answer(t) for t in problem.targets)
        key = tuple(view.key(answers))
    notes = tuple(Check(name, True, detail) for name, detail in problem.notes)
    overflowed = tuple(
        Check("finite", False, f"{a.name} is {NOT_FINITE} (overflow or division by zero)")
        for a in answers
        if a.shown == NOT_FINITE
    )
    checks = (
        view.checks()
        + overflowed
        + _valueless(problem, view, answers)
        + _undefined_equations(problem.system)
        + notes
        + second_methods
        + _assumption_checks(assumptions)
        + tuple(view.limit_checks)
        + tuple(
            Check(f"answer {k.name}", k.passed, f"expected {k.expected}; {k.detail}") for k in key
        )
    )
    spec = problem.spec
    return Solution(
        file=spec.file,
        title=spec.title,
        source=spec.source,
        system=spec.system,
        mode=problem.mode,
        free_body=free_body,
        assumptions=assumptions,
        givens=tuple(view.given_row(g) for g in problem.givens if view.used(g)),
        equations=view.equation_rows(),
        steps=_with_definitions(
            problem.steps or tuple(view.step(i, b) for i, b in enumerate(outcome.blocks, start=1)),
            view,
        ),
        answers=answers,
        checks=checks,
        key=key,
        status=outcome.status,
        messages=outcome.messages,
        warnings=tuple(f"{name}: {detail}" for name, detail in suspicious_notes(problem.spec)),
        remarks=_remarks(problem, outcome, options, answers, bool(assumptions))
        + _limit_remarks(problem, outcome, options, view),
    )


MASS = Dim(0, 1, 0)


def _valueless(
    problem: SolvableProblem, view: _View, answers: tuple[AnswerRow, ...]
) -> tuple[Check, ...]:
    """A failed check for each answer that should be a number and is not: every letter
    left in it has a value (or it calls a quantity left unevaluated), yet it has none. A
    formula in symbolic givens, or in the motion's t (x(t)), is an answer as it is."""
    from dynsolve.modes.kinematics_mode import VARIABLES

    letters = {g.symbol for g in problem.givens if g.value is None}
    letters |= {symbol for symbol, _ in VARIABLES.values()}
    failed = []
    for target, answer in zip(problem.targets, answers, strict=True):
        if answer.value is not None or answer.shown == NOT_FINITE:
            continue
        value = view.computed(target.name)
        if value is None:
            why = "it was not determined"
        else:
            left = (sympy.Integer(0) + value).xreplace(view.knowns)
            calls = sorted(str(c) for c in left.atoms(AppliedUndef))
            if not calls and left.free_symbols and left.free_symbols <= letters:
                continue
            why = f"{', '.join(calls)} has no value" if calls else "it was not evaluated"
        failed.append(
            Check(f"value of {answer.name}", False, f"{answer.name} = {answer.shown}: {why}")
        )
    return tuple(failed)


def _remarks(
    problem: SolvableProblem,
    outcome: Outcome,
    options: SolveOptions,
    rows: tuple[AnswerRow, ...],
    assumed: bool = False,
) -> tuple[Remark, ...]:
    """Remarks on the answers (a mass that cancels), from the formulas of an exact solve:
    a formula in the givens without the mass is its proof, unless the solve ``assumed`` a
    case (no slip, a cord taut, no tipping) that the mass may decide: then each remark is
    confirmed by solving again with the mass changed (:func:`_confirmed`)."""
    from dynsolve.remarks import cancelled_masses

    if options.mode != "exact" or outcome.status != "solved":
        return ()
    formulas = _derived_formulas(outcome)
    derived = {g.symbol: g.formula for g in problem.givens if g.formula is not None}
    used = set().union(
        *(e.lhs.free_symbols | e.rhs.free_symbols for e in problem.system.equations),
        *(f.free_symbols for f in derived.values()),
    )
    masses = {
        g.symbol: g.name
        for g in problem.givens
        if g.dim == MASS and g.given is not None and g.symbol in used
    }
    if not masses:
        return ()
    answers = {}
    for target in problem.targets:
        if target.trial or target.is_given or target.kind in ("steepest", "threshold"):
            continue  # a limit's expr names its contact, not its formula: never "cancels"
        if target.vector is not None:
            answers[target.name] = target.vector[0] ** 2 + target.vector[1] ** 2
        elif target.expr is not None:
            answers[target.name] = target.expr
    givens = {g.symbol for g in problem.givens if g.given is not None} - set(masses)
    uses = _uses(problem.system, outcome)
    uses.update({s: frozenset((sympy.Integer(0) + f).free_symbols) for s, f in derived.items()})
    remarks = cancelled_masses(
        answers, {**formulas, **derived}, masses, givens, frozenset(problem.system.unknowns), uses
    )
    return _confirmed(problem.spec, remarks, rows) if remarks and assumed else remarks


def _uses(system: EquationSystem, outcome: Outcome) -> dict[sympy.Symbol, frozenset[sympy.Symbol]]:
    """Each solved unknown: the symbols of the equations of the block it was solved in."""
    uses: dict[sympy.Symbol, frozenset[sympy.Symbol]] = {}
    for block in outcome.blocks:
        held = frozenset().union(
            *(
                system.equations[i].lhs.free_symbols | system.equations[i].rhs.free_symbols
                for i in block.equations
            )
        )
        uses.update(dict.fromkeys(block.unknowns, held))
    return uses


MASS_FACTORS = (0.5, 2.0)  # a cancelled mass is confirmed by re-solves at these multiples


def _confirmed(
    spec: Spec, remarks: tuple[Remark, ...], rows: tuple[AnswerRow, ...]
) -> tuple[Remark, ...]:
    """The remarks the problem solved again bears out: each answer keeps its value (to 1e-6)
    with each remarked mass halved and doubled in turn. A formula read under an assumption
    (no slip, a cord taut) holds only while it does: a crate pushed too weakly to slide
    feels F = P whatever its mass, until a lighter one slides, and then F = μk m g. A
    symbolic problem has no numbers to solve again with: its formula in letters is the
    proof, and no assumption of it was decided."""
    if any(g.quantity is None for g in spec.givens):
        return remarks
    values = {row.name: row.value for row in rows}
    again: dict[tuple[str, float], dict[str, float | None] | None] = {}
    kept: dict[tuple[str, ...], list[str]] = {}  # the masses confirmed: the answers
    for remark in remarks:
        for answer in remark.answers:
            masses = []
            for mass in remark.masses:
                for factor in MASS_FACTORS:  # the next factor only while the answer holds
                    if (mass, factor) not in again:
                        again[(mass, factor)] = _answers_with(spec, mass, factor)
                    if not _same(values.get(answer), again[(mass, factor)], answer):
                        break
                else:
                    masses.append(mass)
            if masses:
                kept.setdefault(tuple(masses), []).append(answer)
    return tuple(Remark(tuple(answers), masses) for masses, answers in kept.items())


def _same(value: float | None, again: dict[str, float | None] | None, answer: str) -> bool:
    """True when a re-solve gave ``answer`` the value ``value`` (relative 1e-6)."""
    other = again.get(answer) if again is not None else None
    if value is None or other is None:
        return False
    return math.isclose(value, other, rel_tol=1e-6, abs_tol=1e-12)


def _answers_with(spec: Spec, given: str, factor: float) -> dict[str, float | None] | None:
    """The answers' values (display units) of the problem solved again in numeric mode
    with ``given`` multiplied by ``factor``, or None where it cannot be solved."""
    from dynsolve.grade.substitute import with_variant

    quantity = next(g.quantity for g in spec.givens if g.name == given)
    assert quantity is not None
    unit = quantity.unit.text if quantity.unit is not None else ""
    try:
        changed = with_variant(spec, {given: f"{float(quantity.text) * factor!r} {unit}"}, "mass")
        solution = solve_spec(changed, SolveOptions("numeric", show_formulas=False, simulate=False))
    except (DynsolveError, ValueError, OverflowError):
        return None
    if solution.status != "solved":
        return None
    return {row.name: row.value for row in solution.answers}


def _derived_formulas(outcome: Outcome) -> dict[sympy.Symbol, sympy.Expr]:
    """Each unknown's formula from the blocks solved symbolically (a block solved in
    floating point has lost its letters: its unknowns are left out)."""
    formulas: dict[sympy.Symbol, sympy.Expr] = {}
    for block in outcome.blocks:
        if block.method != "numeric":
            formulas.update(block.formulas)
    return formulas


def _limit_remarks(
    problem: SolvableProblem, outcome: Outcome, options: SolveOptions, view: _View
) -> tuple[LimitRemark, ...]:
    """Limit cases of the answers' formulas (from rest, smooth) that free them from other
    givens, from the formulas of an exact solve. Each is confirmed by solving the problem
    again with that given at 0 (numeric mode): a limit outside the formula's own case (a
    cord that no longer goes slack when the bob starts at rest) fails there and is not
    remarked."""
    from dynsolve.remarks import limit_cases, starting_speeds

    if options.mode != "exact" or outcome.status != "solved":
        return ()
    formulas = _derived_formulas(outcome)
    formulas.update({g.symbol: g.formula for g in problem.givens if g.formula is not None})
    starts = starting_speeds(problem.spec)
    givens = {
        g.symbol: (g.name, _limit_case(g, starts))
        for g in problem.givens
        if g.formula is None and (g.given is not None or g.name == "g")
    }
    targets = {
        t.name: t
        for t in problem.targets
        if not t.trial and not t.is_given and t.vector is None and t.expr is not None
    }
    cases = limit_cases({n: t.expr for n, t in targets.items()}, formulas, givens)
    confirmed: dict[str, Solution | None] = {}
    rows = []
    for case in cases:
        if case.given not in confirmed:
            confirmed[case.given] = _at_zero(problem.spec, case.given)
        again = confirmed[case.given]
        row = next((a for a in again.answers if a.name == case.answer), None) if again else None
        limit = abs_resolved(case.limit, view.knowns)
        if sympy.count_ops(limit) > LIMIT_OPS:
            continue  # a limit too long to tell the reader anything at a glance
        number = real_value(limit, view.knowns)
        if row is None or row.value is None or number is None:
            continue
        _, _, expected = view.shown(case.answer, sympy.Float(abs(number), 17))
        if expected is None or not math.isclose(
            abs(row.value), expected, rel_tol=1e-6, abs_tol=1e-12
        ):
            continue  # the re-solve does not bear the formula out: no remark
        if number < 0 and targets[case.answer].kind != "signed":
            limit = -limit  # a magnitude with its direction, as the answers table shows it
        value_latex = view.shown(case.answer, sympy.Float(abs(number), 17))[1]
        rows.append(
            LimitRemark(
                case.answer, case.given, case.case, view.text(limit), view.latex(limit),
                row.shown, value_latex, case.whatever, row.direction,
            )
        )  # fmt: skip
    return tuple(rows)


LIMIT_OPS = 24  # a limit case's formula longer than this is not remarked


def _at_zero(spec: Spec, given: str) -> Solution | None:
    """The problem solved again (numeric mode) with ``given`` nearly 0 (1e-7 of its value:
    the limit from above, a block nudged off the top of a dome rather than balanced there),
    or None where it cannot be or a check other than an answer's finiteness fails."""
    from dynsolve.grade.substitute import with_variant

    quantity = next(g.quantity for g in spec.givens if g.name == given)
    assert quantity is not None
    unit = quantity.unit.text if quantity.unit is not None else ""
    try:
        small = f"{float(quantity.text) * 1e-7!r} {unit}".strip()
        solution = solve_spec(with_variant(spec, {given: small}, "limit"), SolveOptions("numeric"))
    except (DynsolveError, ValueError, OverflowError):
        return None
    checks = [c for c in solution.checks if c.name != "finite"]
    if solution.status != "solved" or any(c.failed for c in checks):
        return None
    return solution


def _limit_case(given: GivenInfo, starts: frozenset[str]) -> str:
    """The limit case a given's going to 0 stands for: a starting speed (one of
    ``starts``), "nearly from rest"; a friction coefficient, "nearly smooth"; else ""."""
    if given.value is None or not given.value.is_nonzero:
        return ""
    if given.dim == Dim.of("velocity") and given.name in starts:
        return "nearly from rest"
    if given.dim == Dim() and given.name.split("_")[0] in ("mu", "μ"):
        return "nearly smooth"
    return ""


def _orthonormal(
    x: sympy.Expr,
    y: sympy.Expr,
    unknowns: list[sympy.Symbol],
    knowns: Mapping[sympy.Symbol, sympy.Expr],
) -> bool:
    """True when (x, y) = Σ u e_u with the unknowns u along perpendicular unit vectors e_u
    (numbers once the givens are put in), so |(x, y)|² = Σ u²."""
    if not (x.is_polynomial(*unknowns) and y.is_polynomial(*unknowns)):
        return False
    columns = []
    for u in unknowns:
        cx, cy = real_value(x.diff(u).xreplace(knowns)), real_value(y.diff(u).xreplace(knowns))
        if cx is None or cy is None:
            return False
        columns.append((cx, cy))
    zero = {u: sympy.Integer(0) for u in unknowns}
    rests = [real_value((sympy.Integer(0) + c.xreplace(zero)).xreplace(knowns)) for c in (x, y)]
    if rests != [0.0, 0.0]:
        return False
    return all(
        abs(a[0] * b[0] + a[1] * b[1] - (1.0 if i == j else 0.0)) < 1e-12
        for i, a in enumerate(columns)
        for j, b in enumerate(columns)
    )


def _with_definitions(steps: tuple[Step, ...], view: _View) -> tuple[Step, ...]:
    """The solve steps, then one step per answer read from the solved unknowns by a formula
    (ω = v_G/r, O = √(O_n² + O_t²), a_max = v² a/b²), so that no answer appears without
    its derivation."""
    extra = []
    for target in view.problem.targets:
        if target.parts:
            results, note = view.composite_lines(target), "one line per part: I_G + m d²"
            heading = f"{pretty(target.name)} of the parts (composite body)"
            method = "table + parallel axis"
        elif target.kind == "steepest":
            results = view.steepest_formulas(target) if not target.trial else ()
            contact = target.expr.name if target.expr is not None else ""
            if view.happens.get(contact) == "tips":
                note = (
                    f"at the steepest slope N_{contact} reaches the edge of the base: it tips "
                    "(before friction reaches μs N)"
                )
                heading = f"{pretty(target.name)}, the steepest slope: beyond it the body tips"
            else:
                note = "at the steepest slope friction reaches its limit: |F| = μs N"
                heading = f"{pretty(target.name)}, the steepest slope: beyond it the body slips"
            method = "limit"
        elif target.kind == "threshold":
            results = view.threshold_formulas(target)
            found = view.found.get(target.name)
            note = found.note if found is not None else ""
            heading, method = f"{pretty(target.name)}, the threshold", "limit"
        else:
            result = view.definition(target)
            results = (*view.stated(target), result) if result is not None else ()
            note = target.note
            heading, method = f"{pretty(target.name)} from the values found", "substituted"
        if results:
            index = len(steps) + len(extra) + 1
            extra.append(Step(index, (), (target.name,), method, results, (), note, heading))
    return steps + tuple(extra)


RESOLVES = 3  # re-solves of a scene whose friction assumption failed


def _resolved(assumption: Assumption) -> bool:
    """A failed friction trial (no slip, or a stated slide) that was re-solved the other way,
    or a cord found slack or a contact found lost, re-solved without it."""
    return (
        not assumption.holds
        and assumption.name.startswith(
            ("no slip", "sliding", "cord ", "contact at ", "elastic cord ", "sense of ")
        )
        and "re-solved" in assumption.detail
    )


def _releases(assumptions: tuple[Assumption, ...]) -> dict[str, str]:
    """The one-sided elements a trial found pulling or pushing the wrong way: a cord with
    a negative tension (slack) and a contact with a negative normal force (lost).

    >>> _releases((Assumption("cord T taut", False, "T = -3 < 0: …; re-solved without it"),))
    {'T': 'cord'}
    """
    found: dict[str, str] = {}
    for a in assumptions:
        if a.holds or "re-solved" not in a.detail:
            continue
        if a.name.startswith("cord ") and a.name.endswith(" taut"):
            found[a.name[len("cord ") : -len(" taut")]] = "cord"
        elif a.name.startswith("contact at ") and a.name.endswith(" kept"):
            found[a.name[len("contact at ") : -len(" kept")]] = "contact"
    return found


def _assumption_checks(assumptions: tuple[Assumption, ...]) -> tuple[Check, ...]:
    """Final assumptions as checks, agreeing with the assumptions table: one that could not
    be decided did not run; one that failed and was re-solved the other way (a friction
    trial, a cord found slack) passes as rejected, saying the answers are the re-solve's.

    >>> rejected = Assumption("no slip at G", False, "|F| > μs N; re-solved with F = μk N")
    >>> [(c.name, c.status) for c in _assumption_checks((rejected,))]
    [('assumption: no slip at G rejected', 'passed')]
    """
    checks = []
    for a in assumptions:
        name = f"assumption: {a.name}"
        if not a.decided:
            checks.append(Check.not_run(name, a.detail))
        elif _resolved(a):
            detail = f"the answers are for the re-solved case: {a.detail}"
            checks.append(Check(f"{name} rejected", True, detail))
        else:
            checks.append(Check(name, a.holds, a.detail))
    return tuple(checks)


_ANGLE_UNITS = frozenset({"deg", "degree", "degrees", "°", "rad", "radian", "radians"})
_TRIG = (sympy.sin, sympy.cos, sympy.tan, sympy.cot, sympy.sec, sympy.csc)


def _in_trig(formula: sympy.Expr, renamed: Mapping[sympy.Symbol, sympy.Symbol]) -> sympy.Expr:
    """``formula`` with the symbols of ``renamed`` renamed inside the arguments of its
    sines and cosines only.

    >>> t, M, d = sympy.symbols("t M d")
    >>> _in_trig(M * t + sympy.cos(t), {t: d})
    M*t + cos(d)
    """
    if not renamed:
        return formula
    return formula.replace(
        lambda e: isinstance(e, _TRIG), lambda e: e.func(e.args[0].xreplace(renamed))
    )


def _plain(number: float, wrap: bool = True) -> str:
    """A number as a hand calculation writes it: 4 significant digits, no trailing zeros,
    a negative one in parentheses (``wrap``).

    >>> _plain(0.5400), _plain(-2.0), _plain(45.0000001, wrap=False)
    ('0.54', '(-2)', '45')
    """
    text = sig(number, 4)
    if "." in text and "e" not in text:
        text = text.rstrip("0").rstrip(".")
    return f"({text})" if wrap and text.startswith("-") else text


def _angle_arguments(expr: sympy.Expr) -> set[sympy.Symbol]:
    """The symbols that are a term of a sine's or cosine's argument, alone or times a
    rational (``θ``, ``θ/2``, ``θ + φ``): angles, whatever their names.

    >>> t, n = sympy.symbols("t n")
    >>> sorted(s.name for s in _angle_arguments(sympy.cos(t / 2) + sympy.sin(n * sympy.pi)))
    ['t']
    """
    found: set[sympy.Symbol] = set()
    for call in expr.atoms(*_TRIG):
        for term in sympy.Add.make_args(call.args[0]):
            coefficient, rest = term.as_coeff_Mul()
            if isinstance(rest, sympy.Symbol) and coefficient.is_Rational:
                found.add(rest)
    return found


class _View:
    """Formats one solved problem; holds the lookups shared by the row builders."""

    def __init__(
        self,
        problem: SolvableProblem,
        outcome: Outcome,
        trial: Mapping[sympy.Symbol, sympy.Expr],
        options: SolveOptions,
    ) -> None:
        self.problem = problem
        self.outcome = outcome
        self.trial = trial
        self.options = options
        self.thresholds: dict[str, sympy.Expr | None] = {}  # steepest(C), computed once
        self.happens: dict[str, str] = {}  # steepest(C): "slips" or "tips" beyond it
        self.found: dict[str, Any] = {}  # each threshold's regime, derivation and checks
        self.limit_checks: list[Check] = []  # the checks at each threshold's own value
        self.limits: dict[str, object] = {}  # steepest(C)'s F(φ), N(φ): value and derivation
        self.system = problem.spec.system
        self.knowns = problem.system.knowns
        self.units = {t.name: t.unit for t in problem.targets}
        self.dims = problem.dims.dims
        self.pretty_symbols = {s: sympy.Symbol(pretty(n)) for n, s in problem.symbols.items()}
        self.latex_symbols = {s: latex_name(n) for n, s in problem.symbols.items()}
        self._prints: dict[tuple[str, sympy.Expr], str] = {}
        self._substituted: dict[sympy.Expr, tuple[str, str] | None] = {}

    # ---- helpers
    def used(self, given: GivenInfo) -> bool:
        return (
            given.given is not None
            or given.shown
            or given.symbol in self.equation_symbols
            or given.symbol in self.formula_symbols
        )

    @cached_property
    def formula_symbols(self) -> frozenset[sympy.Symbol]:
        """Every symbol a derived quantity's formula is written with (ρ in a_n = v²/ρ)."""
        formulas = [g.formula for g in self.problem.givens if g.formula is not None]
        return frozenset().union(*((sympy.Integer(0) + f).free_symbols for f in formulas))

    @cached_property
    def equation_symbols(self) -> frozenset[sympy.Symbol]:
        """Every symbol the equations hold (gathered once: per given it is n²)."""
        equations = self.problem.system.equations
        return frozenset().union(*(e.lhs.free_symbols | e.rhs.free_symbols for e in equations))

    @cached_property
    def angle_symbols(self) -> frozenset[sympy.Symbol]:
        """The symbols that are angles: given in an angle unit, asked for in one, or used
        as one in the equations (shown in degrees inside a sine or cosine)."""
        names = set(self.problem.dims.angles)
        for info in self.problem.givens:
            quantity = info.given.quantity if info.given is not None else None
            unit = quantity.unit if quantity is not None else None
            if unit is not None and unit.text.strip() in _ANGLE_UNITS:
                names.add(info.name)
        names.update(t.name for t in self.problem.targets if t.unit in _ANGLE_UNITS)
        symbols = {s for n, s in self.problem.symbols.items() if n in names}
        for equation in self.problem.system.equations:  # a scene's θ_2 inside cos(θ_2)
            for side in (equation.lhs, equation.rhs):
                symbols |= _angle_arguments(side)
        return frozenset(s for s in symbols if self.dims.get(s.name, Dim()).dimensionless)

    @cached_property
    def solved(self) -> dict[sympy.Symbol, sympy.Expr]:
        """The knowns and the solved values in one map (merged once: per row it is n²)."""
        return {**self.knowns, **self.outcome.values}

    def unit_of(self, name: str) -> str:
        if name in self.units:
            return self.units[name]
        dim = self.dims.get(name, Dim())
        if dim.dimensionless and (
            name in self.problem.dims.angles or self.problem.symbols.get(name) in self.angle_symbols
        ):
            return "deg"
        return natural_unit(dim, self.system, name)

    def text(self, expr: sympy.Expr) -> str:
        return self._printed("text", expr)

    def latex(self, expr: sympy.Expr) -> str:
        return self._printed("latex", expr)

    def _printed(self, kind: str, expr: sympy.Expr) -> str:
        """``expr`` printed as text or LaTeX, each form once: a big scene shows the same
        formula for many rows (every block's I_G = m w²/6, every cord's P/(n m)). (Floats
        of other precisions are other keys: sympy's Float(0.5, 15) != Float(0.5, 30).)"""
        key = (kind, expr)
        printed = self._prints.get(key)
        if printed is None:
            if kind == "text":
                printed = formula_text(expr, self.pretty_symbols)
            else:
                printed = formula_latex(expr, self.latex_symbols)
            self._prints[key] = printed
        return printed

    def number(self, expr: sympy.Expr) -> float | None:
        return real_value(expr)

    def shown(self, name: str, expr: sympy.Expr) -> tuple[str, str, float | None]:
        """(text, latex, full value in display unit) of a value in base units."""
        value = self.number(expr)
        if value is None:
            return self.text(expr), self.latex(expr), None
        unit = self.unit_of(name)
        converted = convert(value, unit, self.system)
        latex = latex_number(converted) + (f"\\,{latex_unit(unit)}" if unit else "")
        return format_quantity(converted, unit), latex, converted

    # ---- rows
    def given_row(self, info: GivenInfo) -> GivenRow:
        if info.formula is not None:
            return self.derived_row(info)
        given = info.given
        if info.value is None:
            assert given is not None and given.dimension is not None
            written = f"symbolic ({given.dimension.text.replace('_', ' ')})"
            return GivenRow(
                info.name,
                written,
                "—",
                given.description,
                True,
                latex_name(info.name),
                "\\text{symbolic}",
            )
        if given is None:
            written, description = (
                f"{sig(float(info.value))} {pretty_unit(self._g_unit())}",
                (f"standard gravity ({self.system} default)"),
            )
            unit_text = self._g_unit()
            number_text = sig(float(info.value))
        else:
            assert given.quantity is not None
            unit_text = given.quantity.unit.text if given.quantity.unit else ""
            number_text = given.quantity.text
            written = f"{number_text} {pretty_unit(unit_text)}".strip()
            description = given.description
        base_unit = natural_unit(info.dim, self.system, info.name)
        if info.dim.dimensionless and unit_text:
            base_unit = "rad"
        base_value = convert(float(info.value), base_unit, self.system)
        base = format_quantity(base_value, base_unit, 4, trim=True)
        latex_value = number_text + (f"\\,{latex_unit(unit_text)}" if unit_text else "")
        return GivenRow(
            info.name, written, base, description, False, latex_name(info.name), latex_value
        )

    def derived_row(self, info: GivenInfo) -> GivenRow:
        """A quantity dynsolve derived from the givens (r_G, I_O): its formula and value."""
        assert info.formula is not None and info.value is not None
        value = self.number(info.value)
        unit = self.unit_of(info.name) if info.dim.dimensionless else ""
        unit = unit or natural_unit(info.dim, self.system, info.name)
        base = (
            "—"
            if value is None
            else format_quantity(convert(value, unit, self.system), unit, 4, trim=True)
        )
        if value is not None and not (sympy.Integer(0) + info.formula).free_symbols:
            # a number found numerically (a joint by loop closure): shown with its unit
            converted = convert(value, unit, self.system)
            written = f"= {format_quantity(converted, unit, 6)}"
            latex = latex_number(converted, 6) + (f"\\,{latex_unit(unit)}" if unit else "")
        else:  # the table formula, then its numbers (a hand calculation)
            written = f"= {self.text(info.formula)}"
            latex = self.latex(info.formula)
            numbers = self.substituted(info.formula)
            if numbers is not None:
                written += f" = {numbers[0]}"
                latex += f" = {numbers[1]}"
        return GivenRow(
            info.name, written, base, info.note, value is None, latex_name(info.name), latex
        )

    def _g_unit(self) -> str:
        return "m/s^2" if self.system == "SI" else "ft/s^2"

    def equation_rows(self) -> tuple[EquationRow, ...]:
        return self.problem.rows

    def step(self, index: int, block: object) -> Step:
        from dynsolve.solver.outcome import Block

        assert isinstance(block, Block)
        equations = self.problem.system.equations
        results = []
        for symbol in block.unknowns:
            formula = block.formulas.get(symbol)
            if symbol not in block.values:
                results.append(
                    Formula(symbol.name, "", "", "no valid root", "\\text{no valid root}")
                )
                continue
            value_text, value_latex, _ = self.shown(symbol.name, block.values[symbol])
            show_formula = (
                formula is not None and formula.free_symbols and formula != block.values[symbol]
            )
            if show_formula and formula is not None:
                formula = combined_roots(formula, self.solved)
                formula = self.signed(formula)
            numbers = self.substituted(formula) if show_formula and formula else None
            if numbers:
                value_text, value_latex = self.after_numbers(
                    symbol.name, block.values[symbol], value_text, value_latex, formula
                )
            results.append(
                Formula(
                    name=symbol.name,
                    formula=self.text(formula) if show_formula else "",
                    formula_latex=self.latex(formula) if show_formula else "",
                    value=value_text,
                    value_latex=value_latex,
                    substituted=numbers[0] if numbers else "",
                    substituted_latex=numbers[1] if numbers else "",
                )
            )
        discarded = tuple(
            ", ".join(f"{pretty(s.name)} = {self.shown(s.name, v)[0]}" for s, v in d.values.items())
            + f": {d.reason}"
            for d in block.discarded
        )
        return Step(
            index=index,
            lines=tuple(equations[i].line for i in block.equations),
            unknowns=tuple(s.name for s in block.unknowns),
            method=block.method,
            results=tuple(results),
            discarded=discarded,
            note=block.note,
        )

    def substituted(
        self, formula: sympy.Expr, extra: Mapping[sympy.Symbol, sympy.Expr] | None = None
    ) -> tuple[str, str] | None:
        """(text, latex) of ``formula`` with every symbol replaced by its number in base
        units (``extra`` adds values), unevaluated, as a hand calculation writes it; None
        where a symbol has no number (a symbolic problem) or the formula is a bare symbol.
        An angle inside a sine or cosine is shown in degrees, ``cos(45°)`` (elsewhere, as in
        the work M θ of a couple, in radians)."""
        if isinstance(formula, sympy.Symbol):
            return None
        if extra:
            return self._hand_calculation(formula, {**self.solved, **extra})
        if formula in self._substituted:  # a form shown for many rows: written once
            return self._substituted[formula]
        written = self._hand_calculation(formula, self.solved)
        self._substituted[formula] = written
        return written

    def signed(
        self, formula: sympy.Expr, values: Mapping[sympy.Symbol, sympy.Expr] | None = None
    ) -> sympy.Expr:
        """``formula`` with each |x| written x or −x where the numbers (``values``, else the
        solved ones) tell x's sign: no reader needs |cos 40°|, nor Abs(-44.58). Tidying a
        resolved form can make a new |x| (√(1 − sin²θ)³ = cos²θ |cos θ|): resolved again."""
        for _ in range(3):
            if not formula.has(sympy.Abs):
                break
            formula = abs_resolved(formula, self.solved if values is None else values)
        return formula

    def _hand_calculation(
        self, formula: sympy.Expr, values: Mapping[sympy.Symbol, sympy.Expr]
    ) -> tuple[str, str] | None:
        tidy = presentable(self.signed(formula, values))
        if tidy is None:
            return None  # a form with no tidy text: its numbers are not shown either
        formula = tidy  # |−44.58| written 44.58: the sign of each |x| is known from its numbers
        numbers: dict[sympy.Symbol, float] = {}
        for symbol in formula.free_symbols:
            number = real_value(values[symbol]) if symbol in values else None
            if number is None:
                return None
            numbers[symbol] = number
        # placeholders sort as the symbols do, so the terms keep the formula's order
        placeholders = {s: sympy.Symbol(f"{s.name}__") for s in numbers}
        angles = {s: sympy.Symbol(f"{s.name}__deg") for s in numbers if s in self.angle_symbols}
        shown = _in_trig(
            formula.xreplace(placeholders), {placeholders[s]: a for s, a in angles.items()}
        )
        names: dict[sympy.Symbol, str] = {}  # placeholder: its number as text
        latex_names: dict[sympy.Symbol, str] = {}
        for symbol, number in numbers.items():
            names[placeholders[symbol]] = latex_names[placeholders[symbol]] = _plain(number)
            if symbol in angles:
                degrees = _plain(math.degrees(number), wrap=False)
                names[angles[symbol]] = f"{degrees}°"
                latex_names[angles[symbol]] = f"{degrees}^\\circ"
        text = formula_text(shown)
        # numbers side by side need their dot: (-6.372) \cdot 10
        latex = formula_latex(shown, latex_names, mul_symbol="dot")
        for placeholder in sorted(names, key=lambda s: -len(s.name)):
            text = text.replace(placeholder.name, names[placeholder])
        return text, latex

    def computed(self, name: str) -> sympy.Expr | None:
        target = next((t for t in self.problem.targets if t.name == name), None)
        if target is not None and (target.expr is not None or target.vector is not None):
            return self.scene_value(target)
        symbol = self.problem.symbols[name]
        if symbol in self.outcome.values:
            return self.outcome.values[symbol]
        if symbol in self.knowns:
            return self.knowns[symbol]
        if any(g.name == name for g in self.problem.givens):
            return symbol  # a symbolic given asked for: its own formula
        return None

    def scene_value(self, target: Target) -> sympy.Expr | None:
        """A scene target's value: signed along its axis, or a vector's magnitude."""
        if target.kind == "steepest":
            assert target.expr is not None
            return self.steepest_value(target.expr.name, pretty(target.name))
        if target.kind == "threshold":
            assert target.expr is not None
            return self.threshold_value(target.expr, target.name)
        values = {**self.knowns, **(self.trial if target.trial else self.outcome.values)}
        if target.expr is not None and target.expr.atoms(AppliedUndef):  # a define: P/slips(G, P)
            expr = self.with_thresholds(target.expr)
            if expr is None:
                return None
            target = replace(target, expr=expr)
        if target.vector is not None:
            x, y = (sympy.Integer(0) + c for c in target.vector)
            x, y = x.xreplace(values), y.xreplace(values)
            if (x.free_symbols | y.free_symbols) - set(self.knowns) - set(values):
                unsolved = (x.free_symbols | y.free_symbols) & set(self.problem.system.unknowns)
                if unsolved:
                    return None
            return sympy.sqrt(x**2 + y**2)
        assert target.expr is not None
        value = (sympy.Integer(0) + target.expr).xreplace(values)
        if value.free_symbols & set(self.problem.system.unknowns):
            return None
        return value

    def steepest_value(self, contact: str, label: str = "") -> sympy.Expr | None:
        """steepest(C): the steepest slope the contact C holds on (the smaller of the slip
        and tip angles), computed once, with its checks at that slope (``label``: the
        find's name in them)."""
        from dynsolve.modes.scene_mode import steepest, steepest_checks

        if contact not in self.thresholds:
            label = label or f"steepest({contact})"
            limit = self.steepest_limit(contact)
            found = steepest(
                self.problem,  # type: ignore[arg-type]
                contact,
                self.outcome.values,
                self.options,
                limit,  # type: ignore[arg-type]
            )
            self.thresholds[contact], self.happens[contact] = found.angle, found.happens
            if limit is not None:
                self.limit_checks += steepest_checks(
                    label,
                    contact,
                    limit,
                    found,
                    self.knowns,  # type: ignore[arg-type]
                    self.problem.spec.system,
                )
            elif found.angle is not None:
                self.limit_checks.append(
                    Check.not_run(
                        f"{label}: at the slope found",
                        "friction and tipping at the slope were not evaluated",
                    )
                )
        return self.thresholds[contact]

    def threshold_value(self, call: sympy.Expr, name: str) -> sympy.Expr | None:
        """``tips(C, P)``/``slips(G, P)``: the load's size, computed once, re-checked for
        its regime (the checks named after the find ``name``); None where refused."""
        from dynsolve.thresholds import threshold

        key = sympy.srepr(call)
        if key not in self.thresholds:
            found = threshold(self.problem, call, self.options)
            self.thresholds[key], self.found[name] = found.value, found
            self.limit_checks += [
                Check(f"{pretty(name)}: {check}", passed, detail)
                for check, passed, detail in found.checks
            ]
        return self.thresholds[key]

    def with_thresholds(self, expr: sympy.Expr) -> sympy.Expr | None:
        """``expr`` with each threshold it calls (``slips(G, P)``, ``steepest(C)`` in a
        define line) put in as its value; None where one has no value (no size of the load
        reaches it)."""
        from dynsolve.thresholds import THRESHOLDS

        found: dict[sympy.Expr, sympy.Expr] = {}
        for call in expr.atoms(AppliedUndef):
            name = type(call).__name__
            if name == "steepest":
                value = self.steepest_value(call.args[0].name)
            elif name in THRESHOLDS:
                value = self.threshold_value(call, str(call))
            else:
                continue
            if value is None:
                return None
            found[call] = value
        return expr.xreplace(found)

    def direction(self, target: Target, value: float) -> str:
        from dynsolve.modes.scene_mode import direction_of

        if target.kind == "vector" and target.vector is not None:
            values = {**self.knowns, **(self.trial if target.trial else self.outcome.values)}
            x = self.number((sympy.Integer(0) + target.vector[0]).xreplace(values))
            y = self.number((sympy.Integer(0) + target.vector[1]).xreplace(values))
            if x is None or y is None or value == 0:
                return ""
            from dynsolve.modes.scene_mode import direction_word

            return direction_word(x / value, y / value)
        axis = None
        if target.axis is not None:
            known = dict(self.knowns)
            axis = tuple(
                self.number((sympy.Integer(0) + c).xreplace(known)) or 0.0 for c in target.axis
            )
        return direction_of(target.kind, value, axis)

    def answer(self, target: object) -> AnswerRow:
        from dynsolve.modes.equation_mode import Target

        assert isinstance(target, Target)
        value = self.computed(target.name)
        direction = next(
            (a.direction or "" for a in self.problem.spec.answers if a.name == target.name), ""
        )
        if value is None:
            return AnswerRow(target.name, None, target.unit, "not determined", "", "", direction)
        overflow = AnswerRow(target.name, None, target.unit, NOT_FINITE, "", "", direction)
        if value.has(sympy.nan, sympy.zoo, sympy.oo):
            return overflow
        text, latex, number = self.shown(target.name, value)
        if not math.isfinite(number or 0.0):
            return overflow
        if target.kind != "signed" and number is not None:
            direction = self.direction(target, number) or direction
            text, latex, number = self.shown(target.name, abs(value))
        elif sense_word(direction, 1.0) and number is not None:
            # a signed answer keyed with a word (A_y = 2251 N down): shown as the key reads,
            # a magnitude and its word, not "-2251 N down"
            direction = sense_word(direction, number)
            text, latex, number = self.shown(target.name, abs(value))
        if number is None:
            value, sense = self.sensed(target, value)
            direction = sense or direction
        exact = sympy.sstr(value)
        if number is None:
            # numeric mode shows the formula as solved: its tidying is display only
            tidied = value if self.options.mode == "numeric" else _tidy(value)
            exact, latex = self.text(tidied), self.latex(tidied)
            text = exact + self.base_units_note()
        return AnswerRow(target.name, number, target.unit, text, exact, latex, direction)

    def definition(self, target: Target) -> Formula | None:
        """An answer's own derivation line when it is not a solved unknown or a given
        itself: its formula in the problem's symbols, the numbers put in, its value."""
        if target.trial or target.kind in ("steepest", "threshold"):
            return None
        if target.vector is not None:
            formula = self.magnitude(target.vector)
        elif target.expr is not None:
            formula = sympy.Integer(0) + target.expr
        else:
            return None
        if formula is not None and tidying_lightly():  # numeric mode built it untidied
            formula = tidy(formula, light=False)
        if formula is not None:
            formula = self.signed(formula)
        if formula is None or formula.is_Number or (-formula).is_Symbol or formula.is_Symbol:
            return None
        value = self.computed(target.name)
        if value is None or self.number(value) is None:
            return None
        value_text, value_latex, _ = self.shown(target.name, value)  # signed, as its formula
        numbers = self.substituted(formula)
        if numbers:
            value_text, value_latex = self.after_numbers(
                target.name, value, value_text, value_latex, formula
            )
        return Formula(
            name=target.name,
            formula=self.text(formula),
            formula_latex=self.latex(formula),
            value=value_text,
            value_latex=value_latex,
            substituted=numbers[0] if numbers else "",
            substituted_latex=numbers[1] if numbers else "",
        )

    def steepest_limit(self, contact: str) -> object:
        """steepest(C)'s F(φ) and N(φ) in the givens' symbols, solved once for its value and
        its derivation (None when they could not be solved: the value is then solved with
        the numbers in)."""
        if contact not in self.limits:
            from dynsolve.modes.scene_mode import steepest_limit

            self.limits[contact] = steepest_limit(
                self.problem,  # type: ignore[arg-type]
                contact,
                self.outcome.values,
                self.options,
            )
        return self.limits[contact]

    def steepest_formulas(self, target: Target) -> tuple[Formula, ...]:
        """The steepest slope without slip as the seed notes derive it: the friction and
        normal force needed on a slope β, then |F| = μs N, tan β_max = μs (1 + m R²/I)."""
        from dynsolve.modes.scene_mode import steepest_lines

        assert target.expr is not None
        contact = target.expr.name
        angle = self.computed(target.name)
        found = steepest_lines(
            self.problem,  # type: ignore[arg-type]
            contact,
            self.outcome.values,
            self.options,
            self.steepest_limit(contact),  # type: ignore[arg-type]
            self.happens.get(contact, "slips"),
        )
        if found is None or angle is None or self.number(angle) is None:
            return ()
        F, N, tangent, phi = found
        tips = self.happens.get(contact) == "tips"
        beta = sympy.Symbol(pretty(target.name))  # the angle's own name in the formulas
        at = {beta: angle}
        names = {**self.latex_symbols, beta: latex_name(target.name)}
        force_unit = natural_unit(Dim(1, 1, -2), self.system)
        first = (f"x_{contact}", F, natural_unit(Dim(1, 0, 0), self.system))
        rows = []
        for name, expr, unit in (
            first if tips else (f"F_{contact}", F, force_unit),
            (f"N_{contact}", N, force_unit),
        ):
            shown = expr.xreplace({phi: beta})
            number = self.number(shown.xreplace({**self.knowns, **at}))
            numbers = self.substituted(shown, at)
            if number is None:
                return ()
            rows.append(
                Formula(
                    name,
                    self.text(shown),
                    sympy.latex(shown, symbol_names=names),
                    *self.quantity(number, unit),
                    numbers[0] if numbers else "",
                    numbers[1] if numbers else "",
                )
            )
        formula = sympy.atan(tangent)
        numbers = self.substituted(formula)
        value_text, value_latex, _ = self.shown(target.name, angle)
        rows.append(
            Formula(
                target.name,
                self.text(formula),
                self.latex(formula),
                value_text,
                value_latex,
                numbers[0] if numbers else "",
                numbers[1] if numbers else "",
            )
        )
        return tuple(rows)

    def threshold_formulas(self, target: Target) -> tuple[Formula, ...]:
        """How a threshold was solved: the condition's quantity as a formula in the load
        (x_C(P) reaching the edge, F_C(P) reaching μs N), then the load's root."""
        found = self.found.get(target.name)
        if found is None or found.value is None:
            return ()
        rows = []
        load = target.expr.args[1] if target.expr is not None else None
        at = {load: found.value} if load is not None else {}
        for name, expr, dim in found.lines:  # no name: the load's root, the answer
            number = self.number(expr.xreplace({**self.knowns, **at}))
            if number is None:
                continue
            numbers = self.substituted(expr, at if name else None)
            rows.append(
                Formula(
                    name or target.name,
                    self.text(expr),
                    self.latex(expr),
                    *self.quantity(number, natural_unit(dim or target.dim, self.system)),
                    numbers[0] if numbers else "",
                    numbers[1] if numbers else "",
                )
            )
        return tuple(rows)

    def stated(self, target: Target) -> tuple[Formula, ...]:
        """The quantities an answer's derivation states before it (the curvature κ_max
        before a_max = v² κ_max): formula, numbers and value."""
        rows = []
        for name, expr, dim in target.before:
            number = self.number(expr.xreplace(self.knowns))
            if number is None:
                continue
            numbers = self.substituted(expr)
            rows.append(
                Formula(
                    name,
                    self.text(expr),
                    self.latex(expr),
                    *self.quantity(number, natural_unit(dim or target.dim, self.system)),
                    numbers[0] if numbers else "",
                    numbers[1] if numbers else "",
                )
            )
        return tuple(rows)

    def composite_lines(self, target: Target) -> tuple[Formula, ...]:
        """A composite's I about a point as the textbook sums it: each part's mass, its
        I_G + m d² (a hole's negated) with the numbers put in, then the sum."""
        rows, totals = [], []
        mass_unit = natural_unit(Dim(0, 1), self.system)
        inertia_unit = natural_unit(Dim(2, 1), self.system)
        for k, term in enumerate(target.parts, start=1):
            numeric = replace(
                term,
                mass=term.mass.xreplace(self.knowns),
                distance=term.distance.xreplace(self.knowns),
                values=tuple((s, v.xreplace(self.knowns)) for s, v in term.values),
            )
            mass = self.number(numeric.mass)
            total = self.number(term.total.xreplace(self.knowns))
            if mass is None or total is None:
                return ()
            numbers = self.substituted(term.mass)
            rows.append(
                Formula(
                    f"m_{k}",
                    self.text(term.mass),
                    self.latex(term.mass),
                    *self.quantity(mass, mass_unit),
                    numbers[0] if numbers else "",
                    numbers[1] if numbers else "",
                )
            )
            pieces = [numeric.inertia_shown(), numeric.transfer_shown()]
            text = " + ".join(sympy.sstr(p).replace("**", "^") for p in pieces)
            latex = " + ".join(sympy.latex(p) for p in pieces)
            sign = "-" if term.sign < 0 else ""
            rows.append(
                Formula(
                    f"{target.name}_{k}",
                    f"{sign}(I_G + m*d^2)" if sign else "I_G + m*d^2",
                    f"{sign}(I_G + m d^2)" if sign else "I_G + m d^2",
                    *self.quantity(total, inertia_unit),
                    f"{sign}({text})" if sign else text,
                    f"{sign}\\left({latex}\\right)" if sign else latex,
                )
            )
            totals.append(total)
        value = sum(totals)
        names = [f"{target.name}_{k}" for k in range(1, len(totals) + 1)]
        sums = sig(totals[0], 4) + "".join(
            f" {'-' if t < 0 else '+'} {sig(abs(t), 4)}" for t in totals[1:]
        )
        rows.append(
            Formula(
                target.name,
                " + ".join(pretty(n) for n in names),
                " + ".join(latex_name(n) for n in names),
                *self.quantity(value, inertia_unit),
                sums,
                sums,
            )
        )
        return tuple(rows)

    def after_numbers(
        self, name: str, expr: sympy.Expr, text: str, latex: str, formula: sympy.Expr
    ) -> tuple[str, str]:
        """A hand calculation's value as its numbers give it, in the system's base units,
        then as shown (``text``, ``latex``) where the answer is asked in another unit:
        √(4.762² + 7.937²) = 9.26 m/s = 33.3 km/h, not "= 33.3 km/h" straight from numbers
        in m/s; 10.47·12²/2 + 31.42·12 = 1131 rad = 180 rev. An inverse trigonometric
        ``formula`` gives an angle in any unit: asin(0.77) = 50.3°, as textbooks write it."""
        unit = self.unit_of(name)
        value = self.number(expr)
        if not unit or value is None or not math.isfinite(value):
            return text, latex
        if isinstance(formula, (sympy.asin, sympy.acos, sympy.atan, sympy.atan2)):
            return text, latex
        dim = self.dims.get(name, Dim())
        base = "rad" if dim.dimensionless else natural_unit(dim, self.system, name)
        try:
            same = math.isclose(convert(1.0, unit, self.system), convert(1.0, base, self.system))
        except (DynsolveError, ValueError):
            return text, latex
        if same:
            return text, latex
        before, before_latex = self.quantity(value, base)
        return f"{before} = {text}", f"{before_latex} = {latex}"

    def quantity(self, value: float, unit: str) -> tuple[str, str]:
        """(text, latex) of a value in base units shown in ``unit``."""
        converted = convert(value, unit, self.system)
        return format_quantity(converted, unit), f"{latex_number(converted)}\\,{latex_unit(unit)}"

    def magnitude(self, vector: tuple[sympy.Expr, sympy.Expr]) -> sympy.Expr | None:
        """|v| of a vector answer in the unknowns it is made of: √(O_n² + O_t²) when its
        components are those unknowns along perpendicular unit axes, else √(x² + y²);
        None when one unknown alone gives it (its step already shows it)."""
        x, y = (sympy.Integer(0) + c for c in vector)
        unknowns = sorted(
            (x.free_symbols | y.free_symbols) & set(self.problem.system.unknowns), key=str
        )
        values = self.solved
        nonzero = [u for u in unknowns if self.number(values.get(u, u)) not in (None, 0.0)]
        if len(nonzero) < 2:
            return None
        if _orthonormal(x, y, unknowns, self.knowns):
            return sympy.sqrt(sympy.Add(*(u**2 for u in unknowns)))
        return sympy.sqrt(x**2 + y**2)

    def sensed(self, target: Target, value: sympy.Expr) -> tuple[sympy.Expr, str]:
        """A symbolic rotation as its magnitude and sense (cw/ccw), when the sign of the
        formula is the same for every positive value of the givens; else as it is."""
        from dynsolve.solver.roots import sign_of

        if target.kind != "rotation" or value.free_symbols & set(self.problem.system.unknowns):
            return value, ""
        try:
            sense = sign_of(value, {})
        except ValueError:
            return value, ""
        return sense * value, "ccw" if sense > 0 else "cw"

    def base_units_note(self) -> str:
        """For a formula holding numbers of dimensional givens: which units they are in."""
        numeric = [
            g
            for g in self.problem.givens
            if g.value is not None
            and not (sympy.Integer(0) + g.value).free_symbols
            and not g.dim.dimensionless
        ]
        if not any(self.used(g) for g in numeric):
            return ""
        return f"  (numbers in {', '.join(BASE_UNITS[self.system])})"

    def key(self, answers: tuple[AnswerRow, ...]) -> list[KeyComparison]:
        spec = self.problem.spec
        targets = {t.name: t for t in self.problem.targets}
        known_dims = {g.name: g.dim for g in self.problem.givens} | {
            s.name: self.dims[s.name] for s in self.outcome.values
        }
        if self.problem.mode == "kinematics":
            known_dims |= {n: d for n, d in self.dims.items() if n in ("t", "x", "v")}
        solved = self.solved
        out = []
        for answer in spec.answers:
            target = targets[answer.name]
            row = next(a for a in answers if a.name == answer.name)
            if target.kind != "signed" and answer.formula is None:
                value = self.computed(answer.name)
                number = None if value is None else self.number(value)
                verdict = compare_magnitude(
                    answer,
                    None if number is None else abs(number),
                    row.direction,
                    target.dim,
                    target.unit,
                    spec,
                )
            else:
                computed = self.computed(answer.name)
                if computed is not None and answer.formula is not None:
                    computed, _ = self.sensed(target, computed)
                verdict = compare(
                    answer,
                    computed,
                    target.dim,
                    target.unit,
                    spec,
                    self.problem.symbols,
                    solved,
                    known_dims,
                    confirm=self.options.mode != "numeric",
                )
            out.append(
                KeyComparison(
                    answer.name, verdict.expected, row.shown, verdict.passed, verdict.detail
                )
            )
        return out

    # ---- checks
    def checks(self) -> tuple[Check, ...]:
        outcome = self.outcome
        equations = self.problem.system.equations
        n = len(self.equation_rows())
        detail = f"every equation and constraint is homogeneous ({n} checked)"
        if self.problem.dims.free:
            names = ", ".join(pretty(name) for name in self.problem.dims.free)
            detail += f"; the dimension of {names} is left open by the equations (not asked for)"
        checks = [
            Check("dimensions", True, detail)
            if n
            else Check.not_run("dimensions", "no equation or constraint to check")
        ]
        checks.append(self._structure_check())
        evaluated = [r for r in outcome.residuals if r.evaluated]
        if evaluated:
            worst = max(evaluated, key=lambda r: r.relative)
            checks.append(
                Check(
                    "substitution",
                    worst.relative <= RESIDUAL_LIMIT,
                    "every answer substituted back into "
                    f"{_count(len(evaluated), 'equation')}; largest "
                    f"relative residual {worst.relative:.1e} ({equations[worst.equation].label})",
                )
            )
        if outcome.unneeded:
            labels = ", ".join(equations[i].label for i in outcome.unneeded)
            checks.append(
                Check(
                    "model only what is asked",
                    True,
                    f"not needed for the answers, so not solved: {labels}",
                )
            )
        unevaluated = len(
            [r for r in outcome.residuals if not r.evaluated and r.equation not in outcome.unneeded]
        )
        if unevaluated and outcome.status == "solved":
            verb = "holds" if unevaluated == 1 else "hold"
            detail = f"{_count(unevaluated, 'equation')} {verb} identically"
            checks.append(Check("substitution (symbolic)", True, detail))
        for constraint in self.problem.system.constraints:
            checks.append(self._constraint_check(constraint))
        if outcome.ambiguous:
            names = ", ".join(pretty(s.name) for s in outcome.ambiguous)
            detail = f"several roots remain for {names}: declare a constraint"
            checks.append(Check("root choice", False, detail))
        return tuple(checks)

    def _structure_check(self) -> Check:
        outcome = self.outcome
        lines = {i: e.label for i, e in enumerate(self.problem.system.equations)}
        if outcome.status == "underdetermined":
            names = ", ".join(pretty(s.name) for s in outcome.undetermined)
            detail = (
                f"cannot determine {names}: {_count(outcome.missing_equations, 'equation')} missing"
                + self._typo_hint()
            )
            return Check("structure", False, detail)
        if outcome.status == "inconsistent":
            which = ", ".join(lines[i] for i in outcome.conflicting)
            return Check("structure", False, f"the equations conflict: {which}")
        if outcome.status == "no_valid_root":
            return Check("structure", False, "no root satisfies the constraints")
        if outcome.status == "failed":
            return Check("structure", False, "; ".join(outcome.messages) or "the solve failed")
        unknowns = [pretty(s.name) for s in self.problem.system.unknowns]
        if not unknowns and not lines:
            return Check.not_run("structure", "no equations to solve: nothing to check")
        named = ", ".join(unknowns[:NAMED_UNKNOWNS]) + (
            ", …" if len(unknowns) > NAMED_UNKNOWNS else ""
        )
        detail = (
            f"{_count(len(unknowns), 'unknown')} ({named}) from {_count(len(lines), 'equation')}"
            if unknowns
            else f"no unknowns; {_count(len(lines), 'equation')}"
        )
        if outcome.redundant:
            detail += "; redundant and consistent: " + ", ".join(
                lines[i] for i in outcome.redundant
            )
        return Check("structure", True, detail)

    def _typo_hint(self) -> str:
        import difflib

        if self.problem.mode == "scene":
            return self._support_hint()
        given = [g.name for g in self.problem.givens]
        hints = []
        for symbol in self.outcome.undetermined:
            close = difflib.get_close_matches(symbol.name, given, n=1, cutoff=0.6)
            if close:
                hints.append(f"'{symbol.name}' may be a typo for given '{close[0]}'")
        return ("; " + "; ".join(hints)) if hints else ""

    def _support_hint(self) -> str:
        """Which bodies the free unknowns belong to, and what would pin them down."""
        bodies = self.problem.scene.bodies  # type: ignore[attr-defined]
        free = [s.name for s in self.outcome.undetermined]
        hints = []
        for body in bodies:
            mine = [n for n in free if n.endswith(f"_{body}") or (len(bodies) == 1 and n in
                    ("a_Gx", "a_Gy", "a_Gt", "a_Gn", "alpha"))]  # fmt: skip
            if mine:
                hints.append(
                    f"{body}'s {', '.join(pretty(n) for n in mine)} stay free: add a support "
                    f"(pin, contact, rolls, base) or a cord that fixes {body}'s motion, "
                    f"or state 'motion {body}: translation'"
                )
        return ("; " + "; ".join(hints)) if hints else ""

    def _constraint_check(self, constraint: object) -> Check:
        from dynsolve.system import Constraint

        assert isinstance(constraint, Constraint)
        name = f"constraint {constraint.text} (line {constraint.line})"
        verdict = truth(constraint.relation, self.solved)
        if verdict is None:
            return Check.not_run(name, "cannot be decided for symbolic givens")
        symbolic = any(v.free_symbols for v in self.outcome.values.values())
        how = " (at sampled values of the givens)" if symbolic else ""
        return Check(name, verdict, ("holds" if verdict else "violated by the solution") + how)


def _count(n: int, noun: str) -> str:
    """``3 equations``, ``1 equation``."""
    return f"{n} {noun}" + ("" if n == 1 else "s")


def combined_roots(formula: sympy.Expr, values: Mapping[sympy.Symbol, sympy.Expr]) -> sympy.Expr:
    """``formula`` with the square roots of a product combined into one, for display, where
    every radicand is positive at the problem's values (``sqrt(a)*sqrt(b) = sqrt(a*b)``
    holds there); unchanged when that is not known, or for fewer than two roots.

    >>> g, h, m = sympy.symbols("g h m")
    >>> v = sympy.sqrt(2) * sympy.sqrt(g) * sympy.sqrt(h) / sympy.sqrt(m)
    >>> nine, two, one = sympy.Integer(9), sympy.Integer(2), sympy.Integer(1)
    >>> combined_roots(v, {g: nine, h: two, m: one})
    sqrt(2*g*h/m)
    >>> combined_roots(sympy.sqrt(g) * sympy.sqrt(h), {g: nine})  # h has no value: kept
    sqrt(g)*sqrt(h)
    """
    inside, outside = [], []
    for factor in sympy.Mul.make_args(formula):
        if factor.is_Pow and abs(factor.exp) == sympy.Rational(1, 2):
            inside.append(factor.base ** (2 * factor.exp))
        else:
            outside.append(factor)
    if len(inside) < 2:
        return formula
    for radicand in inside:
        number = real_value(radicand, values)
        if number is None or number <= 0:
            return formula
    root = sympy.Pow(sympy.Mul(*inside), sympy.Rational(1, 2), evaluate=False)
    return sympy.Mul(*outside, root, evaluate=False) if outside else root


def _tidy(expr: sympy.Expr) -> sympy.Expr:
    """A readable form of a symbolic answer, tidied only when small."""
    if sympy.count_ops(expr) > 80:
        return expr
    return tidy(expr)
