"""Solve once, evaluate many: a problem's answers as closed forms in its varied givens.

:func:`build_closed_form` solves the problem with the varied givens left as symbols (the
others substituted), checks that every answer is a closed form in them, and compiles the
answers and the conditions the base solve relied on (declared constraints; in a scene,
contact kept, no slip, cord taut) with ``sympy.lambdify(..., "numpy")``.
:func:`evaluate` then computes every variant at once, and marks the rows the closed form
does not answer: a condition that comes out otherwise than in the base problem (a root
choice or an assumption that flips), a value at the edge of a condition, a value that is
not finite, or a given whose sign breaks the symbol's assumption. Those rows are solved
one by one (:mod:`dynsolve.grade.expected`).

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec('''
... given:
...   m = 2 kg
...   F = 10 N
... equations:
...   F = m*a
... find: a
... ''', "p.dyn")
>>> form = build_closed_form(spec, ("m",))
>>> batch = evaluate(form, [{"m": "4 kg"}, {"m": "5000 g"}])
>>> [float(v) for v in batch.values["a"]], batch.fast.tolist()
([2.5, 2.0], [True, True])
"""

from __future__ import annotations

import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
import sympy

from dynsolve.errors import DynsolveError
from dynsolve.grade.substitute import read_cell
from dynsolve.quantities import resolve_quantity
from dynsolve.spec.ast import Spec
from dynsolve.system import SolveOptions
from dynsolve.units import Dim, system_factor

EDGE = 1e-9  # a condition within this fraction of its edge is decided by a full solve
IMPENDING = 1e-9  # as scene mode: |F| ≤ μs N (1 + 1e-9) still holds


class NotClosedForm(Exception):
    """The problem has no usable closed form in its varied givens (the reason says why)."""


@dataclass(frozen=True)
class TargetForm:
    """How one find is read from the compiled outputs."""

    name: str
    kind: str  # as Target.kind: signed, rotation, along, vector, magnitude
    unit: str  # display unit (as ``dynsolve solve`` shows it)
    dim: Dim
    outputs: tuple[int, ...]  # value; or x, y of a vector
    axis: tuple[int, int] | None = None  # outputs of an "along" axis


@dataclass(frozen=True)
class Condition:
    """A condition the base solve relied on, and how it came out there."""

    label: str
    kind: str  # ">=0", ">0", "<=0", "<0", or "no slip" (outputs F, mu, N)
    outputs: tuple[int, ...]
    holds: bool


@dataclass(frozen=True)
class ClosedForm:
    """A problem's answers and conditions compiled for arrays of the varied givens."""

    spec: Spec
    names: tuple[str, ...]  # varied givens, in the compiled function's argument order
    positive: tuple[bool, ...]  # whether each given's symbol is taken as positive
    base: tuple[float, ...]  # each varied given's base value (base units)
    targets: tuple[TargetForm, ...]
    conditions: tuple[Condition, ...]
    function: Callable[..., Any] = field(repr=False)
    build_seconds: float = 0.0


@dataclass(frozen=True)
class Batch:
    """Every variant evaluated: values in SI base units, directions, and which rows count."""

    values: Mapping[str, np.ndarray]  # SI base units; a magnitude where a direction is shown
    directions: Mapping[str, list[str]]
    fast: np.ndarray  # bool per row: the closed form answers this row
    errors: Mapping[int, str]  # row → why its cells cannot be read
    why_slow: Mapping[int, str]  # row → why it needs a full solve
    closest: tuple[int, ...] = ()  # per condition, the answered row nearest its edge


