"""The error hierarchy: one root, subclasses carrying a source position and a hint.

Every error a user can cause derives from :class:`DynsolveError`; the CLI catches
that root, prints ``file:line:column: message`` with the hint, and exits with code 2.

>>> err = SpecError("unknown unit 'kgs'", Position("drum.dyn", 3, 12), hint="did you mean 'kg'?")
>>> str(err)
"drum.dyn:3:12: unknown unit 'kgs' (hint: did you mean 'kg'?)"
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TypeVar


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

    def __reduce__(self) -> tuple[object, ...]:
        """Pickle every attribute (position, hint, ``others``), not only the message: errors
        travel from the worker process to the caller."""
        return (_rebuild, (type(self), self.args, self.__dict__))

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


def _rebuild(
    kind: type[DynsolveError], args: tuple[object, ...], state: dict[str, object]
) -> DynsolveError:
    """An error unpickled with all its attributes (see ``DynsolveError.__reduce__``)."""
    error = kind.__new__(kind)
    error.args = args
    error.__dict__.update(state)
    return error


_Error = TypeVar("_Error", bound=DynsolveError)


def with_others(errors: Sequence[_Error]) -> _Error:
    """The first of ``errors``, carrying the rest as ``others`` (the CLI reports them all).

    >>> first = with_others([SpecError("a"), SpecError("b")])
    >>> [str(e) for e in (first, *first.others)]
    ['a', 'b']
    """
    first, *rest = errors
    first.others = [*getattr(first, "others", ()), *rest]  # type: ignore[attr-defined]
    return first


@dataclass(frozen=True)
class ErrorReport:
    """One error as data for the renderers: message, hint, where, and the source line there.

    >>> report = ErrorReport.of(SpecError("bad", Position("a.dyn", 2, 3), "fix"), "x\\n  y = 1\\n")
    >>> report.source, report.as_dict()["column"]
    ('  y = 1', 3)
    """

    message: str
    hint: str = ""
    file: str = ""
    line: int = 0
    column: int = 0
    source: str = ""  # the spec's line at ``line``, "" when unknown

    @classmethod
    def of(cls, error: Exception, text: str | None = None) -> ErrorReport:
        """The report of ``error``; ``text`` is the spec it points into (for the source line)."""
        if not isinstance(error, DynsolveError):
            return cls(str(error))
        where = error.position
        if where is None:
            return cls(error.message, error.hint)
        lines = (text or "").splitlines()
        source = lines[where.line - 1] if 0 < where.line <= len(lines) else ""
        return cls(error.message, error.hint, where.file, where.line, where.column, source)

    @property
    def text(self) -> str:
        """One line: ``file:line:column: message (hint: …)``."""
        where = f"{self.file}:{self.line}:{self.column}: " if self.file else ""
        hint = f" (hint: {self.hint})" if self.hint else ""
        return f"{where}{self.message}{hint}"

    def as_dict(self) -> dict[str, str | int | None]:
        """The JSON form: file, line, column (None when unknown), message, hint."""
        return {
            "file": self.file or None,
            "line": self.line or None,
            "column": self.column or None,
            "message": self.message,
            "hint": self.hint,
        }


def all_errors(error: BaseException) -> list[BaseException]:
    """``error`` and the others it carries (see :func:`with_others`)."""
    return [error, *getattr(error, "others", ())]
