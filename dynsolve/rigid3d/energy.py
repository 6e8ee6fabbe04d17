"""Work and energy between two 3D states: T1 + ΣU1-2 = T2 for a body in a turning frame.

State 1 is the scene at rest, or (``travel …, from omega W``) with the frame turning at W
and the body's spin what its rolling points allow; state 2 is reached when the frame that
``rotates`` has turned through the ``travel`` line's angle, and the scene's rates (ω of
``rotates`` and ``spins``) are those of state 2. The body's angular velocity is composed from the
frame's turn and its own spin, ω = Ω u + ω_s s (Hibbeler 20.1); a ``rolls B at (x, y, z)``
point is at rest, v_H = v_G + ω × r_H/G = 0, which ties the spin to the turn (a gear
rolling on a fixed gear). The kinetic energy is T = ½ m v_G² + ½ ωᵀ I_G ω (Hibbeler
21.3), checked against ½ ωᵀ I_O ω about a fixed point O of the body (the frame's point
on its axis, when the body's point there is at rest). The work is that of a couple
about the frame's axis, M Δθ, and of the weight, −m g Δy_G; bearings at fixed points and
the rolling contact do none.

>>> from dynsolve.spec.parser import parse_spec
>>> from dynsolve.rigid3d.problem import build_3d_problem
>>> spec = parse_spec('''
... given:
...   m = 4 kg
...   r = 0.1 m
...   R = 0.3 m
...   M = 5 N*m
...   n = 2 rev
... scene:
...   body gear: mass m, disk r, at (R, 0, 0)
...   axis gear: (1, 0, 0)
...   rotates gear: about (0, 1, 0), through (0, 0, 0), omega w
...   spins gear: about (-1, 0, 0), omega w_s
...   rolls gear at (R, -r, 0)
...   torque M on gear
...   travel gear: turns n about (0, 1, 0)
... find: w, w_s
... ''', "g.dyn")
>>> [e.note for e in build_3d_problem(spec).system.equations]
['no slip at (R, -r, 0): (v_G + ω × r_H/G)_z = 0', 'T1 + ΣU1-2 = T2']
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import sympy

from dynsolve.dimensions import DimensionReport
from dynsolve.errors import DimensionError, Position, SpecError
from dynsolve.format import pretty_unit
from dynsolve.format import quantity as format_quantity
from dynsolve.modes.equation_mode import Target, check_answers_in_find, givens_of
from dynsolve.modes.scene_mode import _row, _unit, _unused
from dynsolve.numbers import tidy
from dynsolve.quantities import convert
from dynsolve.results import Check
from dynsolve.rigid3d.inertia import Vec3, cross
from dynsolve.rigid3d.model import Rolling, Scene3D, Travel3D
from dynsolve.spec.ast import FindItem, Spec
from dynsolve.system import Constraint, Equation, EquationSystem
from dynsolve.units import Dim, natural_unit

if TYPE_CHECKING:
    from dynsolve.rigid3d.problem import Problem3D

ENERGY = Dim(2, 1, -2)
AXES = "xyz"
ZERO = sympy.Integer(0)


@dataclass(frozen=True)
class EnergyTerms:
    """The two states' energy and work, in the unknown rates of state 2."""

    T1: sympy.Expr
    T2: sympy.Expr
    work: tuple[tuple[str, sympy.Expr], ...]  # (what does it, U1-2)
    omega: Vec3
    v_G: Vec3
    omega_1: Vec3 | None = None  # ω in state 1 when it moves

    @property
    def U(self) -> sympy.Expr:
        """ΣU1-2."""
        return sum((u for _, u in self.work), ZERO)


