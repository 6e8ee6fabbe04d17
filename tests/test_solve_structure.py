"""Tests for the structural analysis: matching, Dulmage–Mendelsohn split, block order, pruning."""

from __future__ import annotations

import sympy
from hypothesis import given, settings
from hypothesis import strategies as st

from dynsolve.solver.structure import analyse_structure, maximum_matching
from dynsolve.system import Equation, EquationSystem

x, y, z, w = sympy.symbols("x y z w")


def system_of(
    *pairs: tuple[sympy.Expr, sympy.Expr],
    unknowns: tuple[sympy.Symbol, ...] = (x, y, z),
    wanted: tuple[sympy.Symbol, ...] = (),
) -> EquationSystem:
    equations = tuple(Equation(lhs, rhs, f"eq {i}") for i, (lhs, rhs) in enumerate(pairs))
    return EquationSystem(equations, tuple(unknowns), wanted=tuple(wanted))


def test_triangular_system_is_ordered_from_the_equation_with_one_unknown():
    # z = x + y needs x and y; y = 3x needs x; x = 2 needs nothing.
    structure = analyse_structure(system_of((z, x + y), (x, 2), (y, 3 * x)))
    assert [b.equations for b in structure.blocks] == [(1,), (2,), (0,)]
    assert [b.unknowns for b in structure.blocks] == [(x,), (y,), (z,)]
    assert structure.blocks[2].depends_on == (0, 1)
    assert structure.undetermined == () and structure.surplus == ()


def test_coupled_equations_form_one_block():
    # x and y appear in both of the first two equations; z follows from them.
    structure = analyse_structure(system_of((x + y, 3), (x - y, 1), (z, x * y)))
    assert [b.equations for b in structure.blocks] == [(0, 1), (2,)]
    assert structure.blocks[0].unknowns == (x, y)


def test_underdetermined_part_names_free_unknowns_and_missing_count():
    # x = 1 is fine; y + z = x leaves y and z with one equation for two unknowns;
    # w appears nowhere.
    structure = analyse_structure(system_of((x, 1), (y + z, x), unknowns=(x, y, z, w)))
    assert structure.undetermined == (y, z, w)
    assert structure.underdetermined_equations == (1,)
    assert structure.missing_equations == 2
    assert [b.unknowns for b in structure.blocks] == [(x,)]


def test_overdetermined_part_leaves_the_later_equation_surplus():
    # Two equations for x alone: the second one is left over to be checked.
    structure = analyse_structure(system_of((x, 1), (2 * x, 2), (y, x), unknowns=(x, y)))
    assert structure.surplus == (1,)
    assert structure.overdetermined == (0, 1)
    assert [b.equations for b in structure.blocks] == [(0,), (2,)]


def test_equation_without_unknowns_is_surplus():
    g = sympy.Symbol("g")
    structure = analyse_structure(system_of((x, 1), (g, 10), unknowns=(x,)))
    assert structure.surplus == (1,)


def test_wanted_keeps_only_the_blocks_it_depends_on():
    # y = 2x needs x; z = 5 is independent of y.
    structure = analyse_structure(system_of((x, 1), (y, 2 * x), (z, 5), wanted=(y,)))
    assert [b.unknowns for b in structure.blocks] == [(x,), (y,)]
    assert structure.unneeded == (2,)


def test_wanted_outside_underdetermined_part_drops_it_as_unneeded():
    structure = analyse_structure(system_of((x, 1), (y + z, 4), wanted=(x,)))
    assert structure.undetermined == ()
    assert structure.unneeded == (1,)


def test_wanted_inside_underdetermined_part_keeps_it():
    structure = analyse_structure(system_of((x, 1), (y + z, 4), wanted=(y,)))
    assert structure.undetermined == (y, z)
    assert structure.missing_equations == 1
    assert structure.unneeded == (0,)


def test_maximum_matching_reassigns_along_an_augmenting_path():
    # Row 0 first takes column 0; row 1 can only use column 0, so row 0 moves to 1.
    assert maximum_matching([[0, 1], [0]], 2) == [1, 0]


@st.composite
def incidences(draw: st.DrawFn) -> tuple[list[list[int]], int]:
    n_columns = draw(st.integers(1, 7))
    rows = draw(
        st.lists(st.lists(st.integers(0, n_columns - 1), max_size=4), min_size=1, max_size=8)
    )
    return rows, n_columns


@settings(max_examples=150, deadline=None)
@given(incidences())
def test_blocks_are_square_and_use_only_earlier_unknowns(case: tuple[list[list[int]], int]):
    rows, n_columns = case
    unknowns = sympy.symbols(f"u0:{n_columns}")
    equations = tuple(
        Equation(sympy.Add(*(unknowns[c] for c in set(row))), 1, f"r{i}")
        for i, row in enumerate(rows)
    )
    structure = analyse_structure(EquationSystem(equations, unknowns))
    known: set[sympy.Symbol] = set()
    for block in structure.blocks:
        assert len(block.equations) == len(block.unknowns)
        used = set().union(*(equations[i].residual.free_symbols for i in block.equations))
        assert used <= known | set(block.unknowns)
        known |= set(block.unknowns)
    # Every unknown is either determined by a block or under-determined, never both.
    assert known.isdisjoint(structure.undetermined)
    assert known | set(structure.undetermined) == set(unknowns)
    # Every equation is in a block, in the under-determined part, or surplus.
    placed = [i for b in structure.blocks for i in b.equations]
    placed += list(structure.underdetermined_equations) + list(structure.surplus)
    assert sorted(placed) == list(range(len(equations)))
