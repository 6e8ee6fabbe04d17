"""Turn a 3D scene into a problem: ΣF = m a_G and ΣM_G = Ḣ_G about the fixed axis.

With Ω = Ω u and α = α u about the fixed axis (unit u through O), r = r_G/O:
a_G = α × r + Ω × (Ω × r). A body that ``spins`` about its own axis s relative to
that frame (symmetric about s, so I_G is constant in the frame) has ω = Ω + ω_s s;
else ω = Ω. H_G = I_G ω and Ḣ_G = (Ḣ_G)_xyz + Ω × H_G = I_G (α u + α_s s) + Ω × H_G
(Hibbeler 21.4). A rate written as a name that is not a given is an unknown (the
precession rate of a steady precession). The bearings'
reactions are named ``A_x``, ``A_y``, ``A_z`` (a journal carries none along the axis); a
``torque`` acts about the axis. An equation with no unknown that holds identically
(ΣM along the axis when α = 0 and no torque) is left out; one that does not hold is
refused (a driving torque is missing). Finds: the reactions, a torque, ``T(B)``
(½ ωᵀ I_G ω + ½ m v_G²), ``Hdot_x(B)`` … (the components of Ḣ_G).

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec('''
... given:
...   m = 10 kg
...   r = 0.1 m
...   w = 30 rad/s
...   L = 0.2 m
... scene:
...   body gear: mass m, disk r, at (0, 0, 0)
...   axis gear: (1, 0, 0)
...   rotates gear: about (1, 0, 0), through (0, 0, 0), omega w
...   bearing A: at (-L, 0, 0), thrust
...   bearing B: at (L, 0, 0), journal
...   gravity
... find: A_y, B_y
... ''', "g.dyn")
>>> problem = build_3d_problem(spec)
>>> [e.note for e in problem.system.equations]
['ΣF_x = m (a_G)_x', 'ΣF_y = m (a_G)_y', 'ΣF_z = m (a_G)_z', 'ΣM_G,y = (Ḣ_G)_y', 'ΣM_G,z = (Ḣ_G)_z']
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import sympy
from sympy.solvers.solveset import NonlinearError

from dynsolve.dimensions import DimensionReport
from dynsolve.errors import DimensionError, Position, SpecError
from dynsolve.format import quantity as format_quantity
from dynsolve.modes.equation_mode import GivenInfo, Target, check_answers_in_find, givens_of
from dynsolve.modes.scene_mode import _row, _unit, _unused
from dynsolve.numbers import light_tidying, tidy
from dynsolve.quantities import convert
from dynsolve.results import Check, EquationRow, Step
from dynsolve.rigid3d.composition import compose
from dynsolve.rigid3d.derivation import composition_checks, composition_notes
from dynsolve.rigid3d.energy import EnergyTerms, build_energy_problem, fixed_point_check
from dynsolve.rigid3d.inertia import Vec3, cross
from dynsolve.rigid3d.model import Scene3D, close_name, read_scene3d
from dynsolve.rigid3d.onset import Onset, build_onset, onset_check
from dynsolve.rigid3d.steady import steady_angles, steady_equations
from dynsolve.shown import formula_text
from dynsolve.spec.ast import FindItem, Spec
from dynsolve.system import Equation, EquationSystem
from dynsolve.trig import tidied
from dynsolve.units import Dim, natural_unit

FORCE, MOMENT, ENERGY = Dim.of("force"), Dim(2, 1, -2), Dim(2, 1, -2)
AXES = "xyz"
VECTORS = {  # find functions of the body's motion, per scene axis: their dimensions
    "omega_": Dim(0, 0, -1),
    "alpha_": Dim(0, 0, -2),
    "v_G": Dim(1, 0, -1),
    "a_G": Dim(1, 0, -2),
    "H_": Dim(2, 1, -1),
    "Hdot_": MOMENT,
}
MOTION_FINDS = frozenset({"T"} | {f"{q}{a}" for q in VECTORS for a in AXES})


@dataclass(frozen=True)
class Problem3D:
    """A 3D scene ready to solve, shaped as the pipeline expects (``SolvableProblem``)."""

    spec: Spec
    givens: tuple[GivenInfo, ...]
    system: EquationSystem
    dims: DimensionReport
    targets: tuple[Target, ...]
    symbols: Mapping[str, sympy.Symbol]
    rows: tuple[EquationRow, ...]
    scene: Scene3D
    reactions: Mapping[str, tuple[Vec3, Vec3]]  # bearing -> (its force, where it acts)
    H_dot: Vec3
    a_G: Vec3
    steps: tuple[Step, ...] = ()
    notes: tuple[tuple[str, str], ...] = ()
    mode: str = "3D scene"
    couples: Mapping[str, Vec3] = field(default_factory=dict)  # a pin's couple across its axis
    energy: EnergyTerms | None = None  # two states: T1, T2 and the work
    moment_point: str = "G"  # where ΣM was written: G, or the one bearing
    onsets: tuple[Onset, ...] = ()  # onset(angle, load) finds


def build_3d_problem(spec: Spec) -> Problem3D:
    """Read the 3D scene of ``spec``, write its six equations and resolve the find list."""
    where = Position(spec.file, 1, 1)
    if not spec.finds:
        raise SpecError("nothing to find", where, hint="add a 'find:' line")
    if spec.equations or spec.defines:
        line = (spec.equations or spec.defines)[0]
        raise SpecError(
            "equations and define lines cannot be combined with a 3D scene yet",
            Position(spec.file, line.line, line.column),
            hint="ask for the scene's own quantities (reactions, T(B), Hdot_x(B), …)",
        )
    scene = read_scene3d(spec)
    body, spin = scene.body, scene.spin
    givens = list(givens_of(spec))
    taken = {g.name for g in givens}
    unknowns: dict[sympy.Symbol, Dim] = {}

    def unknown(name: str, dim: Dim) -> sympy.Symbol:
        if name in taken:
            raise SpecError(
                f"the given '{name}' has the name of an unknown of the scene",
                where,
                hint="rename the given (dynsolve names bearing reactions A_x, A_y, A_z)",
            )
        symbol = sympy.Symbol(name, real=True)
        unknowns[symbol] = dim
        return symbol

    asked = {
        item.ref.function if item.ref and not item.ref.args else item.name for item in spec.finds
    }
    for rate, dim in scene.rates.items():  # an unknown ω or α (a steady precession's Ω)
        tied = (  # the spin that a rolling point ties to the frame's turn
            bool(scene.rolling)
            and scene.spin_of is not None
            and rate == scene.spin_of.omega
            and not close_name(rate.name, list(taken))
        )
        if rate.name not in asked and not tied:  # a typo for a given must not become one
            raise SpecError(
                f"'{rate.name}' is not a given: a rate to solve for must be in find",
                Position(spec.file, spin.line, 1),
                hint=close_name(rate.name, list(taken))
                or f"add '{rate.name}' to find, or declare it under given:",
            )
        unknown(rate.name, dim)
    for angle, dim in scene.angles.items():  # an unknown angle of the position
        unknown(angle.name, dim)
    if scene.travel is not None or scene.rolling:
        return build_energy_problem(spec, scene, unknowns)
    # only ω, α, H_G, … asked: the motion is given and no load is asked for
    loads = bool(unknowns) or not all(_of_the_motion(item) for item in spec.finds)
    along = next(i for i, c in enumerate(scene.shaft) if c != 0)
    reactions: dict[str, tuple[Vec3, Vec3]] = {}
    couples: dict[str, Vec3] = {}
    for bearing in scene.bearings if loads else ():
        force = tuple(
            unknown(f"{bearing.name}_{AXES[i]}", FORCE)
            if i != along or bearing.kind in ("thrust", "ball", "pin", "fixed")
            else sympy.Integer(0)
            for i in range(3)
        )
        reactions[bearing.name] = (force, bearing.at)  # type: ignore[assignment]
        if bearing.kind in ("pin", "fixed"):  # a hinge: a couple across its axis only
            couples[bearing.name] = tuple(  # type: ignore[assignment]
                unknown(f"M_{bearing.name}{AXES[i]}", MOMENT)
                if i != along or bearing.kind == "fixed"
                else sympy.Integer(0)
                for i in range(3)
            )
    torque = sympy.Integer(0)
    for name in scene.torques if loads else ():
        size = scene.symbols[name] if name in taken else unknown(name, MOMENT)
        torque += size
    omega, alpha, v_G, a_G = motion(scene)
    H: Vec3 = tuple(body.I_G * sympy.Matrix(omega))  # type: ignore[assignment]
    I_alpha = tuple(body.I_G * sympy.Matrix(alpha))
    H_dot = tuple(a + b for a, b in zip(I_alpha, cross(omega, H), strict=True))
    equations: list[Equation] = []
    label = "G"
    steady = steady_angles(spec, scene, tuple(unknowns))
    if loads:
        forces = Loads(reactions, couples, torque)
        equations, label = _newton_euler(scene, forces, set(unknowns), a_G, H_dot, where)
        equations += steady_equations(steady, equations, tuple(unknowns))
        _check_determined(equations, unknowns, scene, body.name, where)
    symbols = {g.name: g.symbol for g in givens} | {s.name: s for s in unknowns}
    dims = {g.name: g.dim for g in givens} | {s.name: d for s, d in unknowns.items()}
    knowns = {g.symbol: g.value for g in givens if g.value is not None}
    onsets: list[Onset] = []
    targets_found: list[Target] = []
    for item in spec.finds:
        if item.ref is not None and item.ref.function == "onset":
            at = Position(spec.file, item.line, item.column)
            onset = build_onset(
                item.name,
                item.ref.args,
                tuple(scene.angles),
                {g.name: g.symbol for g in givens},
                knowns,
                equations,
                tuple(unknowns),
                at,
            )
            onsets.append(onset)
            unit, dim = _unit(item, dims[onset.load.name], spec, at)
            targets_found.append(
                Target(
                    item.name,
                    sympy.Symbol(item.name),
                    dim,
                    unit,
                    item.unit is not None,
                    False,
                    "signed",
                    onset.value,
                )
            )
            continue
        if item.ref is not None and item.ref.function == "steady":
            at = Position(spec.file, item.line, item.column)
            unit, dim = _unit(item, Dim(), spec, at)
            steady = sympy.Symbol(item.name, real=True)
            targets_found.append(
                Target(item.name, steady, dim, unit, item.unit is not None, False, "signed", steady)
            )
            continue
        vectors = {"omega_": omega, "alpha_": alpha, "v_G": v_G, "a_G": a_G, "H_": H}
        vectors["Hdot_"] = H_dot
        targets_found.append(_target(item, spec, scene, unknowns, dims, vectors))
    targets = tuple(targets_found)
    check_answers_in_find(spec)
    # every reaction is solved: the second moment point checks them all
    system = EquationSystem(
        tuple(equations), tuple(unknowns), knowns, scene.assumptions, wanted=tuple(unknowns)
    )
    symbol_dims = {symbols[n]: d for n, d in dims.items() if n in symbols}
    try:
        rows = tuple(_row(e, symbol_dims, spec) for e in equations)
    except DimensionError as error:
        raise DimensionError(error.message, where, error.hint) from None
    notes = (_inertia_note(scene, knowns, spec), *composition_notes(scene, knowns, spec))
    notes += tuple(_unused(spec))
    return Problem3D(
        spec,
        tuple(givens),
        system,
        DimensionReport(dims, (), frozenset()),
        targets,
        symbols,
        rows,
        scene,
        reactions,
        H_dot,  # type: ignore[arg-type]
        a_G,  # type: ignore[arg-type]
        notes=notes,
        couples=couples,
        moment_point=label,
        onsets=tuple(onsets),
    )


@dataclass(frozen=True)
class Loads:
    """The loads on the body other than its weight: bearing reactions (force, where it
    acts), couples of pins and fixed supports, and the torque about the turn's axis."""

    reactions: Mapping[str, tuple[Vec3, Vec3]]
    couples: Mapping[str, Vec3]
    torque: sympy.Expr


