"""Plane (curvilinear) motion of a particle from a ``kinematics:`` section (Hibbeler ch. 12).

Two relations give the motion, one per component:

* x–y components: along each axis its position, velocity or acceleration in t
  (``x = …``, ``v_x = …`` or ``a_x = …``; ``y = …``, ``v_y = …`` or ``a_y = …``), each
  integrated as a rectilinear motion from ``t_0`` and the initial conditions ``x_0``,
  ``y_0``, ``v_x0``, ``v_y0`` (givens, or lines of the section such as
  ``v_x0 = v_0*cos(theta_0)``; zero when absent). A projectile: ``a_x = 0``, ``a_y = -g``.
* r–θ components: ``r = …`` and ``theta = …`` (θ in rad), differentiated by
  :func:`~dynsolve.principles.curvilinear.polar_components`.

``find`` names a quantity in t (``x(t)``), at a given time or an earlier find's time
(``v(t_1)``, ``x(t_f)``), the time a quantity takes a value (``t_at(y, h)``: the later
root after t₀) or a quantity's largest or smallest value (``max(y)``).

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec('''
... given:
...   c = 2 m/s^2
...   k = 1 m/s^3
...   t_1 = 1 s
... kinematics:
...   x = c*t^2
...   y = k*t^3
... find: v_1 = v(t_1), rho_1 = rho(t_1)
... ''', "p.dyn")
>>> problem = build_plane_problem(spec)
>>> [sympy.N(t.expr.xreplace(dict(problem.system.knowns)), 4) for t in problem.targets]
[5.000, 10.42]
"""

from __future__ import annotations

import difflib
from collections.abc import Callable
from dataclasses import dataclass

import sympy

from dynsolve.dimensions import DimensionReport, check_dimensions
from dynsolve.errors import Position, SpecError
from dynsolve.expressions import to_sympy
from dynsolve.format import latex_number, latex_unit, pretty_unit
from dynsolve.format import quantity as format_quantity
from dynsolve.modes.equation_mode import Target, check_answers_in_find, givens_of
from dynsolve.modes.kinematics_mode import KinematicsProblem, check_motion_names, relation_row
from dynsolve.names import latex_name, pretty
from dynsolve.numbers import real_value, tidy
from dynsolve.principles.curvilinear import path_components, polar_components
from dynsolve.principles.rectilinear import (
    Crossings,
    Motion,
    T,
    crossing_times,
    extreme_time,
    integrate_motion,
)
from dynsolve.quantities import convert, resolve_unit
from dynsolve.results import Formula, Step
from dynsolve.shown import formula_latex, formula_text
from dynsolve.spec.ast import EquationStmt, FindItem, Name, Spec
from dynsolve.spec.parser import iter_names
from dynsolve.system import EquationSystem
from dynsolve.units import GRAVITY, Dim, natural_unit
from dynsolve.usage import unused_note

LENGTH, TIME = Dim.of("length"), Dim.of("time")
VELOCITY, ACCELERATION = Dim.of("velocity"), Dim.of("acceleration")
AXES = {"x": ("x", "v_x", "a_x"), "y": ("y", "v_y", "a_y")}  # position, velocity, acceleration
INITIAL = {"x_0": LENGTH, "y_0": LENGTH, "v_x0": VELOCITY, "v_y0": VELOCITY}
QUANTITIES = {
    "x–y": ("x", "y", "v_x", "v_y", "a_x", "a_y", "v", "a", "a_t", "a_n", "rho"),
    "r–θ": ("r", "theta", "v_r", "v_theta", "a_r", "a_theta", "v", "a", "a_t", "a_n", "rho"),
}
DIMS = {"theta": Dim()} | {
    name: dim
    for dim, names in (
        (LENGTH, ("x", "y", "r", "rho")),
        (VELOCITY, ("v", "v_x", "v_y", "v_r", "v_theta")),
        (ACCELERATION, ("a", "a_x", "a_y", "a_r", "a_theta", "a_t", "a_n")),
    )
    for name in names
}
# particle kinetics: the resultant force m a in each component (needs the given mass m)
FORCES = {
    "F_x": "a_x", "F_y": "a_y", "F_r": "a_r", "F_theta": "a_theta",
    "F_t": "a_t", "F_n": "a_n", "F": "a",
}  # fmt: skip
DIMS |= {name: Dim.of("force") for name in FORCES}
PLANE_ONLY = frozenset({"y", "v_x", "v_y", "a_x", "a_y", "r", "theta", "y_0", "v_x0", "v_y0"})
_AXIS_RULES = {  # the rectilinear rules of integrate_motion, along one axis
    "v = v₀ + ∫ a dt": "v_{0} = v_{0}0 + ∫ a_{0} dt",
    "x = x₀ + ∫ v dt": "{0} = {0}₀ + ∫ v_{0} dt",
    "v = dx/dt": "v_{0} = d{0}/dt",
    "a = dv/dt": "a_{0} = dv_{0}/dt",
}


