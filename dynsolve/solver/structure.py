"""Structural analysis: which equations determine which unknowns, and in what order.

Only the *pattern* of the system is used (which unknowns occur in which equation),
never the values. The steps are:

1. the bipartite incidence of equations and unknowns;
2. a maximum matching (augmenting paths, breadth first);
3. the Dulmage–Mendelsohn split: unknowns reachable by alternating paths from an
   unmatched unknown form the *under-determined* part, equations reachable from an
   unmatched equation the *over-determined* part, the rest is *well determined*;
4. the determined pairs (well-determined part and the matched core of the
   over-determined part) ordered into strongly connected blocks, each block using
   only unknowns of itself and of earlier blocks.

The unmatched equations of the over-determined part are *surplus*: nothing is
left for them to determine, so the solver only checks them afterwards.

>>> import sympy
>>> from dynsolve.system import Equation, EquationSystem
>>> x, y = sympy.symbols("x y")
>>> system = EquationSystem(
...     equations=(Equation(x + y, 3, "eq 1"), Equation(x, 1, "eq 2")), unknowns=(x, y))
>>> [block.equations for block in analyse_structure(system).blocks]
[(1,), (0,)]
"""

from __future__ import annotations

import heapq
from collections import deque
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import sympy
from sympy.utilities.iterables import strongly_connected_components

from dynsolve.system import EquationSystem


@dataclass(frozen=True)
class StructuralBlock:
    """A square set of equations that must be solved together for its unknowns."""

    equations: tuple[int, ...]  # indices into EquationSystem.equations, ascending
    unknowns: tuple[sympy.Symbol, ...]  # in the order of EquationSystem.unknowns
    depends_on: tuple[int, ...] = ()  # indices of earlier blocks in Structure.blocks


@dataclass(frozen=True)
class Structure:
    """The structural verdict on an equation system, with the determined part in solve order."""

    blocks: tuple[StructuralBlock, ...]  # determined blocks in a valid solve order
    surplus: tuple[int, ...] = ()  # over-determined equations left unmatched: checks only
    overdetermined: tuple[int, ...] = ()  # every equation of the over-determined part
    undetermined: tuple[sympy.Symbol, ...] = ()  # unknowns of the under-determined part
    underdetermined_equations: tuple[int, ...] = ()  # equations of the under-determined part
    missing_equations: int = 0  # unknowns minus equations in the under-determined part
    unneeded: tuple[int, ...] = ()  # equations the wanted unknowns do not depend on


def incidence(system: EquationSystem) -> tuple[frozenset[int], ...]:
    """For each equation, the indices of the unknowns it contains.

    >>> import sympy
    >>> from dynsolve.system import Equation, EquationSystem
    >>> x, y, k = sympy.symbols("x y k")
    >>> system = EquationSystem((Equation(k * x, y, "a"), Equation(x, 2, "b")), (x, y), {k: 3})
    >>> [sorted(row) for row in incidence(system)]
    [[0, 1], [0]]
    """
    position = {unknown: i for i, unknown in enumerate(system.unknowns)}
    return tuple(
        frozenset(position[s] for s in equation.residual.free_symbols if s in position)
        for equation in system.equations
    )


def maximum_matching(rows: Sequence[Iterable[int]], n_columns: int) -> list[int]:
    """A maximum matching of rows (equations) to columns (unknowns); -1 marks unmatched.

    Rows are matched in order by breadth-first augmenting paths, so when equations
    compete for the same unknowns the later ones are the ones left over.

    >>> maximum_matching([[0, 1], [0], [0]], 2)
    [1, 0, -1]
    """
    adjacency = [sorted(row) for row in rows]
    row_of = [-1] * n_columns
    column_of = [-1] * len(adjacency)
    for root in range(len(adjacency)):
        _augment(root, adjacency, row_of, column_of)
    return column_of


def _augment(
    root: int, adjacency: list[list[int]], row_of: list[int], column_of: list[int]
) -> None:
    """Grow the matching by one augmenting path starting at ``root``, if there is one."""
    reached_from: dict[int, int] = {}
    queue = deque([root])
    while queue:
        row = queue.popleft()
        for column in adjacency[row]:
            if column in reached_from:
                continue
            reached_from[column] = row
            if row_of[column] == -1:
                _flip_path(column, reached_from, row_of, column_of)
                return
            queue.append(row_of[column])


