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


def test_null_space_of_velocity_constraints() -> None:
    """A disk of radius r rolling on the ground (v_x + r ω = 0, v_y = 0): v = −r ω, so
    the rates per unit ω are (−r, 0, 1), by hand; a block on a cord wound on a pulley
    of radius r, the cord leaving along (cos θ, sin θ) (v·d = r ω, v·n = 0): v = r ω
    (cos θ, sin θ). Numeric mode's elimination gives sympy's null vectors (the free
    column 1), and counts the degrees of freedom as sympy does."""
    import sympy

    from dynsolve.model.states import _null_space
    from dynsolve.numbers import light_tidying

    r, t = sympy.symbols("r theta", positive=True)
    rolling = sympy.Matrix([[1, 0, r], [0, 1, 0]])
    c, s = sympy.cos(t), sympy.sin(t)
    cord = sympy.Matrix([[c, s, -r], [-s, c, 0]])
    free = sympy.Matrix([[1, 0, 0, r]])  # two rates left free: two degrees of freedom
    with light_tidying():
        assert [list(v) for v in _null_space(rolling)] == [[-r, 0, 1]]
        (v,) = _null_space(cord)
        assert [sympy.simplify(e) for e in v] == [r * c, r * s, 1]
        assert len(_null_space(free)) == len(free.nullspace()) == 3


def test_positions_by_elimination_as_linsolve() -> None:
    """A bob on a link of length L from O, moved to hang straight down from θ off the
    vertical: Δx = L sin θ, Δy = L cos θ − L, and the link turns by θ (cos, sin of it),
    by hand; numeric mode's elimination fixes what sympy's linsolve fixes, in the same
    (tidied) forms, leaves a free unknown free, and refuses contradicting equations."""
    import sympy

    from dynsolve.model.states import _by_elimination, _by_linsolve, _tidiest
    from dynsolve.numbers import light_tidying

    L, t = sympy.symbols("L theta", positive=True)
    u, w, c, s, f = sympy.symbols("u w c s f", real=True)
    C, S = sympy.cos(t), sympy.sin(t)
    equations = [
        L * c * S - L * s * C - L * S + u,
        L * c * C + L * s * S - L * C + w,
        u - L * S,
        w + L - L * C,
    ]
    with light_tidying():
        found = _by_elimination(equations, [u, w, c, s, f])
    assert found == {u: L * S, w: L * C - L, c: C, s: S}
    exact = {k: _tidiest(v) for k, v in _by_linsolve(equations, [u, w, c, s, f]).items()}
    assert found == exact
    with light_tidying(), pytest.raises(ValueError, match="cannot reach"):
        _by_elimination([u - 1, u - 2], [u])