def build_energy_problem(
    spec: Spec, scene: Scene3D, unknowns: dict[sympy.Symbol, Dim]
) -> Problem3D:
    """The two-state problem of a 3D scene with a ``travel`` line (a ``Problem3D``):
    the no-slip equations of its rolling points and T1 + ΣU1-2 = T2."""
    from dynsolve.rigid3d.problem import Problem3D, motion

    travel = scene.travel
    where = Position(spec.file, 1, 1)
    if travel is None:
        line = scene.rolling[0]
        raise SpecError(
            "a rolling point in a 3D scene ties the spin to the turn between two states: "
            "add a travel line",
            Position(spec.file, line.line, line.column),
            hint=f"e.g. 'travel {scene.body.name}: turns 2 rev about "
            f"({', '.join(sympy.sstr(c) for c in scene.spin.axis)})' (state 1 at rest)",
        )
    at = Position(spec.file, travel.line, travel.column)
    if scene.angles:
        names = ", ".join(a.name for a in scene.angles)
        raise SpecError(
            f"an unknown angle of the position ({names}) cannot be found between two states",
            at,
            hint="give the position, or solve the instant (without the travel line)",
        )
    _check_two_state_scene(scene, spec, at)
    body = scene.body
    givens = list(givens_of(spec))
    taken = {g.name for g in givens}
    for name in scene.torques:
        if name not in taken:
            unknowns[sympy.Symbol(name, real=True)] = Dim(2, 1, -2)
    omega, _alpha, v_G, _a_G = motion(scene)
    equations: list[Equation] = []
    every: list[sympy.Expr] = []
    for contact in scene.rolling:
        r = tuple(contact.at[i] - body.G[i] for i in range(3))
        v_H = tuple(v + c for v, c in zip(v_G, cross(omega, r), strict=True))
        point = ", ".join(_plain(c) for c in contact.at)
        _check_rolling(v_H, scene, spec, contact)
        every.extend(v_H)
        if len(every) > 3:  # each point can be at rest: all of them at once too?
            _check_rolling(every, scene, spec, contact, "the rolling points together")
        for i, axis in enumerate(AXES):
            component = sympy.expand(v_H[i])
            if not set(unknowns) & component.free_symbols and (
                sympy.simplify(component.xreplace(dict(scene.values))) == 0
            ):
                continue  # holds whatever the rates
            note = f"no slip at ({point}): (v_G + ω × r_H/G)_{axis} = 0"
            equations.append(Equation(component, ZERO, note, contact.line, note))
    terms = energy_terms(scene, omega, v_G, travel, taken)
    _check_work(terms, unknowns, scene, spec, at)
    note = "T1 + ΣU1-2 = T2"
    equations.append(Equation(terms.T1 + terms.U, terms.T2, note, travel.line, note))
    constraints = _sense(scene, travel, unknowns)
    symbols = {g.name: g.symbol for g in givens} | {s.name: s for s in unknowns}
    dims = {g.name: g.dim for g in givens} | {s.name: d for s, d in unknowns.items()}
    knowns = {g.symbol: g.value for g in givens if g.value is not None}
    targets = tuple(_target(item, spec, scene, unknowns, dims, terms) for item in spec.finds)
    check_answers_in_find(spec)
    system = EquationSystem(
        tuple(equations), tuple(unknowns), knowns, constraints, wanted=tuple(unknowns)
    )
    symbol_dims = {symbols[n]: d for n, d in dims.items() if n in symbols}
    try:
        rows = tuple(_row(e, symbol_dims, spec) for e in equations)
    except DimensionError as error:
        raise DimensionError(error.message, where, error.hint) from None
    from dynsolve.rigid3d.problem import _inertia_note

    notes = (
        _inertia_note(scene, knowns, spec),
        _state_1_note(terms, travel, knowns, spec),
        *(_work_note(what, u, knowns, spec) for what, u in terms.work),
        *_no_work(scene),
        *_unused(spec),
    )
    return Problem3D(
        spec,
        tuple(givens),
        system,
        DimensionReport(dims, (), frozenset()),
        targets,
        symbols,
        rows,
        scene,
        {},
        (ZERO, ZERO, ZERO),
        (ZERO, ZERO, ZERO),
        notes=notes,
        energy=terms,
    )


