"""Large generated specs solve correctly (issue 14, part 5): long chains of bodies and
equations, dense linear systems with long flat sums, and the nesting bound still refusing
what would overflow the recursion of the tree's walkers. Timings are in bench/scaling.py.
"""

from __future__ import annotations

import random

import pytest

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_text


def block_chain(n: int) -> str:
    """n blocks of mass m on a smooth floor, joined by cords, the last pulled by P."""
    lines = ["given:", "  m = 2 kg", "  P = 10 N", "  w = 1 m", "scene:"]
    for i in range(n):
        lines.append(f"  body b{i}: mass m, block w by w, at ({2 * i}*w, w/2)")
        lines.append(f"  contact b{i} at (0, -w/2): smooth, normal up")
    lines += [f"  cord T{i}: b{i} at G to b{i + 1} at G, right" for i in range(n - 1)]
    lines += [
        f"  force P on b{n - 1} at G: right",
        "  gravity",
        "find: a = a_G(b0) [m/s^2], T0 [N]",
    ]
    return "\n".join(lines) + "\n"


def equation_chain(n: int) -> str:
    lines = ["given:", "  c = 1 m", "  x_0 = 2 m", "equations:"]
    lines += [f"  x_{i} = x_{i - 1} + c" for i in range(1, n + 1)]
    return "\n".join([*lines, f"find: x_{n}"]) + "\n"


def dense_system(n: int, seed: int = 1) -> tuple[str, list[int]]:
    """A diagonally dominant n × n system built from a known integer solution."""
    rng = random.Random(seed)
    solution = [rng.randint(-9, 9) for _ in range(n)]
    lines = ["given:", "  f = 1 N", "equations:"]
    for i in range(n):
        row = [rng.randint(-3, 3) for _ in range(n)]
        row[i] = sum(abs(c) for c in row) + 1
        rhs = sum(c * s for c, s in zip(row, solution, strict=True))
        terms = " + ".join(f"{c}*F_{j}" for j, c in enumerate(row) if c)
        lines.append(f"  {terms} = {rhs}*f")
    lines.append("find: " + ", ".join(f"F_{j}" for j in range(n)))
    return "\n".join(lines) + "\n", solution


def linkage_chain(n: int) -> str:
    """A crank and n − 1 bars in a zigzag, each bar's far end a slider on a horizontal
    guide: joints at (i a, (i mod 2) b), every one placed (no loop closure)."""
    lines = ["given:", "  a = 0.3 m", "  b = 0.1 m", "  w = 2 rad/s", "scene:"]
    lines += ["  point P0: (0, 0)", "  point Q: (0, b)"]
    for i in range(1, n + 1):
        height = "b" if i % 2 else "0"
        lines.append(f"  bar L{i}: P{i - 1} to P{i}")
        lines.append(f"  joint P{i}: ({i}*a, {height})")
        if i > 1:
            lines.append(f"  slider P{i}: along right, through {'Q' if i % 2 else 'P0'}")
    lines += ["  omega L1: w ccw", f"find: v_end = v(P{n}), w_2 = omega(L2)"]
    return "\n".join(lines) + "\n"


def test_a_chain_of_50_bars_moves_as_the_first_slider():
    # by hand: v_P1 = ω k × (a, b) = (−ω b, ω a); bar 2 (r = (a, −b)), P2 horizontal:
    # y: 0 = ω a + ω_2 a -> ω_2 = −ω; x: v_P2 = −ω b − ω_2 (−b) = −2 ω b = −0.4 m/s; every
    # later bar joins two horizontal sliders: ω_i = 0, the same speed.
    solution = solve_text(linkage_chain(50), "linkchain.dyn")
    found = {a.name: a for a in solution.answers}
    assert found["v_end"].value == pytest.approx(0.4, rel=1e-12)
    assert found["v_end"].direction == "left"
    assert found["w_2"].value == pytest.approx(2, rel=1e-12) and found["w_2"].direction == "cw"
    assert not any(check.failed for check in solution.checks)


def test_a_chain_of_40_blocks_accelerates_as_one_mass():
    # the whole chain: P = (n m) a -> a = 10/(40*2) = 0.125 m/s²; the first cord pulls
    # only the first block: T0 = m a = 0.25 N (by hand)
    solution = solve_text(block_chain(40), "chain.dyn")
    values = {a.name: a.value for a in solution.answers}
    assert values["a"] == pytest.approx(0.125, rel=1e-12)
    assert values["T0"] == pytest.approx(0.25, rel=1e-12)
    assert not any(check.failed for check in solution.checks)


def test_a_chain_of_160_equations():
    # x_n = x_0 + n c = 2 + 160 = 162 m
    (answer,) = solve_text(equation_chain(160), "eqchain.dyn").answers
    assert answer.value == pytest.approx(162, rel=1e-12)


def test_a_dense_30_unknown_system_with_30_term_sums():
    text, expected = dense_system(30)
    solution = solve_text(text, "dense.dyn")
    assert [a.value for a in solution.answers] == pytest.approx(expected, rel=1e-12)


def test_a_long_flat_sum_is_not_refused_as_nesting():
    # 200 terms: one flat chain, not 200 levels (a + a + … = 200 a)
    text = "given:\n  a = 1.5 m\nequations:\n  x = " + "+".join(["a"] * 200) + "\nfind: x\n"
    (answer,) = solve_text(text, "sum.dyn").answers
    assert answer.value == pytest.approx(300, rel=1e-12)


@pytest.mark.parametrize("operator", ["+", "*", "/"])
def test_a_chain_past_the_bound_is_a_positioned_error(operator: str):
    # 300 operations of one chain is 50 levels (6 per level): over the bound of 40, refused
    # before any walker of the tree could run out of recursion
    text = "given:\n  a = 1.5 m\nequations:\n  x = " + operator.join(["a"] * 301) + "\nfind: x\n"
    with pytest.raises(SpecError, match="nested more than 40 levels") as caught:
        solve_text(text, "long.dyn")
    assert caught.value.position.line == 4
