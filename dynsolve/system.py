"""The equation system handed to the solver: equations, unknowns, known values, constraints.

It is plain, immutable data built by every front end (equations, kinematics, scene,
linkage, 3D) and consumed by :func:`dynsolve.solver.solve_system`.

>>> import sympy
>>> T, m, g = sympy.symbols("T m g", positive=True)
>>> eq = Equation(lhs=T, rhs=m * g, label="line 3", line=3)
>>> system = EquationSystem(equations=(eq,), unknowns=(T,), knowns={m: 2, g: 10})
>>> system.unknowns
(T,)
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cached_property
from typing import Literal

import sympy


@dataclass(frozen=True)
class Equation:
    """One governing equation ``lhs = rhs``, with where it came from."""

    lhs: sympy.Expr
    rhs: sympy.Expr
    label: str  # how reports name it, e.g. "line 14" or "ΣF_y (drum)"
    line: int = 0  # source line, 0 when generated
    note: str = ""  # the principle it states, e.g. "ΣM_O = I_O α"

    @cached_property
    def residual(self) -> sympy.Expr:
        """``lhs - rhs``: zero when the equation holds (built once: the solver asks often)."""
        return self.lhs - self.rhs


@dataclass(frozen=True)
class Constraint:
    """A declared sign or range condition on unknowns, e.g. ``omega >= 0``."""

    relation: sympy.core.relational.Relational
    text: str  # as the user wrote it
    line: int = 0


SolveMode = Literal["exact", "numeric", "auto"]


@dataclass(frozen=True)
class SolveOptions:
    """How to solve: exactly, numerically, or ``auto`` (numerically, exact when needed).

    ``exact`` keeps rationals and radicals and only falls back to numbers when a
    nonlinear block exceeds ``time_budget`` seconds; ``numeric`` goes straight to
    floating point root finding; ``auto`` solves numerically, measures the digits
    float64 loses against a 30-digit re-solve and escalates to exact when more than 3 are
    lost (:mod:`dynsolve.precision`).
    """

    mode: SolveMode = "exact"
    time_budget: float = 5.0
    show_formulas: bool = True
    simulate: bool = True  # False: no simulation cross-check (a re-solve read for its answers)


@dataclass(frozen=True)
class EquationSystem:
    """Equations to solve for ``unknowns``; ``knowns`` maps given symbols to values.

    Symbols that are neither unknowns nor in ``knowns`` stay symbolic (a symbolic
    problem); ``wanted`` lists the unknowns the user asked for (all when empty).
    """

    equations: tuple[Equation, ...]
    unknowns: tuple[sympy.Symbol, ...]
    knowns: Mapping[sympy.Symbol, sympy.Expr] = field(default_factory=dict)
    constraints: tuple[Constraint, ...] = ()
    wanted: tuple[sympy.Symbol, ...] = ()