def build_closed_form(
    spec: Spec, varied: Sequence[str], options: SolveOptions | None = None
) -> ClosedForm:
    """Solve ``spec`` with the givens in ``varied`` as symbols and compile the answers;
    :class:`NotClosedForm` when a closed form does not exist or cannot be trusted."""
    start = time.perf_counter()
    options = options or SolveOptions()
    phases = _phases(spec, options)
    final = phases[-1].problem
    infos = {g.name: g for g in final.givens if g.given is not None and g.value is not None}
    missing = [n for n in varied if n not in infos]
    if missing:
        raise NotClosedForm(f"{missing[0]} is not a given with a value")
    symbols = tuple(infos[n].symbol for n in varied)
    exprs: list[sympy.Expr] = []
    outputs = [_solved_outputs(phase.problem, set(symbols), exprs, options) for phase in phases]
    conditions = tuple(
        c
        for phase, output in zip(phases, outputs, strict=True)
        for c in phase.conditions(phase.problem, output)
    )
    trial, last = phases[0].problem, outputs[-1]
    targets = tuple(  # trial(X) is read from the no-slip trial, as the pipeline does
        _target_form(old, outputs[0], trial) if old.trial else _target_form(new, last, final)
        for old, new in zip(trial.targets, final.targets, strict=True)
    )
    function = sympy.lambdify(symbols, exprs, "numpy", cse=True)
    base = [np.array([float(infos[n].value)]) for n in varied]  # type: ignore[arg-type]
    raw = [np.broadcast_to(_real(v), (1,)) for v in function(*base)]
    for condition in conditions:  # the compiled conditions must say what the base solve said
        if bool(_condition(condition, raw)[0][0]) != condition.holds:
            raise NotClosedForm(f"{condition.label}: the closed form disagrees with the base solve")
    return ClosedForm(
        spec,
        tuple(varied),
        tuple(bool(s.is_positive) for s in symbols),
        tuple(float(infos[n].value) for n in varied),  # type: ignore[arg-type]
        targets,
        conditions,
        function,
        time.perf_counter() - start,
    )


@dataclass(frozen=True)
class _Phase:
    """One solve of the pipeline (a no-slip trial, then the re-solve), and its conditions."""

    problem: Any
    conditions: Callable[[Any, Callable[[object], int]], list[Condition]]


def _solved_outputs(
    problem: Any, chosen: set[sympy.Symbol], exprs: list[sympy.Expr], options: SolveOptions
) -> _Outputs:
    """Solve ``problem`` with the ``chosen`` givens as symbols; return a function that adds an
    expression of its unknowns, in closed form, to ``exprs`` and gives its index."""
    from dynsolve.solver import solve_system

    fixed = {s: v for s, v in problem.system.knowns.items() if s not in chosen}
    for info in problem.givens:
        if info.formula is not None:  # a derived quantity: from the givens as they vary
            fixed[info.symbol] = info.formula.xreplace(fixed)
    try:
        outcome = solve_system(replace(problem.system, knowns=fixed), options)
    except DynsolveError as error:
        raise NotClosedForm(f"the symbolic solve stops: {error.message}") from None
    if outcome.ambiguous:
        names = ", ".join(u.name for u in outcome.ambiguous)
        raise NotClosedForm(f"the root of {names} cannot be chosen for every value of the givens")
    if outcome.status != "solved":
        raise NotClosedForm(f"the symbolic solve ends '{outcome.status}'")
    if any(b.method == "numeric" for b in outcome.blocks):
        raise NotClosedForm("a block is solved numerically, not in closed form")
    return _Outputs({**fixed, **outcome.values}, chosen, exprs)


@dataclass(frozen=True)
class _Outputs:
    """Adds expressions of one solve's unknowns, in closed form, to the compiled outputs."""

    values: Mapping[sympy.Symbol, Any]  # the solve: knowns (varied ones symbolic), unknowns
    chosen: set[sympy.Symbol]
    exprs: list[sympy.Expr]

    def __call__(self, expr: object) -> int:
        """The index of ``expr`` (in the solve's values) among the compiled outputs."""
        expr = (sympy.Integer(0) + expr).xreplace(self.values)  # type: ignore[operator]
        if expr.free_symbols - self.chosen:
            others = ", ".join(sorted(str(s) for s in expr.free_symbols - self.chosen))
            raise NotClosedForm(f"an answer depends on {others}, not only on the varied givens")
        if expr.has(sympy.Piecewise, sympy.nan, sympy.zoo, sympy.oo):
            raise NotClosedForm("an answer is piecewise or not finite in closed form")
        self.exprs.append(expr)
        return len(self.exprs) - 1