def is_plane(spec: Spec) -> bool:
    """Whether the kinematics section describes plane motion: it names y, v_x, a_y, r, θ …,
    or has more than one relation, one of them for x (one relation alone is rectilinear).

    >>> from dynsolve.spec.parser import parse_spec
    >>> is_plane(parse_spec("kinematics:\\n  a_x = 0\\n  a_y = -g", "k.dyn"))
    True
    >>> is_plane(parse_spec("kinematics:\\n  x = 2*t", "k.dyn"))
    False
    """
    names = {s.lhs.text for s in spec.kinematics if isinstance(s.lhs, Name)}
    return bool(names & PLANE_ONLY) or (len(spec.kinematics) > 1 and "x" in names)


def build_plane_problem(spec: Spec, numbers_first: bool = False) -> KinematicsProblem:
    """Check the two relations (and initial conditions), derive every component, and
    resolve the find list.

    ``numbers_first`` (numeric mode): the givens' values are put into the relations, the
    initial conditions and the finds' arguments once their units are checked, so every
    component is derived, solved for and searched with numbers (the steps show
    y(t) = 10*t − 981*t²/200); a given without a value, and the default g (whose use
    the notes report), stay letters.

    >>> from dynsolve.spec.parser import parse_spec
    >>> given = "given:\\n  c = 3 m/s\\n  w = 2 rad/s\\n"
    >>> text = given + "kinematics:\\n  r = c*t\\n  theta = w*t\\nfind: q = v_theta(t)"
    >>> build_plane_problem(parse_spec(text, "k.dyn")).targets[0].expr
    c*t*w
    """
    return _Builder(spec, numbers_first).problem()


@dataclass(frozen=True)
class Derivation:
    """One derived formula: the quantity, its expression, the rule and the lines it uses."""

    name: str
    expr: sympy.Expr
    rule: str
    method: str
    lines: tuple[int, ...]
    dim: Dim
    discarded: tuple[str, ...] = ()
    time: sympy.Expr | None = None  # for a largest/smallest value: when it occurs