def energy_terms(
    scene: Scene3D, omega: Vec3, v_G: Vec3, travel: Travel3D, taken: set[str]
) -> EnergyTerms:
    """T1 (0 from rest), T2 = ½ m v_G·v_G + ½ ωᵀ I_G ω and the work of the couples and
    the weight over the frame's turn Δθ = ± the travel's angle (+ along the ``rotates``
    axis)."""
    body, spin = scene.body, scene.spin
    T2 = kinetic(scene, omega, v_G)
    T1, omega_1 = ZERO, None
    if travel.omega_1 is not None:
        omega_1, v_G1 = _state_1(scene, travel.omega_1)
        T1 = kinetic(scene, omega_1, v_G1)
    turn = _turn(travel, spin.axis)
    work: list[tuple[str, sympy.Expr]] = []
    for name in scene.torques:
        size = scene.symbols[name] if name in taken else sympy.Symbol(name, real=True)
        work.append((f"the couple {name}", size * turn))  # U = M Δθ
    if scene.gravity is not None:
        r = tuple(body.G[i] - spin.through[i] for i in range(3))
        end = _rotated(r, spin.axis, turn)
        rise = sympy.simplify(end[1] - r[1])
        work.append(("the weight", -body.mass * scene.symbols["g"] * rise))  # −W Δy_G
    return EnergyTerms(T1, T2, tuple(work), omega, v_G, omega_1)


def kinetic(scene: Scene3D, omega: Vec3, v_G: Vec3) -> sympy.Expr:
    """T = ½ m v_G·v_G + ½ ωᵀ I_G ω (Hibbeler 21.3)."""
    body = scene.body
    I_w = body.I_G * sympy.Matrix(omega)
    rotation = sum((w * h for w, h in zip(omega, I_w, strict=True)), ZERO) / 2
    translation = body.mass * sum((v**2 for v in v_G), ZERO) / 2
    return sympy.expand(translation + rotation)


def _state_1(scene: Scene3D, rate: sympy.Expr) -> tuple[Vec3, Vec3]:
    """ω and v_G in state 1: the frame turning at ``rate``, the body's spin (if any) the one
    its rolling points allow (v_H = 0 solved for it)."""
    from dynsolve.rigid3d.problem import motion

    first = replace(scene, spin=replace(scene.spin, omega=rate))
    own = scene.spin_of
    if own is None:
        omega, _, v_G, _ = motion(first)
        return omega, v_G
    spin = sympy.Dummy("spin_1", real=True)
    first = replace(first, spin_of=replace(own, omega=spin))
    omega, _, v_G, _ = motion(first)
    body = scene.body
    no_slip = [
        sympy.expand(v + c)
        for contact in scene.rolling
        for v, c in zip(
            v_G, cross(omega, tuple(contact.at[i] - body.G[i] for i in range(3))), strict=True
        )
    ]
    found = sympy.solve([e for e in no_slip if e != 0], [spin], dict=True)
    value = found[0][spin] if found else ZERO
    return tuple(c.xreplace({spin: value}) for c in omega), tuple(  # type: ignore[return-value]
        c.xreplace({spin: value}) for c in v_G
    )


def _turn(travel: Travel3D, axis: Vec3) -> sympy.Expr:
    """The frame's turn about its own axis: the travel's angle, negated when the travel's
    direction is the opposite of the axis."""
    along = sympy.simplify(sum((a * b for a, b in zip(travel.axis, axis, strict=True)), ZERO))
    return along * travel.angle


def _rotated(r: Sequence[sympy.Expr], u: Vec3, angle: sympy.Expr) -> Vec3:
    """r turned about the unit vector u by ``angle`` (Rodrigues)."""
    c, s = sympy.cos(angle), sympy.sin(angle)
    u_r = sum((a * b for a, b in zip(u, r, strict=True)), ZERO)
    u_x_r = cross(u, r)
    return tuple(  # type: ignore[return-value]
        r[i] * c + u_x_r[i] * s + u[i] * u_r * (1 - c) for i in range(3)
    )


