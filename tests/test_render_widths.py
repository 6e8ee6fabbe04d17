"""The terminal view at 60, 80 and 120 columns: nothing is cut with "…"; every answer,
equation and the file name appear (long ones fold onto the next line, whole)."""

from __future__ import annotations

import io
import re
from functools import cache
from pathlib import Path

import pytest
from rich.cells import cell_len
from rich.console import Console

from dynsolve.pipeline import solve_file
from dynsolve.render.terminal import solution_renderable
from dynsolve.results import Solution

ROOT = Path(__file__).resolve().parent.parent
SEEDS = sorted((ROOT / "problems" / "seed").glob("*.dyn"))
WIDTHS = (60, 80, 120)


@cache
def solved(path: Path) -> Solution:
    return solve_file(path)


def rendered(solution: Solution, width: int) -> str:
    buffer = io.StringIO()
    Console(file=buffer, width=width, color_system=None).print(solution_renderable(solution))
    return buffer.getvalue()


def words(text: str, longest: int) -> list[str]:
    """The words of ``text`` that fit in a narrow column (longer ones may fold mid-word)."""
    return [w for w in re.split(r"\s+", text) if w and len(w) <= longest]


@pytest.mark.parametrize("path", SEEDS, ids=[p.stem for p in SEEDS])
@pytest.mark.parametrize("width", WIDTHS)
def test_nothing_is_cut(path: Path, width: int) -> None:
    solution = solved(path)
    out = rendered(solution, width)
    assert "…" not in out
    assert all(cell_len(line) <= width for line in out.splitlines())
    flat = re.sub(r"\s+", "", out)
    # the file name folds inside the title panel; its characters stay in order, whole
    assert re.sub(r"\s+", "", solution.file) in flat.replace("│", "")
    for answer in solution.answers:
        for word in words(answer.shown, 8):
            assert word in out, (answer.name, word)
    for equation in solution.equations:
        for word in words(equation.text, 8):
            assert word in out, (equation.line, word)


def test_a_scene_without_equations_says_so_instead_of_an_empty_table():
    # Hibbeler 12e Example 20.2 asks only for ω and α: every value is a formula of the
    # givens, so there is no equation to show (was an empty table header)
    path = Path(__file__).parent.parent / "problems" / "rigid3d" / "gyrotop_nutation.dyn"
    console = Console(file=io.StringIO(), width=100, color_system=None)
    console.print(solution_renderable(solve_file(path)))
    text = console.file.getvalue()
    assert "No equations: every value asked follows from the givens." in text
    assert "line  equation  units" not in text