def _flip_path(
    column: int, reached_from: dict[int, int], row_of: list[int], column_of: list[int]
) -> None:
    """Swap matched and unmatched edges along the path that ends at a free ``column``."""
    while column != -1:
        row = reached_from[column]
        previous = column_of[row]
        column_of[row], row_of[column] = column, row
        column = previous


def _under_part(
    free_columns: Iterable[int], rows: Sequence[frozenset[int]], column_of: list[int]
) -> tuple[set[int], set[int]]:
    """Rows and columns reachable by alternating paths from the unmatched columns.

    The path goes column → any row containing it → that row's matched column.
    """
    rows_with = _rows_with_column(rows)
    columns, reached_rows = set(free_columns), set()
    queue = deque(columns)
    while queue:
        for r in rows_with.get(queue.popleft(), ()):
            if r not in reached_rows:
                reached_rows.add(r)
                if column_of[r] != -1 and column_of[r] not in columns:
                    columns.add(column_of[r])
                    queue.append(column_of[r])
    return reached_rows, columns


def _over_part(
    free_rows: Iterable[int], rows: Sequence[frozenset[int]], row_of: list[int]
) -> set[int]:
    """Rows reachable by alternating paths from the unmatched rows.

    The path goes row → any of its columns → that column's matched row.
    """
    reached = set(free_rows)
    queue = deque(reached)
    while queue:
        for c in rows[queue.popleft()]:
            r = row_of[c]
            if r != -1 and r not in reached:
                reached.add(r)
                queue.append(r)
    return reached


def _rows_with_column(rows: Sequence[frozenset[int]]) -> dict[int, list[int]]:
    """Invert the incidence: for each column, the rows containing it."""
    inverse: dict[int, list[int]] = {}
    for r, columns in enumerate(rows):
        for c in columns:
            inverse.setdefault(c, []).append(r)
    return inverse


def _order_blocks(
    pairs: dict[int, int], rows: Sequence[frozenset[int]], row_of: list[int]
) -> list[tuple[list[int], list[int]]]:
    """Group matched (row, column) pairs into strongly connected blocks in solve order.

    Row ``r`` depends on row ``row_of[c]`` for every other column ``c`` it contains.
    Among blocks ready to solve, the one with the smallest equation index goes first.
    """
    vertices = sorted(pairs)
    edges = [
        (r, row_of[c]) for r in vertices for c in rows[r] if c != pairs[r] and row_of[c] in pairs
    ]
    components = [sorted(comp) for comp in strongly_connected_components((vertices, edges))]
    component_of = {r: i for i, comp in enumerate(components) for r in comp}
    needs: list[set[int]] = [set() for _ in components]
    for r, dependency in edges:
        if component_of[r] != component_of[dependency]:
            needs[component_of[r]].add(component_of[dependency])
    users: list[list[int]] = [[] for _ in components]
    for i, required in enumerate(needs):
        for j in required:
            users[j].append(i)
    waiting = [len(required) for required in needs]
    ready = [(comp[0], i) for i, comp in enumerate(components) if not waiting[i]]
    heapq.heapify(ready)
    ordered: list[tuple[list[int], list[int]]] = []
    while ready:
        _, i = heapq.heappop(ready)
        ordered.append((components[i], sorted(pairs[r] for r in components[i])))
        for j in users[i]:
            waiting[j] -= 1
            if not waiting[j]:
                heapq.heappush(ready, (components[j][0], j))
    return ordered


def _block_dependencies(
    ordered: list[tuple[list[int], list[int]]], rows: Sequence[frozenset[int]]
) -> list[tuple[int, ...]]:
    """For each ordered block, the earlier blocks whose unknowns its equations use."""
    block_of_column = {c: i for i, (_, columns) in enumerate(ordered) for c in columns}
    result = []
    for i, (block_rows, _) in enumerate(ordered):
        used = {block_of_column[c] for r in block_rows for c in rows[r] if c in block_of_column}
        result.append(tuple(sorted(used - {i})))
    return result