def _phases(spec: Spec, options: SolveOptions) -> list[_Phase]:
    """The solves the pipeline makes of the base problem, and how to read their conditions:
    one, or a no-slip trial and its re-solve with kinetic friction (``solve_scene``)."""
    if spec.kinematics:
        raise NotClosedForm("motion from a(t), a(v) or a(x) is solved per variant")
    if not spec.scene:
        from dynsolve.modes.equation_mode import build_problem

        return [_Phase(build_problem(spec), _constraints)]
    from dynsolve.linkage.model import is_linkage
    from dynsolve.rigid3d.model import is_3d

    if is_3d(spec):
        from dynsolve.rigid3d.problem import build_3d_problem

        return [_Phase(build_3d_problem(spec), _constraints)]
    if is_linkage(spec):
        from dynsolve.linkage.problem import build_linkage_problem

        linkage = build_linkage_problem(spec)
        if linkage.placement.closure:
            raise NotClosedForm(
                "a linkage placed by loop closure (numerically) is solved per variant"
            )
        if linkage.linkage.method == "ic" or any(
            m.pressure is not None for m in linkage.linkage.meshes
        ):
            raise NotClosedForm(  # a geometry or a force's sense the givens may change
                "instantaneous centres (where each IC lies, or at infinity) and a tooth "
                "force's radial push are decided per variant"
            )
        return [_Phase(linkage, _constraints)]
    from dynsolve.modes.scene_mode import assess, build_scene_problem
    from dynsolve.solver import solve_system

    problem = build_scene_problem(spec)
    scene, formulation = problem.scene, problem.formulation
    if formulation.stages or scene.travels or scene.impacts or scene.pivots:
        raise NotClosedForm("a scene with stages, travel or impacts is solved per variant")
    outcome = solve_system(problem.system, options)
    assumptions, slips = assess(problem, outcome.values)
    if not slips:
        return [_Phase(problem, lambda p, output: _assumptions(p, assumptions, output))]
    if 0 in slips.values():
        raise NotClosedForm("a stated slide the answer contradicts is solved per variant")
    if any(key.startswith("sense:") for key in slips):
        raise NotClosedForm("a load found acting against its stated sense is solved per variant")
    resolved = build_scene_problem(spec, slips)
    after, more = assess(resolved, solve_system(resolved.system, options).values)
    if more and not more.items() <= slips.items():
        raise NotClosedForm("the base problem is re-solved more than once")
    trial = [a for a in assumptions if a.name.startswith(("no slip at ", "sliding at "))]
    return [
        _Phase(problem, lambda p, output: _assumptions(p, trial, output, slips)),
        _Phase(resolved, lambda p, output: _assumptions(p, after, output)),
    ]


def _constraints(problem: Any, output: Callable[[object], int]) -> list[Condition]:
    """Declared constraints (they chose the root): held in the base problem."""
    out = []
    for constraint in problem.system.constraints:
        relation = constraint.relation
        kind = {">=": ">=0", ">": ">0", "<=": "<=0", "<": "<0"}.get(relation.rel_op)
        if kind is None:
            raise NotClosedForm(f"constraint {constraint.text} is not an inequality")
        index = output(relation.lhs - relation.rhs)
        out.append(Condition(f"constraint {constraint.text}", kind, (index,), True))
    return out


def _assumptions(
    problem: Any,
    assumptions: Sequence[Any],
    output: Callable[[object], int],
    slips: Mapping[str, int] | None = None,
) -> list[Condition]:
    """A scene's assumptions as conditions: contact kept, no slip (and, for a failed no-slip
    trial in ``slips``, the sense of the slip), cord taut, a stated slide, no tipping, the
    slip of a re-solved contact, a load of unknown size acting in its stated sense."""
    reactions = problem.formulation.reactions
    supports = {s.name: s for s in problem.scene.supports}
    out = []
    for assumption in assumptions:
        name = assumption.name
        if not assumption.decided:  # nothing to compare a variant's verdict with
            raise NotClosedForm(f"assumption '{name}' is not decided in the base problem")
        if name.startswith("contact at ") and name.endswith(" kept"):
            support = name.removeprefix("contact at ").removesuffix(" kept")
            index = output(reactions[f"N_{support}"][0])
            out.append(Condition(name, ">=0", (index,), assumption.holds))
        elif name.startswith("cord ") and name.endswith(" taut"):
            cord = name.removeprefix("cord ").removesuffix(" taut")
            out.append(Condition(name, ">=0", (output(reactions[cord][0]),), assumption.holds))
        elif name.startswith("no slip at ") and name[11:] in supports:
            support = supports[name[11:]]
            mu = support.mu_s if support.mu_s is not None else support.mu_k
            outputs = (
                output(reactions[f"F_{support.name}"][0]),
                output(mu),
                output(reactions[f"N_{support.name}"][0]),
            )
            out.append(Condition(name, "no slip", outputs, assumption.holds))
            if slips and support.name in slips:  # the trial's friction sets the slip's sense
                kind = ">0" if slips[support.name] > 0 else "<0"
                out.append(
                    Condition(f"sense of the slip at {support.name}", kind, outputs[:1], True)
                )
        elif name.startswith("slip at ") and name[8:] in problem.slipping:
            out.append(_slip(problem, supports[name[8:]], assumption, output))
        elif name.startswith("sliding at ") and name[11:] in supports:
            out.extend(_slide(problem, supports[name[11:]], assumption, output))
        elif name.startswith("no tipping on base ") and name[19:] in supports:
            out.append(_tipping(problem, supports[name[19:]], assumption, output))
        elif name.startswith(("sense of force ", "sense of couple ")):
            size = {s.name: s for s in problem.formulation.unknowns}[name.split(" ")[-1]]
            out.append(Condition(name, ">=0", (output(size),), assumption.holds))
        else:
            raise NotClosedForm(f"assumption '{name}' is checked per variant")
    return out


