"""How a sheet tags its equations: by spec line on the full sheet, numbered (1), (2), … on
the handout (which has no spec to point at), shared by the LaTeX and HTML renderers.

Each trial and the final solve are numbered separately, continuing one sequence, so a trial's
``line 1`` and the re-solve's ``line 1`` (different equations) never share a number; the
equations one spec line writes (a 3D body's three moment equations) each have their own.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

from dynsolve.format import and_list, lines_phrase
from dynsolve.results import EquationRow, Solution


@dataclass(frozen=True)
class EquationTags:
    """The tags of one solve's equations (a trial's, or the final solve's)."""

    numbers: Mapping[EquationRow, int] | None  # None: tag by spec line
    lines: Mapping[int, tuple[int, ...]] = field(default_factory=dict)  # line -> its numbers

    def tag(self, row: EquationRow) -> str:
        """``(line 3)``, or ``(2)`` on the handout.

        >>> row = EquationRow(3, "T = m a", "T = m a", "", "", True, False)
        >>> EquationTags(None).tag(row), EquationTags({row: 2}).tag(row)
        ('(line 3)', '(2)')
        """
        if self.numbers is None:
            return f"(line {row.line})"
        return f"({self.numbers.get(row, '?')})"

    def phrase(self, lines: Sequence[int], dash: str = "–") -> str:
        """How a step names its equations: ``Equations (lines 3–5) give``, or on the
        handout ``Equations (1), (2) and (4) give``.

        >>> EquationTags({}, {3: (1,), 5: (2,), 9: (4,)}).phrase([9, 3, 5])
        'Equations (1), (2) and (4) give'
        >>> EquationTags(None).phrase([3, 4], "--")
        'Equations (lines 3--4) give'
        """
        if self.numbers is None:
            return lines_phrase(lines, dash)
        shown = sorted({n for line in lines for n in self.lines.get(line, ())})
        if not shown:
            return "The solver gives"
        if len(shown) == 1:
            return f"Equation ({shown[0]}) gives"
        return f"Equations {and_list([f'({n})' for n in shown])} give"

    def untagged(self, text: str) -> str:
        """A solver's note as the sheet shows it: on the handout without its spec-line tags.

        >>> EquationTags({}).untagged("violates Ω > 0 (line 28)")
        'violates Ω > 0'
        >>> EquationTags(None).untagged("violates Ω > 0 (line 28)")
        'violates Ω > 0 (line 28)'
        """
        return text if self.numbers is None else _LINE_TAG.sub("", text)


_LINE_TAG = re.compile(r"\s*\(lines? \d+(?:\s*(?:,|–|-|and)\s*\d+)*\)")
BY_LINE = EquationTags(None)  # the full sheet's tags: each equation's spec line


@dataclass(frozen=True)
class SheetTags:
    """The tags of every solve on a sheet: one per trial, then the final solve's."""

    trials: tuple[EquationTags, ...]
    final: EquationTags


def sheet_tags(solution: Solution, numbered: bool) -> SheetTags:
    """Spec-line tags (``numbered`` False), or numbers in the order the sheet shows the
    equations: each trial's equations and second moment point, then the final solve's.

    >>> from dynsolve.results import Trial
    >>> def row(line, text):
    ...     return EquationRow(line, text, text, "", "", True, False)
    >>> trial = Trial("no slip", (row(1, "F + P = m a"), row(2, "N = m g")), (), "fails")
    >>> final = (row(1, "-μ N + P = m a"), row(4, "a_y = 0"), row(4, "α = 0"))
    >>> sheet = Solution("p.dyn", "", "", "SI", "scene", (), final, (), (), (), (),
    ...                  "solved", trials=(trial,))
    >>> tags = sheet_tags(sheet, numbered=True)
    >>> tags.trials[0].tag(trial.equations[0]), [tags.final.tag(r) for r in final]
    ('(1)', ['(3)', '(4)', '(5)'])
    >>> tags.final.phrase([4])
    'Equations (4) and (5) give'
    >>> sheet_tags(sheet, numbered=False).final.tag(final[1])
    '(line 4)'
    """
    if not numbered:
        return SheetTags(tuple(BY_LINE for _ in solution.trials), BY_LINE)
    count = 0

    def numbered_rows(rows: Sequence[EquationRow]) -> EquationTags:
        nonlocal count
        numbers: dict[EquationRow, int] = {}
        lines: dict[int, tuple[int, ...]] = {}
        for row in rows:
            if row not in numbers:
                count += 1
                numbers[row] = count
                lines[row.line] = (*lines.get(row.line, ()), count)
        return EquationTags(numbers, lines)

    trials = tuple(numbered_rows((*t.equations, *t.second_moments)) for t in solution.trials)
    return SheetTags(trials, numbered_rows((*solution.equations, *solution.second_moments)))