def _check_two_state_scene(scene: Scene3D, spec: Spec, at: Position) -> None:
    """What the two-state form assumes: the frame turns about a fixed axis, the body spins
    about an axis through G that it is symmetric about (so I_G keeps its value in the
    frame), a couple about the frame's axis does work M Δθ (the spin ⊥ the axis)."""
    body, spin, own = scene.body, scene.spin, scene.spin_of
    values = dict(scene.values)
    if sympy.Integer(0) + spin.alpha != 0 or (own is not None and own.alpha != 0):
        raise SpecError(
            "between two states the rates are those of state 2: an alpha has no place here",
            Position(spec.file, spin.line, 1),
            hint="drop ', alpha …' from the rotates and spins lines",
        )
    travel = scene.travel
    if travel is not None and travel.omega_1 is not None and own is not None and not scene.rolling:
        raise SpecError(
            "from a moving state 1 the body's spin is taken from its rolling points: a body "
            "that spins freely in the frame has no known spin in state 1",
            at,
            hint="add the 'rolls' line that ties the spin to the turn, or start from rest",
        )
    if own is None:
        return
    if own.through is not None and any(
        sympy.simplify((own.through[i] - body.G[i]).xreplace(values)) != 0 for i in range(3)
    ):
        raise SpecError(
            "between two states the body's own spin must be about an axis through G "
            "(a pin off G moves G relative to the frame: not supported yet)",
            at,
            hint="drop 'through' from the spins line, or solve the instant",
        )
    s = own.axis
    I_s = sum((s[i] * (body.I_G * sympy.Matrix(s))[i] for i in range(3)), ZERO)
    transverse = (body.I_G.trace() - I_s) / 2
    symmetric = body.I_G - I_s * sympy.Matrix(s) * sympy.Matrix(s).T
    symmetric -= transverse * (sympy.eye(3) - sympy.Matrix(s) * sympy.Matrix(s).T)
    if any(sympy.simplify(e.xreplace(values)) != 0 for e in symmetric):
        raise SpecError(
            f"{body.name} must be symmetric about its spin axis between two states "
            "(else its inertia changes as it spins)",
            at,
            hint=f"spin {body.name} about its axis of symmetry (its 'axis' line)",
        )
    if scene.torques and sympy.simplify(sum(a * b for a, b in zip(s, spin.axis, strict=True))) != 0:
        raise SpecError(
            "a couple about the frame's axis does work M Δθ only when the spin axis is "
            "perpendicular to it",
            at,
            hint="spin about an axis perpendicular to the 'rotates' axis",
        )


def _check_rolling(
    v_H: Sequence[sympy.Expr],
    scene: Scene3D,
    spec: Spec,
    contact: Rolling,
    what: str = "the rolling point",
) -> None:
    """A rolling point must be able to stay at rest while the frame turns: with Ω = 1 the
    spin (if any) that keeps it at rest must exist; else it is not on the rim."""
    frame = scene.spin.omega
    own = scene.spin_of
    if not isinstance(frame, sympy.Symbol):
        return  # a given turn: the solve shows any clash with the substitution check
    spin = own.omega if own is not None and isinstance(own.omega, sympy.Symbol) else None
    values = dict(scene.values)
    ratio = sympy.Dummy("ratio")
    equations = [
        sympy.expand(c.xreplace({frame: 1} | ({spin: ratio} if spin else {})).xreplace(values))
        for c in v_H
    ]
    solutions = sympy.solve(equations, [ratio] if spin else [], dict=True)
    ok = bool(solutions) if spin else all(sympy.simplify(e) == 0 for e in equations)
    if not ok:
        raise SpecError(
            f"{what} cannot stay at rest while the frame turns (not where the body "
            "touches the fixed surface)",
            Position(spec.file, contact.line, contact.column),
            hint="place it on the body's rim, where it meets the fixed gear (for a disk of "
            "radius r centred at G, at distance r from G in the disk's plane)",
        )