class _Builder:
    """Builds one plane-motion problem; holds the lookups its steps share."""

    def __init__(self, spec: Spec, numbers_first: bool = False) -> None:
        self.spec, self.file = spec, spec.file
        self.givens = tuple(givens_of(spec))
        self.given_dims = {g.name: g.dim for g in self.givens}
        self.symbols = {g.name: g.symbol for g in self.givens} | {"t": T}
        self.values = {g.symbol: g.value for g in self.givens if g.value is not None}
        # numbers_first: the values put in as the motion is built (the default g stays a
        # letter: the note on standard gravity reads whether an answer uses it)
        self.put_in = {
            g.symbol: g.value
            for g in self.givens
            if numbers_first and g.value is not None and not (g.name == "g" and g.given is None)
        }
        self.relations: dict[str, EquationStmt] = {}
        self.initial_lines: dict[str, EquationStmt] = {}
        self.formulas: dict[str, sympy.Expr] = {}
        self.derivations: list[Derivation] = []
        self.targets: dict[str, Target] = {}
        self.components = "x–y"
        self.accelerations: dict[str, sympy.Expr] = {}  # a_x, a_y with letters (the notes)
        self.t0: sympy.Expr = self._in(self.symbols.get("t_0", sympy.Integer(0)))
        self.initial: dict[str, sympy.Expr] = {}

    def at(self, line: int, column: int) -> Position:
        return Position(self.file, line, column)

    def _in(self, expr: sympy.Expr) -> sympy.Expr:
        """``expr`` with the values put in (numeric mode), else as it is."""
        return (sympy.Integer(0) + expr).xreplace(self.put_in) if self.put_in else expr

    def problem(self) -> KinematicsProblem:
        self._classify()
        check_motion_names(self.givens, ("t", *QUANTITIES[self.components]), self.file)
        self._check_names()
        statements = self.spec.kinematics
        lhs_dims = {n: DIMS.get(n) or INITIAL[n] for n in (*self.relations, *self.initial_lines)}
        known = self.given_dims | {"t": TIME, "pi": Dim()} | lhs_dims
        report = check_dimensions(statements, known, self.file, self.spec.system)
        self._initial_conditions()
        if self.components == "x–y":
            self._cartesian()
        else:
            self._polar()
        targets = tuple(self._target(item) for item in self.spec.finds)
        check_answers_in_find(self.spec)
        rows = tuple(
            relation_row(s, check.dim, self.spec, _note(s))
            for s, check in zip(statements, report.checks, strict=True)
        )
        lines = tuple(s.line for s in self.relations.values())
        motion = Motion(
            ", ".join(f"{pretty(n)}(t)" for n in self.relations),
            {f"{q}(t)": e for q, e in self.formulas.items()},
            tuple((d.name, d.rule) for d in self.derivations),
        )
        dims = self.given_dims | {"t": TIME} | {t.name: t.dim for t in targets}
        steps = tuple(self._step(i, d, lines) for i, d in enumerate(self.derivations, start=1))
        return KinematicsProblem(
            self.spec,
            self.givens,
            EquationSystem(equations=(), unknowns=(), knowns=self.values),
            DimensionReport(dims, (), frozenset()),
            targets,
            self.symbols,
            rows,
            steps,
            motion,
            self._notes(targets),
        )

    # ---- the section
    def _classify(self) -> None:
        by_component: dict[str, EquationStmt] = {}
        for st in self.spec.kinematics:
            where = self.at(st.line, st.column)
            name = st.lhs.text if isinstance(st.lhs, Name) else str(st.lhs)
            if st.relation != "=":
                raise SpecError(
                    f"'{st.text}' is not a relation of the motion", where, f"write '{name} = …'"
                )
            if name in self.given_dims:
                raise SpecError(
                    f"'{name}' is a given and is also set in kinematics",
                    where,
                    hint=f"remove '{name}' from given: or from kinematics:",
                )
            if name in INITIAL:
                self.initial_lines[name] = st
                continue
            component = next((a for a, names in AXES.items() if name in names), None)
            component = component or (name if name in ("r", "theta") else None)
            if component is None:
                raise SpecError(
                    f"'{name}' is not a component of plane motion", where, _lhs_hint(name)
                )
            if component in by_component:
                first = by_component[component]
                raise SpecError(
                    f"the {pretty(component)} motion is given twice "
                    f"(line {first.line}: '{first.text}')",
                    where,
                    hint="give one relation per component",
                )
            by_component[component] = st
            self.relations[name] = st
        cartesian = [by_component[a] for a in ("x", "y") if a in by_component]
        polar = [by_component[a] for a in ("r", "theta") if a in by_component]
        if cartesian and polar:
            later = max(cartesian[0], polar[0], key=lambda s: (s.line, s.column))
            raise SpecError(
                f"the section mixes x–y components (line {cartesian[0].line}) "
                f"and r–θ components (line {polar[0].line})",
                self.at(later.line, later.column),
                hint="describe the motion in one set: x and y (or v_x, a_x …), or r and theta",
            )
        if not cartesian and not polar:
            st = next(iter(self.initial_lines.values()))
            raise SpecError(
                "initial conditions are given but no relation of the motion",
                self.at(st.line, st.column),
                hint="add a_x = … and a_y = … (or x = … and y = …)",
            )
        if polar:
            self.components = "r–θ"
            for name, st in self.initial_lines.items():
                raise SpecError(
                    f"'{name}' is an x–y initial condition, but the motion is given by r and θ",
                    self.at(st.line, st.column),
                    hint="remove it: r(t) and theta(t) give the motion at every time",
                )
        pairs = (("r", "theta"), ("theta", "r")) if polar else (("x", "y"), ("y", "x"))
        for have, need in pairs:
            if have in by_component and need not in by_component:
                st = by_component[have]
                partner = f"{need} = …" if polar else f"{need} = …, v_{need} = … or a_{need} = …"
                raise SpecError(
                    f"'{st.text}' has no partner: plane motion needs the {pretty(need)} "
                    "component too",
                    self.at(st.line, st.column),
                    hint=f"add {partner} (one relation per component)",
                )

    def _check_names(self) -> None:
        for st in self.spec.kinematics:
            initial = isinstance(st.lhs, Name) and st.lhs.text in INITIAL
            allowed = set(self.given_dims) | ({"pi"} if initial else {"pi", "t"})
            for name in iter_names(st.rhs):
                if name.text in allowed:
                    continue
                where = self.at(name.line, name.column)
                if name.text == "t":
                    raise SpecError(
                        f"the initial condition {st.lhs} depends on t",
                        where,
                        hint="give its value at t_0, from the givens",
                    )
                close = difflib.get_close_matches(name.text, sorted(allowed - {"pi"}), n=1)
                if name.text in DIMS or name.text in INITIAL:
                    hint = "a relation of plane motion is a function of t and the givens only"
                else:
                    hint = f"did you mean '{close[0]}'?" if close else "declare it under given:"
                what = "a given" if initial else "a given nor t"
                raise SpecError(f"'{name.text}' is neither {what}", where, hint)
        for name, dim in [*INITIAL.items(), ("t_0", TIME)]:
            given = next((g.given for g in self.givens if g.name == name), None)
            if given is not None and self.given_dims[name] != dim:
                raise SpecError(
                    f"{name} is {dim.name}, but it is given as {self.given_dims[name].name}",
                    self.at(given.line, given.column),
                    hint=f"give it a unit of {dim.name}",
                )

    # ---- the motion
    def _derive(self, quantity: str, expr: sympy.Expr, rule: str, lines: tuple[int, ...]) -> None:
        self.formulas[quantity] = expr
        method = "integration" if "∫" in rule else "differentiation" if "/dt" in rule else ""
        method = method or ("given" if rule == "given" else "algebra")
        name = f"{pretty(quantity)}(t)"
        self.derivations.append(Derivation(name, expr, rule, method, lines, DIMS[quantity]))

    def _initial_conditions(self) -> None:
        for name, dim in INITIAL.items():
            if name in self.given_dims:
                self.initial[name] = self._in(self.symbols[name])
            elif name in self.initial_lines:
                st = self.initial_lines[name]
                expr = self._in(to_sympy(st.rhs, self.symbols, self.values))
                self.initial[name] = expr
                self.derivations.append(
                    Derivation(name, expr, "initial condition", "algebra", (st.line,), dim)
                )
            else:
                self.initial[name] = sympy.Integer(0)

    def _cartesian(self) -> None:
        for axis, names in AXES.items():
            name = next(n for n in names if n in self.relations)
            st = self.relations[name]
            kind = ("x(t)", "v(t)", "a(t)")[names.index(name)]
            letters = to_sympy(st.rhs, self.symbols, self.values)
            self.accelerations[names[2]] = sympy.diff(letters, T, 2 - names.index(name))
            expr = self._in(letters)
            start = (self.initial[f"{axis}_0"], self.initial[f"v_{axis}0"])
            motion = integrate_motion(expr, kind, self.t0, *start, in_time_only=True)
            used = [self.initial_lines.get(n) for n in (f"{axis}_0", f"v_{axis}0")]
            lines = tuple(sorted({st.line, *(s.line for s in used if s and kind != "x(t)")}))
            for key, how in motion.steps:
                if key not in ("x(t)", "v(t)", "a(t)"):
                    continue  # t(v), x(v): one-line relations, not components
                quantity = names[("x(t)", "v(t)", "a(t)").index(key)]
                rule = _AXIS_RULES.get(how, how).format(axis)
                step_lines = (st.line,) if how in ("given", "v = dx/dt", "a = dv/dt") else lines
                self._derive(quantity, motion.formulas[key], rule, step_lines)
        lines = tuple(s.line for s in self.relations.values())
        v_x, v_y, a_x, a_y = (self.formulas[q] for q in ("v_x", "v_y", "a_x", "a_y"))
        self._derive("v", tidy(sympy.sqrt(v_x**2 + v_y**2)), "v = √(v_x² + v_y²)", lines)
        self._derive("a", tidy(sympy.sqrt(a_x**2 + a_y**2)), "a = √(a_x² + a_y²)", lines)

    def _polar(self) -> None:
        r_line, theta_line = self.relations["r"], self.relations["theta"]
        lines = (r_line.line, theta_line.line)
        r, theta = (
            self._in(to_sympy(s.rhs, self.symbols, self.values)) for s in (r_line, theta_line)
        )
        self._derive("r", r, "given", (r_line.line,))
        self._derive("theta", theta, "given", (theta_line.line,))
        found = polar_components(r, theta, T)
        self._derive("v_r", found.v_r, "v_r = dr/dt", lines)
        self._derive("v_theta", found.v_theta, "v_θ = r dθ/dt", lines)
        self._derive("a_r", found.a_r, "a_r = d²r/dt² − r (dθ/dt)²", lines)
        self._derive("a_theta", found.a_theta, "a_θ = r d²θ/dt² + 2 (dr/dt)(dθ/dt)", lines)
        speed = tidy(sympy.sqrt(found.v_r**2 + found.v_theta**2), light=False)
        self._derive("v", speed, "v = √(v_r² + v_θ²)", lines)
        magnitude = tidy(sympy.sqrt(found.a_r**2 + found.a_theta**2), light=False)
        self._derive("a", magnitude, "a = √(a_r² + a_θ²)", lines)

    def _normal_tangential(self) -> None:
        if "a_t" in self.formulas:
            return
        v1, v2, a1, a2 = (
            ("v_x", "v_y", "a_x", "a_y") if self.components == "x–y" else QUANTITIES["r–θ"][2:6]
        )
        p1, p2, q1, q2 = (pretty(n) for n in (v1, v2, a1, a2))
        found = path_components(*(self.formulas[n] for n in (v1, v2, a1, a2)))
        lines = tuple(s.line for s in self.relations.values())
        self._derive("a_t", found.a_t, f"a_t = (v·a)/v = ({p1} {q1} + {p2} {q2})/v", lines)
        self._derive("a_n", found.a_n, f"a_n = |v × a|/v = |{p1} {q2} − {p2} {q1}|/v", lines)
        self._derive("rho", found.rho, "ρ = v²/a_n", lines)

    # ---- the finds
    def _target(self, item: FindItem) -> Target:
        where = self.at(item.line, item.column)
        if item.name in self.targets:
            raise SpecError(f"'{item.name}' is listed twice in find", where, hint="remove one")
        ref = item.ref
        if ref is None:
            raise SpecError(
                f"'{item.name}' is not a quantity of the motion",
                where,
                hint="name one such as 'v_1 = v(t_1)', 'y_t = y(t)' or 't_f = t_at(y, y_0)'",
            )
        at, args = self.at(ref.line, ref.column), ref.args
        lines = tuple(s.line for s in self.relations.values())
        if ref.function == "t_at":
            if len(args) != 2:
                raise SpecError("t_at takes a quantity and a value", at, "e.g. t_f = t_at(y, h)")
            quantity = self._quantity(args[0], at)
            if args[1] == "0":  # zero in any unit, as in one-line motion: t_at(y, 0)
                level, dim = sympy.Integer(0), DIMS[quantity]
            else:
                level, dim = self._value(args[1], at)
            if dim != DIMS[quantity]:
                raise SpecError(
                    f"'{args[1]}' is {dim.name}, but {pretty(quantity)} is {DIMS[quantity].name}",
                    at,
                    hint=f"give a value of {DIMS[quantity].name}",
                )
            q = self.formulas[quantity]
            found = self._solving(at, lambda: crossing_times(q, level, self.t0, self.values))
            if not found.times:
                raise SpecError(
                    f"{pretty(quantity)} never equals {pretty(args[1])} after t₀",
                    at,
                    hint="check the value and the signs of the relations",
                )
            expr, dim = found.times[-1], TIME
            rule = (
                f"{pretty(quantity)}(t) = {pretty(args[1])} solved for t; "
                "the later root after t₀ is taken"
            )
            earlier = [(t, "an earlier root") for t in found.times[:-1]]
            discarded = self._discarded((*found.discarded, *earlier))
            self.derivations.append(
                Derivation(item.name, expr, rule, "root choice", lines, dim, discarded)
            )
        elif ref.function in ("max", "min"):
            if len(args) != 1:
                raise SpecError(f"{ref.function} takes one quantity", at, "e.g. h = max(y)")
            quantity, largest = self._quantity(args[0], at), ref.function == "max"
            q = self.formulas[quantity]
            found = self._solving(at, lambda: extreme_time(q, self.t0, self.values, largest))
            time, dim = found.times[0], DIMS[quantity]
            expr = tidy(self.formulas[quantity].subs(T, time))
            shown, sign = pretty(quantity), "<" if largest else ">"
            rule = (
                f"{shown} is {'largest' if largest else 'smallest'} where d{shown}/dt = 0 "
                f"and d²{shown}/dt² {sign} 0"
            )
            discarded = self._discarded(found.discarded)
            self.derivations.append(
                Derivation(item.name, expr, rule, "extreme", lines, dim, discarded, time)
            )
        else:
            quantity = self._quantity(ref.function, at)
            if len(args) != 1:
                raise SpecError(
                    f"{ref.function} takes one argument, the time",
                    at,
                    hint=f"write {ref.function}(t), or {ref.function}(t_1) at a given time",
                )
            time = self._time(args[0], at)
            expr, dim = self.formulas[quantity].subs(T, time), DIMS[quantity]
            self._defined(expr, quantity, args[0], at)
        unit = item.unit.text if item.unit is not None else natural_unit(dim, self.spec.system)
        if item.unit is not None and resolve_unit(item.unit, self.file).dim != dim:
            raise SpecError(
                f"{item.name} is {dim.name}, not in {item.unit.text}",
                where,
                hint=f"use a unit of {dim.name}",
            )
        if dim.dimensionless and item.unit is None:
            unit = "rad"
        target = Target(
            item.name, sympy.Symbol(item.name), dim, unit, item.unit is not None, False, expr=expr
        )
        self.targets[item.name] = target
        return target

    def _quantity(self, name: str, at: Position) -> str:
        available = QUANTITIES[self.components]
        if name in FORCES and FORCES[name] in available:
            return self._force(name, at)
        if name in available:
            if name in ("a_t", "a_n", "rho"):
                self._normal_tangential()
            return name
        other = "r–θ" if self.components == "x–y" else "x–y"
        listed = ", ".join(available)
        if name in QUANTITIES[other]:
            raise SpecError(
                f"{pretty(name)} applies to {other} components, but the motion is given "
                f"in {self.components} components",
                at,
                hint=f"the quantities of this motion: {listed}",
            )
        if name == "t":
            raise SpecError("t(…) is not a quantity", at, "the time at which y = h is t_at(y, h)")
        close = difflib.get_close_matches(name, [*available, "t_at", "max", "min"], n=1)
        hint = f"did you mean '{close[0]}'?" if close else f"the quantities: {listed}"
        raise SpecError(f"'{name}' is not a quantity of plane motion", at, hint)

    def _force(self, name: str, at: Position) -> str:
        """The resultant force on the particle in one component: ΣF = m a."""
        if self.given_dims.get("m") != Dim.of("mass"):
            raise SpecError(
                f"{pretty(name)} = m {pretty(FORCES[name])} needs the particle's mass",
                at,
                hint="give it as 'm = … kg' under given:",
            )
        self._quantity(FORCES[name], at)
        lines = tuple(s.line for s in self.relations.values())
        rule = f"ΣF = m a: {pretty(name)} = m {pretty(FORCES[name])} (resultant force)"
        mass = self._in(self.symbols["m"])
        self._derive(name, tidy(mass * self.formulas[FORCES[name]]), rule, lines)
        return name

    def _value(self, name: str, at: Position) -> tuple[sympy.Expr, Dim]:
        """A given, an initial condition or an earlier find: its value and dimension."""
        if name in self.given_dims:
            return self._in(self.symbols[name]), self.given_dims[name]
        if name == "t_0":
            return self.t0, TIME
        if name in INITIAL and self.components == "x–y":
            return self.initial[name], INITIAL[name]
        if name in self.targets and self.targets[name].expr is not None:
            target = self.targets[name]
            return sympy.Integer(0) + target.expr, target.dim
        later = any(f.name == name for f in self.spec.finds)
        names = sorted({*self.given_dims, *self.targets, "t_0"})
        close = difflib.get_close_matches(name, names, n=1)
        hint = (
            f"list '{name}' before the find that uses it"
            if later
            else f"did you mean '{close[0]}'?"
            if close
            else "declare it under given:"
        )
        raise SpecError(f"'{name}' is neither a given nor an earlier find", at, hint)

    def _time(self, name: str, at: Position) -> sympy.Expr:
        if name == "t":
            return T
        value, dim = self._value(name, at)
        if dim != TIME:
            raise SpecError(
                f"'{name}' is {dim.name}, not a time",
                at,
                hint="evaluate at t, a given time (t_1 = 2 s) or an earlier find t_f = t_at(y, h)",
            )
        return value

    def _solving(self, at: Position, run: Callable[[], Crossings]) -> Crossings:
        """Run crossing_times or extreme_time, turning their ValueError into a SpecError."""
        try:
            return run()
        except ValueError as error:
            message = str(error)
            if "largest value after" in message or "smallest value after" in message:
                hint = (  # a ball thrown downward: highest at the start, no dy/dt = 0
                    "no stationary point after t₀ is that extreme; the value sought may be "
                    "at the start (ask e.g. y(t_0)) or at a later find's time"
                )
            elif "give values" in message:
                hint = "give values to the givens, or ask at a given time"
            else:
                hint = "ask at a given time, e.g. y(t_1)"
            raise SpecError(message, at, hint=hint) from error

    def _defined(self, expr: sympy.Expr, quantity: str, argument: str, at: Position) -> None:
        value = expr.xreplace(self.values)
        if expr.has(sympy.nan, sympy.zoo) or (
            not value.free_symbols and not sympy.N(value).is_finite
        ):
            if quantity == "rho":
                message = f"ρ is infinite at {argument}: the path is straight there (a_n = 0)"
            else:
                message = f"{pretty(quantity)} is undefined at {argument}: the speed is zero there"
            raise SpecError(message, at, hint="ask at another time")

    # ---- what is shown
    def _shown(self, expr: sympy.Expr, dim: Dim) -> tuple[str, str]:
        with_numbers = expr.xreplace(self.values)
        number = None if with_numbers.free_symbols else real_value(with_numbers)
        if number is None:
            rounded = sympy.N(with_numbers, 4)
            return formula_text(rounded), formula_latex(rounded)
        unit = natural_unit(dim, self.spec.system)
        value = convert(number, unit, self.spec.system)
        latex = latex_number(value) + (f"\\,{latex_unit(unit)}" if unit else "")
        return format_quantity(value, unit), latex

    def _discarded(self, roots: tuple[tuple[sympy.Expr, str], ...]) -> tuple[str, ...]:
        return tuple(f"t = {self._shown(t, TIME)[0]}: {why}" for t, why in roots)

    def _formula(self, name: str, expr: sympy.Expr, dim: Dim) -> Formula:
        pretty_names = {s: sympy.Symbol(pretty(n)) for n, s in self.symbols.items()}
        latex_names = {s: latex_name(n) for n, s in self.symbols.items()}
        shown = expr.free_symbols != set()
        text = formula_text(expr, pretty_names) if shown else ""
        latex = formula_latex(expr, latex_names) if shown else ""
        return Formula(name, text, latex, *self._shown(expr, dim))

    def _step(self, index: int, d: Derivation, lines: tuple[int, ...]) -> Step:
        results = (self._formula("t", d.time, TIME),) if d.time is not None else ()
        results += (self._formula(d.name, d.expr, d.dim),)
        return Step(index, d.lines or lines, (d.name,), d.method, results, d.discarded, d.rule)

    def _notes(self, targets: tuple[Target, ...]) -> tuple[tuple[str, str], ...]:
        notes = []
        g = self.symbols["g"]
        a_x, a_y = (self.formulas.get(a) for a in ("a_x", "a_y"))
        if self.put_in and self.components == "x–y":  # the numbers are in: read the letters
            a_x, a_y = (tidy(self.accelerations[a], light=False) for a in ("a_x", "a_y"))
        if a_x == 0 and a_y == -g:
            notes.append(("projectile", "a_x = 0, a_y = −g: the axes move independently"))
        used = any(g in (t.expr or sympy.Integer(0)).free_symbols for t in targets)
        default = next(i for i in self.givens if i.name == "g").given is None
        if used and default:
            value, unit = GRAVITY[self.spec.system]
            notes.append(("standard gravity", f"g = {value} {pretty_unit(unit)} (default)"))
        return (*notes, *unused_note(self.givens, self._read()))

    def _read(self) -> set[str]:
        """The givens' names the motion and the finds read: the relations, the initial
        conditions and t_0, the finds' arguments, and m where a force is asked."""
        read = {n.text for st in self.spec.kinematics for n in iter_names(st.rhs)}
        read |= {*INITIAL, "t_0"}
        for item in self.spec.finds:
            if item.ref is not None:
                read |= set(item.ref.args) | ({"m"} if item.ref.function in FORCES else set())
        return read


def _lhs_hint(name: str) -> str:
    """What to write instead of a left side that is not a component of plane motion."""
    if name in ("a", "v"):
        return f"plane motion takes components: {name}_x = … and {name}_y = …"
    if name in ("s", "s_x", "s_y"):
        return "dynsolve names the position x and y: write 'x = …' and 'y = …'"
    choices = [n for names in AXES.values() for n in names] + ["r", "theta", *INITIAL]
    close = difflib.get_close_matches(name, choices, n=1)
    if close:
        return f"did you mean '{close[0]}'?"
    return "give x = f(t) and y = g(t), a_x and a_y, or r = f(t) and theta = g(t)"


def _note(statement: EquationStmt) -> str:
    """The principle column of a relation without a comment."""
    name = statement.lhs.text if isinstance(statement.lhs, Name) else ""
    return "initial condition" if name in INITIAL else f"{pretty(name)}(t) given"