def _slide(
    problem: Any, support: Any, assumption: Any, output: Callable[[object], int]
) -> list[Condition]:
    """A stated ``slides DIR`` (as scene mode's ``_declared_slide``): the contact point moves
    that way, or, from rest and without a μs, starts to; anything else is per variant."""
    scene = problem.scene
    if support.kind == "contact" and scene.motions.get(support.body) == "translation":
        return []  # a driven wheel's slide: stated, not checked
    if not assumption.holds:
        raise NotClosedForm(f"assumption '{assumption.name}' fails in the base problem")
    if support.friction_sense is None:  # sliding at the velocities given, no slides line
        raise NotClosedForm(f"assumption '{assumption.name}' (the velocities given) is per variant")
    along = -support.friction_sense
    v, a = _contact_motion(problem, support)
    if v != 0:
        return [Condition(assumption.name, ">0", (output(along * v),), True)]
    if a is None or support.mu_s is not None:
        raise NotClosedForm(f"assumption '{assumption.name}' is checked per variant")
    return [Condition(assumption.name, ">=0", (output(along * a),), True)]


def _slip(
    problem: Any, support: Any, assumption: Any, output: Callable[[object], int]
) -> Condition:
    """A re-solved contact (as scene mode's ``_slip_sense``): its point slips against the
    kinetic friction: by its velocity, or from rest by its acceleration."""
    sense = problem.slipping[support.name]
    if support.friction_sense is not None and sense != support.friction_sense:
        raise NotClosedForm(f"assumption '{assumption.name}' is checked per variant")
    v, a = _contact_motion(problem, support)
    if v != 0:
        return Condition(assumption.name, ">=0", (output(-sense * v),), assumption.holds)
    if a is None:
        raise NotClosedForm(f"assumption '{assumption.name}' is checked per variant")
    return Condition(assumption.name, ">=0", (output(-sense * a),), assumption.holds)


def _contact_motion(problem: Any, support: Any) -> tuple[sympy.Expr, sympy.Expr | None]:
    """The velocity and acceleration of a body's contact point along the contact tangent,
    as expressions (scene mode's ``_contact_motion`` before numbers)."""
    from dynsolve.model.scene import ZERO
    from dynsolve.principles.newton_euler import point_acceleration

    scene = problem.scene
    kin = problem.formulation.kinematics.get(support.body)
    G = scene.bodies[support.body].G
    omega = kin.omega if kin else scene.omegas.get(support.body, sympy.Integer(0))
    v_G = scene.velocities.get(support.body, ZERO)
    r = (support.point[0] - G[0], support.point[1] - G[1])
    v_P = (v_G[0] - omega * r[1], v_G[1] + omega * r[0])
    t = support.tangent
    v = sympy.expand(v_P[0] * t[0] + v_P[1] * t[1])
    if kin is None:
        return v, None
    a_P = point_acceleration(kin, G, support.point)
    return v, a_P[0] * t[0] + a_P[1] * t[1]