def _check_work(
    terms: EnergyTerms,
    unknowns: Mapping[sympy.Symbol, Dim],
    scene: Scene3D,
    spec: Spec,
    at: Position,
) -> None:
    """State 2 is reached only if T1 + ΣU1-2 > 0 (T2 = 0 would leave the body at rest);
    from rest, ΣU1-2 > 0 and something must do work."""
    if terms.T1 != 0:
        _check_reached(terms, scene, at)
        return
    U = terms.U.xreplace(dict(scene.values))
    if not terms.work or U == 0:
        raise SpecError(
            "nothing does work between the two states: from rest the body stays at rest",
            at,
            hint=f"add the driving couple: 'torque M on {scene.body.name}'",
        )
    if U.free_symbols:  # an unknown torque, or symbolic givens: the solve decides
        return
    value = float(sympy.N(U))
    if value <= 0:
        raise SpecError(
            f"the work done from state 1 to state 2 is {value:.4g} J (not positive): "
            "starting from rest, the body never gets there",
            at,
            hint="check the sense of the torque and of the travel's axis",
        )


def _check_reached(terms: EnergyTerms, scene: Scene3D, at: Position) -> None:
    """From a moving state 1: the frame turns in the sense of the travel, and
    T2 = T1 + ΣU1-2 must be positive (else the body stops first)."""
    assert scene.travel is not None and scene.travel.omega_1 is not None
    start = (scene.travel.omega_1 * _turn(scene.travel, scene.spin.axis)).xreplace(
        dict(scene.values)
    )
    if not start.free_symbols and start < 0:
        raise SpecError(
            "in state 1 the frame turns against the travel: it would stop and turn back",
            at,
            hint="give the rate in state 1 in the sense of the travel's axis (right-hand)",
        )
    T2 = (terms.T1 + terms.U).xreplace(dict(scene.values))
    if T2.free_symbols:  # an unknown torque, or symbolic givens: the solve decides
        return
    value = float(sympy.N(T2))
    if value <= 0:
        raise SpecError(
            f"T1 + ΣU1-2 = {value:.4g} J is not positive: the body stops before it has "
            "turned that far",
            at,
            hint="check the sense of the torque, the travel's angle and the rate in state 1",
        )


def _sense(
    scene: Scene3D, travel: Travel3D, unknowns: Mapping[sympy.Symbol, Dim]
) -> tuple[Constraint, ...]:
    """The frame turns in the sense of the travel in state 2 (the root of T2 = ΣU)."""
    frame = scene.spin.omega
    if not (isinstance(frame, sympy.Symbol) and frame in unknowns):
        return ()
    sense = _turn(travel, scene.spin.axis)
    relation = sympy.StrictGreaterThan(frame * sympy.sign(sense.xreplace(dict(scene.values))), 0)
    if relation in (sympy.true, sympy.false):  # a symbolic turn: taken as written, positive
        relation = sympy.StrictGreaterThan(frame, 0)
    word = ">" if relation.lhs == frame else "<"
    text = f"{frame.name} {word} 0 (the frame turns in the sense of the travel)"
    return (Constraint(relation, text, travel.line),)


def _state_1_note(
    terms: EnergyTerms, travel: Travel3D, knowns: Mapping[sympy.Symbol, sympy.Expr], spec: Spec
) -> tuple[str, str]:
    """State 1: at rest, or moving with its T1 as formula and value."""
    if travel.omega_1 is None:
        return ("state 1", f"at rest: T1 = 0 {pretty_unit(natural_unit(ENERGY, spec.system, 'E'))}")
    shown = _plain(tidy(terms.T1))
    value = terms.T1.xreplace(dict(knowns))
    if not value.free_symbols:
        unit = natural_unit(ENERGY, spec.system, "E")
        shown += " = " + format_quantity(convert(float(sympy.N(value)), unit, spec.system), unit)
    rate = _plain(travel.omega_1)
    return (
        "state 1",
        f"the frame turns at {rate} (the spin as the rolling points allow): "
        f"T1 = ½ m v_G² + ½ ωᵀ I_G ω = {shown}",
    )