def _newton_euler(
    scene: Scene3D,
    loads: Loads,
    unknowns: set[sympy.Symbol],
    a_G: Vec3,
    H_dot: Vec3,
    where: Position,
) -> tuple[list[Equation], str]:
    """ΣF = m a_G and ΣM = Ḣ_G (about G, or about the one bearing when an angle of the
    position or a rate is unknown), with the moment point's label; a moment component that
    no unknown load can balance is refused. Ḣ_G + r_G × m a_G is written in its shortest
    form, sin² u + cos² u = 1 applied where that shortens it
    (:func:`~dynsolve.trig.tidied`)."""
    body, spin = scene.body, scene.spin
    weight = (
        tuple(body.mass * scene.symbols["g"] * c for c in scene.gravity)
        if scene.gravity
        else (sympy.Integer(0),) * 3
    )
    equations: list[Equation] = []
    reactions, couples, torque = loads.reactions, loads.couples, loads.torque
    for i, axis in enumerate(AXES):
        total = sum((f[i] for f, _ in reactions.values()), sympy.Integer(0)) + weight[i]
        note = f"ΣF_{axis} = m (a_G)_{axis}"
        equations.append(Equation(total, body.mass * a_G[i], note, spin.line, note))
    # about G; about the one bearing when the motion is unknown (an angle of the position, or
    # a rate: a top's precession about its fixed point, Hibbeler eq. 21-30), so that its
    # reactions drop out of the moments and the motion comes from the moments alone
    unknown_motion = bool(scene.angles or scene.rates)
    pivot = scene.bearings[0] if unknown_motion and len(scene.bearings) == 1 else None
    point = pivot.at if pivot is not None else body.G
    label = pivot.name if pivot is not None else "G"
    r_G = tuple(body.G[i] - point[i] for i in range(3))
    moment = [sympy.Integer(0)] * 3
    for force, at in reactions.values():
        arm = tuple(at[i] - point[i] for i in range(3))
        moment = [m + c for m, c in zip(moment, cross(arm, force), strict=True)]
    moment = [m + c for m, c in zip(moment, cross(r_G, weight), strict=True)]
    moment = [m + torque * c for m, c in zip(moment, spin.axis, strict=True)]
    for couple in couples.values():
        moment = [m + c for m, c in zip(moment, couple, strict=True)]
    m_a_moment = cross(r_G, tuple(body.mass * a for a in a_G))
    for i, axis in enumerate(AXES):
        if pivot is None:
            note = f"ΣM_G,{axis} = (Ḣ_G)_{axis}"
        else:
            note = f"ΣM_{label},{axis} = (Ḣ_G + r_G/{label} × m a_G)_{axis}"
        lhs, rhs = moment[i], tidied(H_dot[i] + m_a_moment[i])  # factored where shorter
        if not (unknowns & (lhs - rhs).free_symbols):
            if sympy.simplify((lhs - rhs).xreplace(dict(scene.values))) == 0:
                continue  # holds whatever the reactions: nothing to solve for
            raise SpecError(
                f"the moments about the {axis} axis cannot balance: (Ḣ_G)_{axis} = "
                f"{sympy.sstr(rhs)} but no unknown load acts about it",
                where,
                hint="a driving torque is missing: add 'torque M on "
                f"{body.name}' (M unknown) or check α",
            )
        equations.append(Equation(lhs, rhs, note, spin.line, note))
    if scene.angles:  # sin 2θ from I_G's entries as 2 sin θ cos θ: one factor sin θ to solve
        equations = [
            Equation(
                sympy.expand_trig(e.lhs),
                sympy.expand(sympy.expand_trig(e.rhs)),
                e.label,
                e.line,
                e.note,
            )
            for e in equations
        ]
    return equations, label