def _tipping(
    problem: Any, support: Any, assumption: Any, output: Callable[[object], int]
) -> Condition:
    """No tipping on a base (as scene mode's ``_tipping``): N acts within the base."""
    body = problem.scene.bodies[support.body]
    t = support.tangent
    foot = (body.G[0] - support.point[0]) * t[0] + (body.G[1] - support.point[1]) * t[1]
    length = (support.end[0] - support.point[0]) * t[0] + (support.end[1] - support.point[1]) * t[1]
    where = sympy.Symbol(f"x_{support.name}", real=True)  # an unknown unless a reaction
    x = problem.formulation.reactions.get(f"x_{support.name}", (where,))[0]
    outputs = (output(x), output(-foot), output(length - foot))
    return Condition(assumption.name, "within", outputs, assumption.holds)


def _target_form(target: Any, output: _Outputs, problem: Any) -> TargetForm:
    """How a find is read: from the final solve, or (``trial(X)``) from the no-slip trial."""
    values = output.values
    if target.kind not in ("signed", "rotation", "along", "vector", "magnitude"):
        raise NotClosedForm(f"{target.name} ({target.kind}) is answered per variant")
    if target.vector is not None:
        outputs: tuple[int, ...] = (output(target.vector[0]), output(target.vector[1]))
    elif target.expr is not None:
        outputs = (output(target.expr),)
    elif target.symbol in values:
        outputs = (output(values[target.symbol]),)
    elif any(g.name == target.name for g in problem.givens):
        outputs = (output(target.symbol),)
    else:
        raise NotClosedForm(f"{target.name} is not determined")
    axis = None
    if target.kind == "along" and target.axis is not None:
        axis = (output(target.axis[0]), output(target.axis[1]))
    return TargetForm(target.name, target.kind, target.unit, target.dim, outputs, axis)


def _given_arrays(
    form: ClosedForm, rows: Sequence[Mapping[str, str]]
) -> tuple[list[np.ndarray], dict[int, str]]:
    """Each varied given's values over the rows, in base units; rows whose cells cannot be
    read (their reason) get the base value and are reported."""
    cache: dict[str, float] = {}
    errors: dict[int, str] = {}
    system, file = form.spec.system, form.spec.file
    dims = {g.name: g for g in form.spec.givens}
    columns = []
    for name, base in zip(form.names, form.base, strict=True):
        column = np.full(len(rows), base)
        expected = resolve_quantity(dims[name].quantity, system, file)[1]  # type: ignore[arg-type]
        for i, row in enumerate(rows):
            text = row.get(name, "").strip()
            if not text:
                continue
            if text not in cache:
                try:
                    value, dim = resolve_quantity(read_cell(text), system, file)
                except DynsolveError as error:
                    errors.setdefault(i, f"cannot read {name} = '{text[:40]}': {error.message}")
                    continue
                if dim != expected:
                    errors.setdefault(
                        i, f"{name} = '{text[:40]}' is {dim.name}, not {expected.name}"
                    )
                    continue
                cache[text] = float(value)
            column[i] = cache[text]
        columns.append(column)
    return columns, errors


def evaluate(form: ClosedForm, rows: Sequence[Mapping[str, str]]) -> Batch:
    """Every row at once (see the module docstring for the rows it leaves to a full solve)."""
    arrays, errors = _given_arrays(form, rows)
    return evaluate_arrays(form, arrays, errors)