def _work_note(
    what: str, work: sympy.Expr, knowns: Mapping[sympy.Symbol, sympy.Expr], spec: Spec
) -> tuple[str, str]:
    """U1-2 of one load, as formula and value: a couple's M Δθ (Δθ in rad), the weight's
    −W Δy_G (none when G keeps its height through the turn)."""
    if work == 0:
        return (f"work of {what}", "none: G keeps its height through the turn (Δy_G = 0)")
    formula = "M Δθ" if what.startswith("the couple") else "−m g Δy_G"
    value = work.xreplace(dict(knowns))
    shown = _plain(work)
    if not value.free_symbols:
        unit = natural_unit(ENERGY, spec.system, "E")
        number = float(sympy.N(value))
        shown += " = " + format_quantity(convert(number, unit, spec.system), unit)
    return (f"work of {what}", f"U1-2 = {formula} = {shown}")


def _no_work(scene: Scene3D) -> tuple[tuple[str, str], ...]:
    """The forces that do no work, named as a textbook does."""
    notes = []
    if scene.rolling:
        notes.append(
            (
                "no work",
                "the rolling contact (its point is at rest: no slip); the fixed surface is "
                "taken round about the frame's axis (a fixed gear centred on the shaft), so "
                "the body rolls on it through the whole turn",
            )
        )
    if scene.bearings:
        names = ", ".join(b.name for b in scene.bearings)
        notes.append(("no work", f"the bearings {names} (fixed points)"))
    return tuple(notes)


def _target(
    item: FindItem,
    spec: Spec,
    scene: Scene3D,
    unknowns: Mapping[sympy.Symbol, Dim],
    dims: Mapping[str, Dim],
    terms: EnergyTerms,
) -> Target:
    from dynsolve.rigid3d.problem import named_target

    hint = f"ask for a rate, a torque, T({scene.body.name}) or U({scene.body.name})"
    found = named_target(item, spec, unknowns, dims, hint)
    if found is not None:
        return found
    where = Position(spec.file, item.line, item.column)
    symbol = sympy.Symbol(item.name)
    function, args = item.ref.function, item.ref.args
    name = scene.body.name
    if function not in ("T", "U") or len(args) != 1 or args[0] != name:
        raise SpecError(
            f"'{function}({', '.join(args)})' is not a quantity of this two-state scene",
            where,
            hint=f"between two states ask for the rates, T({name}) (in state 2) or "
            f"U({name}) (the work ΣU1-2)",
        )
    value = terms.T2 if function == "T" else terms.U
    unit, dim = _unit(item, ENERGY, spec, where)
    unit = unit if item.unit is not None else natural_unit(ENERGY, spec.system, "E")
    return Target(item.name, symbol, dim, unit, item.unit is not None, False, "signed", tidy(value))


def fixed_point_inertia(
    scene: Scene3D, terms: EnergyTerms, values: Mapping[sympy.Symbol, sympy.Expr]
) -> sympy.Matrix | None:
    """I_O about the frame's point O on its axis when the body's point there is at rest (O
    is then a fixed point of the body): I_O = I_G + m (|d|² E − d dᵀ), d = r_G/O (the
    parallel-axis theorem in 3D); None when that point moves."""
    body, origin = scene.body, scene.spin.through
    d = tuple(body.G[i] - origin[i] for i in range(3))
    v_O = tuple(
        v + c for v, c in zip(terms.v_G, cross(terms.omega, tuple(-x for x in d)), strict=True)
    )
    if not _at_rest(v_O, terms.v_G, values):
        return None
    D = sympy.Matrix(d)
    return body.I_G + body.mass * ((D.T * D)[0] * sympy.eye(3) - D * D.T)