def _needed_blocks(blocks: Sequence[StructuralBlock], wanted: set[sympy.Symbol]) -> set[int]:
    """Indices of the blocks holding wanted unknowns, plus everything they depend on."""
    stack = [i for i, block in enumerate(blocks) if wanted & set(block.unknowns)]
    needed: set[int] = set()
    while stack:
        i = stack.pop()
        if i not in needed:
            needed.add(i)
            stack.extend(blocks[i].depends_on)
    return needed


def _prune_to_wanted(
    structure: Structure, system: EquationSystem, rows: Sequence[frozenset[int]]
) -> Structure:
    """Keep only what the wanted unknowns depend on; the rest becomes ``unneeded``."""
    wanted = set(system.wanted)
    needed = _needed_blocks(structure.blocks, wanted)
    renumber = {old: new for new, old in enumerate(sorted(needed))}
    kept = [
        StructuralBlock(b.equations, b.unknowns, tuple(renumber[d] for d in b.depends_on))
        for i, b in enumerate(structure.blocks)
        if i in needed
    ]
    unneeded = {e for i, b in enumerate(structure.blocks) if i not in needed for e in b.equations}
    position = {u: i for i, u in enumerate(system.unknowns)}  # not .index: n² in big scenes
    solved = {position[u] for b in kept for u in b.unknowns}
    surplus = tuple(e for e in structure.surplus if rows[e] <= solved)
    unneeded |= set(structure.surplus) - set(surplus)
    under_needed = bool(wanted & set(structure.undetermined))
    if not under_needed:
        unneeded |= set(structure.underdetermined_equations)
    return Structure(
        blocks=tuple(kept),
        surplus=surplus,
        overdetermined=tuple(e for e in structure.overdetermined if e not in unneeded),
        undetermined=structure.undetermined if under_needed else (),
        underdetermined_equations=structure.underdetermined_equations if under_needed else (),
        missing_equations=structure.missing_equations if under_needed else 0,
        unneeded=tuple(sorted(unneeded)),
    )


def analyse_structure(system: EquationSystem) -> Structure:
    """Split ``system`` into under-, over- and well-determined parts and order the blocks.

    When ``system.wanted`` is non-empty only the blocks the wanted unknowns depend on
    (transitively) are kept; the other equations are reported as ``unneeded``.

    >>> import sympy
    >>> from dynsolve.system import Equation, EquationSystem
    >>> x, y, z = sympy.symbols("x y z")
    >>> eqs = (Equation(x, 1, "a"), Equation(x, 2, "b"), Equation(y + z, 1, "c"))
    >>> structure = analyse_structure(EquationSystem(eqs, (x, y, z)))
    >>> structure.surplus, structure.undetermined, structure.missing_equations
    ((1,), (y, z), 1)
    """
    rows = incidence(system)
    n_unknowns = len(system.unknowns)
    column_of = maximum_matching(rows, n_unknowns)
    row_of = [-1] * n_unknowns
    for r, c in enumerate(column_of):
        if c != -1:
            row_of[c] = r
    free_columns = [c for c in range(n_unknowns) if row_of[c] == -1]
    free_rows = [r for r in range(len(rows)) if column_of[r] == -1]
    under_rows, under_columns = _under_part(free_columns, rows, column_of)
    over_rows = _over_part(free_rows, rows, row_of)
    pairs = {r: c for r, c in enumerate(column_of) if c != -1 and r not in under_rows}
    ordered = _order_blocks(pairs, rows, row_of)
    dependencies = _block_dependencies(ordered, rows)
    blocks = tuple(
        StructuralBlock(tuple(r), tuple(system.unknowns[c] for c in cs), deps)
        for (r, cs), deps in zip(ordered, dependencies, strict=True)
    )
    structure = Structure(
        blocks=blocks,
        surplus=tuple(free_rows),
        overdetermined=tuple(sorted(over_rows)),
        undetermined=tuple(system.unknowns[c] for c in sorted(under_columns)),
        underdetermined_equations=tuple(sorted(under_rows)),
        missing_equations=len(free_columns),
    )
    return _prune_to_wanted(structure, system, rows) if system.wanted else structure