def evaluate_arrays(
    form: ClosedForm, arrays: Sequence[np.ndarray], errors: Mapping[int, str] | None = None
) -> Batch:
    """Every row at once from the varied givens' values (one array each, in ``form.names``'
    order, in the problem's base units); ``errors`` are rows already known to be unreadable.

    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("given:\\n  m = 2 kg\\n  F = 10 N\\nequations:\\n  F = m*a\\nfind: a")
    >>> evaluate_arrays(build_closed_form(spec, ("m",)), [np.array([4.0, 5.0])]).values["a"]
    array([2.5, 2. ])
    """
    errors = dict(errors or {})
    n = len(arrays[0]) if arrays else 0
    with np.errstate(all="ignore"):
        raw = [np.broadcast_to(_real(v), (n,)) for v in form.function(*arrays)]
    fast = np.ones(n, dtype=bool)
    why: dict[int, str] = {}

    def slow(mask: np.ndarray, reason: str) -> None:
        for i in np.flatnonzero(mask & fast):
            why.setdefault(int(i), reason)
        fast[mask] = False

    for i in errors:
        fast[i] = False
    for name, positive, column in zip(form.names, form.positive, arrays, strict=True):
        if positive:
            slow(~(column > 0), f"{name} is not positive, as the closed form assumes")
    margins = []
    for condition in form.conditions:
        holds, edge, margin = _condition(condition, raw)
        margins.append(margin)
        slow(edge, f"{condition.label} is at its edge")
        slow(
            holds != condition.holds, f"{condition.label} {'fails' if condition.holds else 'holds'}"
        )
    values: dict[str, np.ndarray] = {}
    directions: dict[str, list[str]] = {}
    for target in form.targets:
        value, words = _answer(target, raw, form.spec.system)
        slow(~np.isfinite(value), f"{target.name} is not finite in closed form")
        values[target.name], directions[target.name] = value, words
    closest = tuple(  # per condition, the answered row nearest its edge
        int(np.flatnonzero(fast)[np.argmin(margin[fast])]) for margin in margins if fast.any()
    )
    return Batch(values, directions, fast, errors, why, closest)


def _real(value: object) -> np.ndarray:
    """Output values as floats; a value with an imaginary part becomes NaN (a full solve
    then decides), never its real part alone.

    >>> _real(np.array([1 + 0j, 2 + 1j])).tolist()
    [1.0, nan]
    """
    array = np.asarray(value)
    if np.iscomplexobj(array):
        real = array.real
        return np.where(np.abs(array.imag) <= 1e-12 * np.abs(real), real, np.nan)
    return array.astype(float)


def _condition(
    condition: Condition, raw: Sequence[np.ndarray]
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Whether the condition holds on each row, whether the row is at its edge, and how far
    from the edge it is (relative; NaN where not finite)."""
    if condition.kind == "no slip":
        F, mu, N = (raw[i] for i in condition.outputs)
        limit = mu * N
        holds = np.abs(F) <= limit * (1 + IMPENDING)
        margin = np.abs(np.abs(F) - limit) / np.abs(limit)
        edge = margin <= 1e3 * EDGE
        return holds, edge | ~np.isfinite(margin), margin
    if condition.kind == "within":
        x, low, high = (raw[i] for i in condition.outputs)
        lo, hi = np.minimum(low, high), np.maximum(low, high)
        holds = (lo <= x) & (x <= hi)
        margin = np.minimum(np.abs(x - lo), np.abs(x - hi)) / np.maximum(np.abs(lo), np.abs(hi))
        return holds, (margin <= EDGE) | ~np.isfinite(margin), margin
    (x,) = (raw[i] for i in condition.outputs)
    holds = {">=0": x >= 0, ">0": x > 0, "<=0": x <= 0, "<0": x < 0}[condition.kind]
    finite = np.abs(x[np.isfinite(x)])
    margin = np.abs(x) / max(float(np.max(finite)) if finite.size else 0.0, 1e-300)
    return holds, (margin <= EDGE) | ~np.isfinite(margin), margin


def _answer(
    target: TargetForm, raw: Sequence[np.ndarray], system: str
) -> tuple[np.ndarray, list[str]]:
    """A find's values in SI base units, as ``dynsolve solve`` shows them (magnitudes where a
    direction is stated), and the direction words."""
    from dynsolve.modes.scene_mode import direction_of, direction_word

    factor = system_factor(target.dim, system)  # type: ignore[arg-type]
    n = len(raw[0]) if raw else 0
    if target.kind == "vector":
        x, y = (raw[i] for i in target.outputs)
        size = np.hypot(x, y)
        words = [
            direction_word(float(a) / float(s), float(b) / float(s)) if s > 0 else ""
            for a, b, s in zip(x, y, size, strict=True)
        ]
        return size * factor, words
    value = raw[target.outputs[0]]
    if target.kind == "signed":
        return value * factor, [""] * n
    if target.kind == "rotation":
        words = np.where(value > 0, "ccw", np.where(value < 0, "cw", "")).tolist()
    elif target.kind == "along" and target.axis is not None:
        ax, ay = (raw[i] for i in target.axis)
        words = [
            direction_of("along", float(v), (float(a), float(b)))
            for v, a, b in zip(value, ax, ay, strict=True)
        ]
    else:
        words = [""] * n
    return np.abs(value) * factor, words