def fixed_point_check(
    scene: Scene3D, terms: EnergyTerms, values: Mapping[sympy.Symbol, sympy.Expr], system: str
) -> tuple[Check, ...]:
    """A second method for T2: about the frame's point O on its axis, when the body's point
    there is at rest, T2 = ½ ωᵀ I_O ω (:func:`fixed_point_inertia`)."""
    I_O = fixed_point_inertia(scene, terms, values)
    if I_O is None:
        return ()  # the body's point on the frame's axis moves: no fixed point there
    w = sympy.Matrix(terms.omega)
    about_O = ((w.T * I_O * w)[0] / 2).xreplace(values)
    about_G = terms.T2.xreplace(values)
    point = ", ".join(_plain(c) for c in scene.spin.through)
    lead = (
        f"the body's point ({point}) on the frame's axis is at rest: T2 = ½ ωᵀ I_O ω with "
        "I_O = I_G + m(|r_G/O|² E − r_G/O r_G/Oᵀ)"
    )
    if about_O.free_symbols or about_G.free_symbols:  # symbolic: the same formula
        same = sympy.simplify(about_O - about_G) == 0
        detail = f"{lead} = {_plain(sympy.factor(about_O))}, as ½ m v_G² + ½ ωᵀ I_G ω"
        return (Check("T about the fixed point", same, detail),)
    a, b = float(sympy.N(about_O, 20)), float(sympy.N(about_G, 20))
    error = abs(a - b) / max(abs(a), abs(b), 1e-300)
    unit = natural_unit(ENERGY, system, "E")
    shown = format_quantity(convert(b, unit, system), unit)
    detail = f"{lead} = {shown}, as ½ m v_G² + ½ ωᵀ I_G ω (relative difference {error:.1e})"
    checks = [Check("T about the fixed point", error < 1e-9, detail)]
    if terms.omega_1 is not None:
        w_1 = sympy.Matrix(terms.omega_1)
        a = float(sympy.N(((w_1.T * I_O * w_1)[0] / 2).xreplace(values), 20))
        b = float(sympy.N(terms.T1.xreplace(values), 20))
        error = abs(a - b) / max(abs(a), abs(b), 1e-300)
        shown = format_quantity(convert(b, unit, system), unit)
        detail = (
            f"T1 = ½ ω1ᵀ I_O ω1 = {shown}, as ½ m v_G1² + ½ ω1ᵀ I_G ω1 "
            f"(relative difference {error:.1e})"
        )
        checks.append(Check("T1 about the fixed point", error < 1e-9, detail))
    return tuple(checks)


EnergyRow = tuple[str, sympy.Expr, str]  # ("name = meaning", formula, unit)


def energy_table(
    scene: Scene3D,
    terms: EnergyTerms,
    values: Mapping[sympy.Symbol, sympy.Expr],
    system: str,
) -> tuple[tuple[EnergyRow, ...], dict[sympy.Symbol, sympy.Expr]]:
    """T1 + ΣU1-2 = T2 term by term, as the notes write it (seed 002, problem 9.1): T1, the
    work of each load (U_M = M Δθ), their sum U_12 when several do work, and T2. About a
    fixed point O of the body whose I_O is diagonal in scene axes, T2 = ½ (I_xx ω_x² +
    I_yy ω_y² + I_zz ω_z²) after a row for each I_O moment (9.5)–(9.7); else T2 = ½ m v_G² +
    ½ ωᵀ I_G ω. Returns the rows and the values of the names they define (I_xx …)."""
    energy = natural_unit(ENERGY, system, "E")
    rows = [
        (
            f"T1 = kinetic energy in state 1 ({'moving' if terms.T1 != 0 else 'at rest'})",
            terms.T1,
            energy,
        ),
        *_work_rows(terms, energy),
    ]
    I_O = fixed_point_inertia(scene, terms, values)
    if I_O is None or not _diagonal(I_O, values):
        meaning = "½ m v_G² + ½ ωᵀ I_G ω (kinetic energy in state 2)"
        return (*rows, (f"T2 = {meaning}", terms.T2, energy)), {}
    about_O, defined = _fixed_point_rows(scene, terms, I_O, values, system)
    return (*rows, *about_O), defined


def _work_rows(terms: EnergyTerms, unit: str) -> tuple[EnergyRow, ...]:
    """U1-2 of each load that does work, and their sum U_12 when there are several."""
    works = [(what, u) for what, u in terms.work if u != 0]
    rows = [(f"{_work_name(what)} = {_work_meaning(what)}", u, unit) for what, u in works]
    if len(works) > 1:
        rows.append(("U_12 = ΣU(1→2), the work of all the loads", terms.U, unit))
    return tuple(rows)