def motion(scene: Scene3D) -> tuple[Vec3, Vec3, Vec3, Vec3]:
    """ω, α (absolute), v_G and a_G of the scene's body.

    The frame turns at Ω = Ω u about the ``rotates`` axis through O; the body turns
    relative to it about s through P (a point the frame carries: G for a rotor's spin),
    so ω = Ω u + ω_s s, α = Ω' u + α_s s + Ω u × ω_s s, v_P = Ω × r_P/O,
    a_P = Ω' u × r_P/O + Ω × (Ω × r_P/O), and v_G = v_P + ω × r_G/P,
    a_G = a_P + α × r_G/P + ω × (ω × r_G/P) (Hibbeler 20.4); with a ``nutates`` line
    the same step is taken once more (:func:`~dynsolve.rigid3d.composition.compose`).

    >>> from dynsolve.rigid3d.model import Body3D, Scene3D, Spin
    >>> z, one = sympy.Integer(0), sympy.Integer(1)
    >>> rod = Body3D("bar", one, (one, z, z), sympy.eye(3), (one,) * 3, ((one, z, z),) * 3, "")
    >>> turn = Spin((z, one, z), (z, z, z), 2 * one, z)
    >>> omega, alpha, v_G, a_G = motion(Scene3D("s.dyn", rod, turn, (), None))
    >>> v_G, a_G  # G 1 m from the axis at 2 rad/s: 2 m/s, 4 m/s² toward the axis
    ((0, 0, -2), (-4, 0, 0))
    """
    chain = compose(scene)
    return chain.omega, chain.alpha, chain.v_G, chain.a_G


