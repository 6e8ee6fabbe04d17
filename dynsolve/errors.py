"""The error hierarchy: one root, subclasses carrying a source position and a hint.

Every error a user can cause derives from :class:`DynsolveError`; the CLI catches
that root, prints ``file:line:column: message`` with the hint, and exits with code 2.

>>> err = SpecError("unknown unit 'kgs'", Position("drum.dyn", 3, 12), hint="did you mean 'kg'?")
>>> str(err)
"drum.dyn:3:12: unknown unit 'kgs' (hint: did you mean 'kg'?)"
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Position:
    """A place in a spec file: 1-based line and column."""

    file: str
    line: int
    column: int

    def __str__(self) -> str:
        return f"{self.file}:{self.line}:{self.column}"


class DynsolveError(Exception):
    """Root of every error dynsolve raises on bad input."""

    def __init__(self, message: str, position: Position | None = None, hint: str = "") -> None:
        super().__init__(message)
        self.message = message
        self.position = position
        self.hint = hint

    def __str__(self) -> str:
        where = f"{self.position}: " if self.position else ""
        hint = f" (hint: {self.hint})" if self.hint else ""
        return f"{where}{self.message}{hint}"


class SpecError(DynsolveError, ValueError):
    """The spec text is malformed: syntax, unknown names, units or bounds."""


class UnitError(DynsolveError, ValueError):
    """A unit is unknown or not usable where it was written."""


class DimensionError(DynsolveError, ValueError):
    """An equation is not dimensionally homogeneous, or a dimension cannot be inferred."""


class SolveError(DynsolveError, ArithmeticError):
    """The equation system cannot be solved as posed (under- or over-determined)."""
