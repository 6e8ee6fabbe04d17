"""How a sheet tags its equations: by spec line on the full sheet, numbered (1), (2), … on
the handout (which has no spec to point at), shared by the LaTeX and HTML renderers.

Each trial and the final solve are numbered separately, continuing one sequence, so a trial's
``line 1`` and the re-solve's ``line 1`` (different equations) never share a number.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from dynsolve.format import and_list, lines_phrase
from dynsolve.results import EquationRow, Solution


@dataclass(frozen=True)
class EquationTags:
    """The tags of one solve's equations (a trial's, or the final solve's)."""

    numbers: dict[int, int] | None  # spec line -> number; None: tag by spec line

    def tag(self, line: int) -> str:
        """``(line 3)``, or ``(2)`` on the handout.

        >>> EquationTags(None).tag(3), EquationTags({3: 2}).tag(3)
        ('(line 3)', '(2)')
        """
        return f"(line {line})" if self.numbers is None else f"({self.numbers.get(line, '?')})"

    def phrase(self, lines: Sequence[int], dash: str = "–") -> str:
        """How a step names its equations: ``Equations (lines 3–5) give``, or on the
        handout ``Equations (1), (2) and (4) give``.

        >>> EquationTags({3: 1, 5: 2, 9: 4}).phrase([9, 3, 5])
        'Equations (1), (2) and (4) give'
        >>> EquationTags(None).phrase([3, 4], "--")
        'Equations (lines 3--4) give'
        """
        if self.numbers is None:
            return lines_phrase(lines, dash)
        shown = sorted({self.numbers[n] for n in lines if n in self.numbers})
        if not shown:
            return "The solver gives"
        if len(shown) == 1:
            return f"Equation ({shown[0]}) gives"
        return f"Equations {and_list([f'({n})' for n in shown])} give"


BY_LINE = EquationTags(None)  # the full sheet's tags: each equation's spec line


@dataclass(frozen=True)
class SheetTags:
    """The tags of every solve on a sheet: one per trial, then the final solve's."""

    trials: tuple[EquationTags, ...]
    final: EquationTags


def sheet_tags(solution: Solution, numbered: bool) -> SheetTags:
    """Spec-line tags (``numbered`` False), or numbers in the order the sheet shows the
    equations: each trial's equations and second moment point, then the final solve's.

    >>> from dynsolve.results import EquationRow, Solution, Trial
    >>> def row(line):
    ...     return EquationRow(line, "", "", "", "", True, False)
    >>> trial = Trial("no slip", (row(1), row(2)), (), "fails")
    >>> sheet = Solution("p.dyn", "", "", "SI", "scene", (), (row(1), row(4)), (), (), (), (),
    ...                  "solved", trials=(trial,))
    >>> tags = sheet_tags(sheet, numbered=True)
    >>> tags.trials[0].tag(1), tags.final.tag(1), tags.final.tag(4)
    ('(1)', '(3)', '(4)')
    >>> sheet_tags(sheet, numbered=False).final.tag(4)
    '(line 4)'
    """
    if not numbered:
        return SheetTags(tuple(BY_LINE for _ in solution.trials), BY_LINE)
    count = 0

    def numbers(rows: Sequence[EquationRow]) -> EquationTags:
        nonlocal count
        found: dict[int, int] = {}
        for row in rows:
            if row.line not in found:
                count += 1
                found[row.line] = count
        return EquationTags(found)

    trials = tuple(numbers((*t.equations, *t.second_moments)) for t in solution.trials)
    return SheetTags(trials, numbers((*solution.equations, *solution.second_moments)))