def _check_determined(
    equations: list[Equation],
    unknowns: Mapping[sympy.Symbol, Dim],
    scene: Scene3D,
    body: str,
    where: Position,
) -> None:
    """The reactions must be fixed by the equations (rank = number of unknowns) and the
    equations consistent (an extra one may repeat the others: G off the shaft)."""
    residuals = [e.lhs - e.rhs for e in equations]
    try:
        A, b = sympy.linear_eq_to_matrix(residuals, list(unknowns))
    except NonlinearError:  # an unknown rate: the solver decides
        if len(unknowns) > len(equations):
            raise SpecError(
                f"the scene is not determined: {len(unknowns)} unknowns for "
                f"{len(equations)} equations",
                where,
                hint="give the rates (omega, alpha) you know as givens",
            ) from None
        return
    A, b = A.xreplace(dict(scene.values)), b.xreplace(dict(scene.values))
    rank = A.rank(simplify=True)
    named = ", ".join(s.name for s in unknowns)
    if rank < len(unknowns):
        raise SpecError(
            f"the reactions are not determined: {len(unknowns)} unknowns ({named}) but only "
            f"{rank} independent equations",
            where,
            hint="a shaft needs two bearings on its axis, one of them a thrust bearing",
        )
    if A.row_join(b).rank(simplify=True) > rank:
        raise SpecError(
            f"the loads cannot balance: {len(unknowns)} unknowns ({named}) for "
            f"{len(equations)} equations that disagree",
            where,
            hint=f"if {body} speeds up (α ≠ 0), a driving torque is missing: add 'torque M "
            f"on {body}' (M unknown); else a bearing is missing",
        )


