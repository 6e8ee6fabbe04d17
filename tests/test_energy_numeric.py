"""Work and energy of a mechanism in numeric mode (:mod:`dynsolve.principles.work_energy`):
its rates are tidied as in exact mode before T2 is composed of them, and the
constant-acceleration second method is Newton–Euler with the numbers put in."""

from __future__ import annotations

from pathlib import Path

import pytest

from dynsolve.pipeline import solve_file
from dynsolve.system import SolveOptions

ROOT = Path(__file__).resolve().parent.parent
PULLEY = ROOT / "problems" / "scenes" / "incline_pulley_hanging_block.dyn"


@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_block_pulley_block_energy_and_second_method(mode: str) -> None:
    """Hibbeler ch. 18 style (the problem's header): T2 = ½ (m_A + m_B + ½ m_p) v²
    (the pulley, a disk, turns at v/r), v = √(195.2379/16.5) = 3.439854 m/s, found
    again by v² = 2 a s with a from Newton–Euler at state 1."""
    solution = solve_file(PULLEY, SolveOptions(mode=mode))
    (T2,) = [term for term in solution.energy if term.name == "T2"]
    shown = {  # exact mode tidies the row as well
        "exact": "v_2_B^2*(2*m_A + 2*m_B + m_p)/4",
        "numeric": "m_A*v_2_B^2/2 + m_B*v_2_B^2/2 + m_p*v_2_B^2/4",
    }
    assert T2.formula == shown[mode]
    (second,) = [c for c in solution.checks if c.name.startswith("second method")]
    assert second.passed and "3.439854" in second.detail