def _fixed_point_rows(
    scene: Scene3D,
    terms: EnergyTerms,
    I_O: sympy.Matrix,
    values: Mapping[sympy.Symbol, sympy.Expr],
    system: str,
) -> tuple[tuple[EnergyRow, ...], dict[sympy.Symbol, sympy.Expr]]:
    """I_xx, I_yy, I_zz about the fixed point O (principal axes there) and T2 = ½ (I_xx ω_x² +
    I_yy ω_y² + I_zz ω_z²) in them, a term for each nonzero component of ω."""
    point = ", ".join(_plain(c) for c in scene.spin.through)
    inertia = natural_unit(Dim(2, 1, 0), system)
    moments = [sympy.Symbol(f"I_{a}{a}") for a in AXES]
    rows: list[EnergyRow] = []
    for i, axis in enumerate(AXES):
        meaning = (
            f"about the {axis} axis through the fixed point O ({point}): "
            f"I_G,{axis}{axis} + m d² (parallel axis)"
        )
        rows.append((f"{moments[i].name} = {meaning}", tidy(I_O[i, i]), inertia))
    T2 = sum(
        (moment * w**2 / 2 for moment, w in zip(moments, terms.omega, strict=True) if w != 0),
        ZERO,
    )
    meaning = f"½ (I_xx ω_x² + I_yy ω_y² + I_zz ω_z²) about O ({point}): kinetic energy in state 2"
    rows.append((f"T2 = {meaning}", T2, natural_unit(ENERGY, system, "E")))
    known = dict(values)
    defined = {moment: (ZERO + I_O[i, i]).xreplace(known) for i, moment in enumerate(moments)}
    return tuple(rows), defined


def _work_name(what: str) -> str:
    """The name of a load's work, as the planar table names it: U_M for the couple M, U_W
    for the weight."""
    return f"U_{what.removeprefix('the couple ')}" if what.startswith("the couple") else "U_W"


def _work_meaning(what: str) -> str:
    formula = "M Δθ" if what.startswith("the couple") else "−m g Δy_G"
    return f"{formula} ({what})"


def _diagonal(I_O: sympy.Matrix, values: Mapping[sympy.Symbol, sympy.Expr]) -> bool:
    """Whether the scene axes are principal axes at O: every product of inertia is zero
    (exactly, with letters; against the largest moment to 1e-12, with numbers)."""
    known = dict(values)
    entries = {(i, j): (ZERO + I_O[i, j]).xreplace(known) for i in range(3) for j in range(3)}
    products = [entries[i, j] for i in range(3) for j in range(i + 1, 3)]
    if any(e.free_symbols for e in entries.values()):
        return all(sympy.simplify(e) == 0 for e in products)
    scale = max(abs(float(sympy.N(entries[k, k]))) for k in range(3))
    return all(abs(float(sympy.N(e))) <= 1e-12 * scale for e in products)


def _at_rest(
    v: Sequence[sympy.Expr], v_G: Sequence[sympy.Expr], values: Mapping[sympy.Symbol, sympy.Expr]
) -> bool:
    """Whether a velocity is zero at the solution: exactly (symbolic), or against v_G's
    size to 1e-9 (numbers)."""
    found = [sympy.expand(ZERO + c).xreplace(values) for c in v]
    if all(f == 0 for f in found):
        return True
    speeds = [(ZERO + c).xreplace(values) for c in v_G]
    if any(f.free_symbols for f in (*found, *speeds)):
        return all(sympy.simplify(f) == 0 for f in found)
    scale = max((abs(float(sympy.N(c))) for c in speeds), default=0.0)
    return all(abs(float(sympy.N(f))) <= 1e-9 * max(scale, 1e-300) for f in found)


def _plain(expr: sympy.Expr) -> str:
    return sympy.sstr(expr).replace("**", "^")