def _inertia_note(
    scene: Scene3D, knowns: Mapping[sympy.Symbol, sympy.Expr], spec: Spec
) -> tuple[str, str]:
    """I_G in scene axes from the body's principal moments, as the derivation's step."""
    body = scene.body
    moments = ", ".join(formula_text(tidy(m)) for m in body.principal)
    rows = []
    for i in range(3):
        entries = []
        for j in range(3):
            value = (sympy.Integer(0) + body.I_G[i, j]).xreplace(dict(knowns))
            entries.append(
                f"{float(sympy.N(value)):.4g}"
                if not value.free_symbols
                else formula_text(body.I_G[i, j])
            )
        rows.append("[" + ", ".join(entries) + "]")
    unit = natural_unit(Dim(2, 1, 0), spec.system)
    if body.products is None:
        detail = (
            f"{body.shape}: principal (I_x, I_y, I_z) = ({moments}) about G in body axes; "
            f"I_G = R diag(I_x, I_y, I_z) Rᵀ in scene axes = [{', '.join(rows)}] {unit}"
        )
    else:
        products = ", ".join(formula_text(tidy(p)) for p in body.products)
        detail = (
            f"{body.shape}: (I_x, I_y, I_z) = ({moments}) and products "
            f"(I_xy, I_yz, I_zx) = ({products}) about G in body axes; "
            "I_G = R J Rᵀ in scene axes, J = [[I_x, −I_xy, −I_zx], [−I_xy, I_y, −I_yz], "
            f"[−I_zx, −I_yz, I_z]], = [{', '.join(rows)}] {unit}"
        )
    return (f"inertia of {body.name}", detail)


