"""What the solver returns: blocks in solve order, chosen and discarded roots, residuals.

Plain frozen data; renderers read it, nothing here computes.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Literal

import sympy

Method = Literal["linear", "symbolic", "numeric"]
Status = Literal["solved", "underdetermined", "inconsistent", "no_valid_root", "failed"]


@dataclass(frozen=True)
class DiscardedRoot:
    """A root the solver found but did not keep, and why."""

    values: Mapping[sympy.Symbol, sympy.Expr]
    reason: str  # e.g. "violates omega >= 0 (line 12)" or "not real"


@dataclass(frozen=True)
class Block:
    """One strongly connected block: these equations determine these unknowns together."""

    equations: tuple[int, ...]  # indices into EquationSystem.equations
    unknowns: tuple[sympy.Symbol, ...]
    method: Method
    formulas: Mapping[sympy.Symbol, sympy.Expr]  # in terms of knowns and earlier unknowns
    values: Mapping[sympy.Symbol, sympy.Expr]  # after substituting the knowns
    discarded: tuple[DiscardedRoot, ...] = ()
    note: str = ""  # e.g. "symbolic solve exceeded 5 s budget; solved numerically"


@dataclass(frozen=True)
class Residual:
    """How well one equation holds once every answer is substituted back."""

    equation: int  # index into EquationSystem.equations
    absolute: float  # |lhs - rhs| in base units; nan when not evaluable
    relative: float  # absolute / max(|lhs|, |rhs|, tiny)
    evaluated: bool  # False when the equation still holds a free (symbolic) name


@dataclass(frozen=True)
class Outcome:
    """The solver's answer for an :class:`~dynsolve.system.EquationSystem`."""

    status: Status
    blocks: tuple[Block, ...]
    values: Mapping[sympy.Symbol, sympy.Expr]  # every unknown solved for
    residuals: tuple[Residual, ...] = ()
    undetermined: tuple[sympy.Symbol, ...] = ()  # unknowns no equation pins down
    missing_equations: int = 0  # how many more independent equations they need
    conflicting: tuple[int, ...] = ()  # equation indices that contradict the rest
    redundant: tuple[int, ...] = ()  # consistent but surplus equations
    unneeded: tuple[int, ...] = ()  # equations not needed for the wanted unknowns
    ambiguous: tuple[sympy.Symbol, ...] = ()  # unknowns left with several valid roots
    messages: tuple[str, ...] = field(default_factory=tuple)

    @property
    def max_residual(self) -> float:
        """The largest relative residual over the evaluated equations (0 when none)."""
        rel = [r.relative for r in self.residuals if r.evaluated]
        return max(rel, default=0.0)