def _target(
    item: FindItem,
    spec: Spec,
    scene: Scene3D,
    unknowns: Mapping[sympy.Symbol, Dim],
    dims: Mapping[str, Dim],
    vectors: Mapping[str, Vec3],
) -> Target:
    hint = "ask for a bearing reaction (A_x, A_y, A_z), a torque, T(B) or Hdot_x(B)"
    found = named_target(item, spec, unknowns, dims, hint)
    if found is not None:
        return found
    where = Position(spec.file, item.line, item.column)
    symbol = sympy.Symbol(item.name)
    function, args = item.ref.function, item.ref.args
    body = scene.body
    if len(args) != 1 or args[0] != body.name:
        raise SpecError(
            f"'{function}({', '.join(args)})' should name the body, {body.name}",
            where,
            hint=f"e.g. T({body.name})",
        )
    if function == "T":
        omega, H = vectors["omega_"], vectors["H_"]
        energy = sum(w * h for w, h in zip(omega, H, strict=True)) / 2
        energy += body.mass * sum(v**2 for v in vectors["v_G"]) / 2
        unit, dim = _unit(item, ENERGY, spec, where)
        unit = unit if item.unit is not None else natural_unit(ENERGY, spec.system, "E")
        return Target(
            item.name, symbol, dim, unit, item.unit is not None, False, "signed", tidy(energy)
        )
    if function in MOTION_FINDS:
        quantity, axis = function[:-1], AXES.index(function[-1])
        unit, dim = _unit(item, VECTORS[quantity], spec, where)
        return Target(
            item.name,
            symbol,
            dim,
            unit,
            item.unit is not None,
            False,
            "signed",
            tidied(vectors[quantity][axis]) if quantity == "Hdot_" else vectors[quantity][axis],
        )
    raise SpecError(
        f"'{function}({args[0]})' is not a quantity of the 3D scene",
        where,
        hint="ask for T(B), omega_x(B), alpha_x(B), H_x(B), Hdot_x(B), v_Gx(B), a_Gx(B), … "
        "or a reaction by name",
    )


def moment_check(
    problem: Problem3D, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Check, ...]:
    """A second moment point: about the first bearing, ΣM_O = Ḣ_G + r_G/O × m a_G, with the
    solved reactions (an error in the moments about G shows here). Between two states,
    T2 about a fixed point instead (:func:`~dynsolve.rigid3d.energy.fixed_point_check`)."""
    if problem.energy is not None:
        known = {**problem.system.knowns, **values}
        return fixed_point_check(problem.scene, problem.energy, known, problem.spec.system)
    known = {**problem.system.knowns, **values}
    onsets = tuple(c for o in problem.onsets for c in onset_check(o, problem.system.knowns))
    motion_checks = composition_checks(problem.scene, known, problem.spec)
    if not problem.reactions:
        return motion_checks + onsets
    return _second_point(problem, known) + motion_checks + onsets


def _of_the_motion(item: FindItem) -> bool:
    """Whether a find is a quantity of the body's motion alone (ω, α, H_G, T, …)."""
    return item.ref is not None and len(item.ref.args) == 1 and item.ref.function in MOTION_FINDS


def named_target(
    item: FindItem,
    spec: Spec,
    unknowns: Mapping[sympy.Symbol, Dim],
    dims: Mapping[str, Dim],
    hint: str,
) -> Target | None:
    """The target of a find that names an unknown or a given of a 3D scene (``A_x``,
    ``F = A_x``); None for a function of the scene (``T(B)``), which the caller reads;
    a name the scene does not know is an error with ``hint``."""
    where = Position(spec.file, item.line, item.column)
    alias = item.ref.function if item.ref is not None and not item.ref.args else item.name
    if item.ref is not None and alias == item.name:
        return None
    symbol = sympy.Symbol(item.name)
    named = {s.name: s for s in unknowns}
    if alias in named:
        unit, dim = _unit(item, dims[alias], spec, where)
        return Target(
            item.name, symbol, dim, unit, item.unit is not None, False, "signed", named[alias]
        )
    if alias == item.name and alias in dims:
        unit, dim = _unit(item, dims[alias], spec, where)
        return Target(item.name, symbol, dim, unit, item.unit is not None, True)
    raise SpecError(
        f"'{alias}' is not a quantity of the 3D scene",
        where,
        hint=close_name(alias, list(named)) or hint,
    )


def _second_origin(problem: Problem3D) -> tuple[Vec3, str]:
    """The second moment point: the first bearing, or G when the equations were about it."""
    first = problem.scene.bearings[0]
    if problem.moment_point != "G":  # the equations were about the bearing: check about G
        return problem.scene.body.G, "G"
    return first.at, first.name


def _moments_about(problem: Problem3D, origin: Vec3) -> tuple[list[sympy.Expr], list[sympy.Expr]]:
    """ΣM_O of the loads (the reactions, the weight, the couples) and Ḣ_G + r_G/O × m a_G,
    component by component in scene axes."""
    body, scene = problem.scene.body, problem.scene
    total = [sympy.Integer(0)] * 3
    weight = (
        tuple(body.mass * scene.symbols["g"] * c for c in scene.gravity)
        if scene.gravity
        else (sympy.Integer(0),) * 3
    )
    loads = [(force, at) for force, at in problem.reactions.values()] + [(weight, body.G)]
    for force, at in loads:
        arm = tuple(at[i] - origin[i] for i in range(3))
        total = [t + c for t, c in zip(total, cross(arm, force), strict=True)]
    torques = sum(
        (
            (scene.symbols[n] if n in scene.symbols else sympy.Symbol(n, real=True))
            for n in scene.torques
        ),
        sympy.Integer(0),
    )
    total = [t + torques * c for t, c in zip(total, scene.spin.axis, strict=True)]
    for couple in problem.couples.values():
        total = [t + c for t, c in zip(total, couple, strict=True)]
    r_G = tuple(body.G[i] - origin[i] for i in range(3))
    m_a = tuple(body.mass * a for a in problem.a_G)
    expected = [h + c for h, c in zip(problem.H_dot, cross(r_G, m_a), strict=True)]
    return total, expected


def second_moment_rows(problem: Problem3D) -> tuple[EquationRow, ...]:
    """The moment equations about the second point, printed in the unknowns as the notes
    write them: about bearing C, ΣM_C = Ḣ_G + r_G/C × m a_G component by component. The
    bearings' couple of a plate turning about its diagonal reads F √(a² + b²) =
    M ω² ab(a² − b²)/(12(a² + b²)) here (seed 002, (9.33)); about G, ΣM_G = Ḣ_G. A check,
    not used to solve (the 'second moment point' check verifies it with the solved values);
    a component that holds whatever the reactions is left out."""
    if problem.energy is not None or not problem.reactions:
        return ()
    with light_tidying(False):  # shown as exact mode shows it, in every mode
        return _second_moment_rows(problem)


def _second_moment_rows(problem: Problem3D) -> tuple[EquationRow, ...]:
    origin, label = _second_origin(problem)
    total, expected = _moments_about(problem, origin)
    dims = {problem.symbols[n]: d for n, d in problem.dims.dims.items() if n in problem.symbols}
    unknowns = set(problem.system.unknowns)
    values = dict(problem.scene.values)
    rows = []
    for i, axis in enumerate(AXES):
        lhs, rhs = tidied(total[i]), tidied(expected[i])
        if not unknowns & (lhs - rhs).free_symbols and (
            sympy.simplify((lhs - rhs).xreplace(values)) == 0
        ):
            continue  # holds whatever the reactions
        kinetic = f"Ḣ_G + r_G/{label} × m a_G" if label != "G" else "Ḣ_G"
        note = f"ΣM_{label},{axis} = ({kinetic})_{axis}: a second moment point, a check, "
        note += "not used in the solve"
        equation = Equation(lhs, rhs, f"ΣM_{label},{axis}", problem.scene.spin.line, note)
        rows.append(_row(equation, dims, problem.spec))
    return tuple(rows)


def _second_point(
    problem: Problem3D, known: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Check, ...]:
    """ΣM about a second point (the first bearing, or G), with the solved reactions."""
    origin, label = _second_origin(problem)
    total, expected = _moments_about(problem, origin)
    worst, scale = 0.0, 0.0
    for lhs, rhs in zip(total, expected, strict=True):
        try:
            a = float(sympy.N((sympy.Integer(0) + lhs).xreplace(known), 20))
            b = float(sympy.N((sympy.Integer(0) + rhs).xreplace(known), 20))
        except TypeError:
            return ()
        worst, scale = max(worst, abs(a - b)), max(scale, abs(a), abs(b))
    error = worst / scale if scale else 0.0
    unit = natural_unit(MOMENT, problem.spec.system)
    shown = format_quantity(convert(scale, unit, problem.spec.system), unit)
    where = f"bearing {label}" if label != "G" else "G"
    law = f"ΣM_{label} = Ḣ_G + r_G/{label} × m a_G" if label != "G" else "ΣM_G = Ḣ_G"
    detail = f"about {where}: {law} (largest component {shown}; relative difference {error:.1e})"
    return (Check(f"second moment point: {where}", error < 1e-9, detail),)
