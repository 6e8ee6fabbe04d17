"""The equation solver: structure analysis, block-by-block solve, root choice, residuals.

:func:`solve_system` never raises for a mathematically bad system; the verdict is
``Outcome.status``: ``solved``, ``underdetermined`` (``undetermined`` and
``missing_equations`` say what is missing; everything determined is still solved),
``inconsistent`` (``conflicting`` equations), ``no_valid_root`` (every root of some
block was discarded) or ``failed`` (no root could be found).

>>> import sympy
>>> from dynsolve.system import Equation, EquationSystem
>>> F, m, a = sympy.symbols("F m a")
>>> system = EquationSystem((Equation(F, m * a, "ΣF = m a"),), (a,), {F: 10, m: 4})
>>> outcome = solve_system(system)
>>> outcome.status, outcome.values[a], outcome.blocks[0].formulas[a]
('solved', 5/2, F/m)
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

import sympy

from dynsolve.magnitude import Bound, OutOfRange, bound, value_bound
from dynsolve.solver.blocks import DEFAULT_OPTIONS, BlockSolution, as_expr, solve_block
from dynsolve.solver.outcome import Block, Outcome, Status
from dynsolve.solver.residuals import all_residuals, equation_residual, is_satisfied
from dynsolve.solver.roots import RootChoice, choose_root
from dynsolve.solver.structure import StructuralBlock, Structure, analyse_structure
from dynsolve.system import Constraint, Equation, EquationSystem, SolveOptions

__all__ = ["solve_system"]


@dataclass
class _Progress:
    """What the block-by-block solve has established so far."""

    given: dict[sympy.Symbol, sympy.Expr]  # knowns, then every solved unknown
    blocks: list[Block] = field(default_factory=list)
    solved: dict[sympy.Symbol, sympy.Expr] = field(default_factory=dict)
    undetermined: set[sympy.Symbol] = field(default_factory=set)
    unsolved: set[sympy.Symbol] = field(default_factory=set)  # not solved for any reason
    missing_equations: int = 0
    conflicting: set[int] = field(default_factory=set)
    ambiguous: list[sympy.Symbol] = field(default_factory=list)
    no_valid_root: bool = False
    failed: bool = False
    messages: list[str] = field(default_factory=list)
    bounds: dict[sympy.Symbol, Bound] = field(default_factory=dict)  # of every value in given


def solve_system(system: EquationSystem, options: SolveOptions = DEFAULT_OPTIONS) -> Outcome:
    """Solve ``system`` block by block and check the answers against every equation.

    >>> import sympy
    >>> from dynsolve.system import Equation, EquationSystem
    >>> x, y = sympy.symbols("x y")
    >>> eqs = (Equation(x + y, 3, "a"), Equation(x, 1, "b"), Equation(y, 5, "c"))
    >>> outcome = solve_system(EquationSystem(eqs, (x, y)))
    >>> outcome.status, outcome.conflicting
    ('inconsistent', (2,))
    """
    structure = analyse_structure(system)
    progress = _Progress(given={k: as_expr(v) for k, v in system.knowns.items()})
    progress.bounds = {k: value_bound(v) for k, v in progress.given.items()}
    progress.undetermined |= set(structure.undetermined)
    progress.unsolved |= set(structure.undetermined)
    progress.missing_equations = structure.missing_equations
    for block in structure.blocks:
        _solve_structural_block(block, system, structure, options, progress)
    try:
        _check_magnitudes(range(len(system.equations)), system, progress)
    except OutOfRange as error:
        if options.mode == "exact":
            raise
        raise OutOfRange(  # exact mode keeps a solved value exact, so its powers stay exact
            error.message, error.line, error.column, f"{error.hint}; or try --mode exact"
        ) from None
    quick = options.mode == "numeric"  # residuals in mpmath, node by node
    redundant = _check_surplus(structure.surplus, system, progress, quick)
    unsolved = set(system.unknowns) - set(progress.solved)
    return Outcome(
        status=_status(progress),
        blocks=tuple(progress.blocks),
        values={u: progress.solved[u] for u in system.unknowns if u in progress.solved},
        residuals=all_residuals(system.equations, progress.given, unsolved, quick),
        undetermined=tuple(u for u in system.unknowns if u in progress.undetermined),
        missing_equations=progress.missing_equations,
        conflicting=tuple(sorted(progress.conflicting)),
        redundant=redundant,
        unneeded=structure.unneeded,
        ambiguous=tuple(progress.ambiguous),
        messages=tuple(_structure_messages(structure, system) + progress.messages),
    )


def _solve_structural_block(
    block: StructuralBlock,
    system: EquationSystem,
    structure: Structure,
    options: SolveOptions,
    progress: _Progress,
) -> None:
    """Solve one block with everything earlier substituted, choose its root, record it."""
    residuals = [system.equations[i].residual for i in block.equations]
    needs = set().union(*(r.free_symbols for r in residuals)) - set(block.unknowns)
    blocked = sorted(needs & progress.unsolved, key=str)
    if blocked:
        _skip(block, blocked, progress)
        return
    _check_magnitudes(block.equations, system, progress)
    solution = solve_block(residuals, block.unknowns, progress.given, options)
    determined = [u for u in block.unknowns if u not in solution.free]
    choice = choose_root(
        solution.candidates,
        determined,
        residuals,
        progress.given,
        _constraints_for(determined, system, progress),
        _checks_for(determined, structure.surplus, system, progress),
    )
    progress.blocks.append(_block(block, solution, choice))
    _record(block, solution, choice, progress)
    try:
        progress.bounds.update({u: value_bound(v) for u, v in choice.values.items()})
    except OutOfRange as error:
        raise error.at(system.equations[block.equations[0]].line, 0) from None


def _check_magnitudes(indices: Iterable[int], system: EquationSystem, progress: _Progress) -> None:
    """Refuse, before substituting, values that would make an equation's numbers too large."""
    for i in indices:
        equation = system.equations[i]
        try:
            bound(equation.residual, progress.bounds)
        except OutOfRange as error:
            raise error.at(equation.line, 0) from None  # the column is the spec's


def _skip(block: StructuralBlock, blocked: list[sympy.Symbol], progress: _Progress) -> None:
    """A block that needs an unknown no earlier block could provide."""
    names = ", ".join(map(str, block.unknowns))
    causes = ", ".join(map(str, blocked))
    progress.unsolved |= set(block.unknowns)
    if set(blocked) & progress.undetermined:
        progress.undetermined |= set(block.unknowns)
    progress.messages.append(f"{names}: not solved, needs {causes}, which is not solved")


def _block(block: StructuralBlock, solution: BlockSolution, choice: RootChoice) -> Block:
    return Block(
        equations=block.equations,
        unknowns=block.unknowns,
        method=solution.method,
        formulas=dict(choice.formulas),
        values=dict(choice.values),
        discarded=choice.discarded,
        note=solution.note,
    )


def _record(
    block: StructuralBlock, solution: BlockSolution, choice: RootChoice, progress: _Progress
) -> None:
    """Fold one block's result into the progress: values, or why there are none."""
    progress.solved.update(choice.values)
    progress.given.update(choice.values)
    progress.unsolved |= set(block.unknowns) - set(choice.values)
    progress.undetermined |= set(solution.free)
    progress.missing_equations += solution.missing_equations
    progress.ambiguous.extend(choice.ambiguous)
    if solution.inconsistent:
        progress.conflicting |= set(block.equations)
    elif not choice.values and len(solution.free) < len(block.unknowns):
        if solution.candidates:
            progress.no_valid_root = True
            progress.messages.append(f"no root of {_names(block)} survives the checks")
        else:
            progress.failed = True
            progress.messages.append(f"no root found for {_names(block)}: {solution.note}")


def _names(block: StructuralBlock) -> str:
    return ", ".join(map(str, block.unknowns))


def _constraints_for(
    unknowns: list[sympy.Symbol], system: EquationSystem, progress: _Progress
) -> list[Constraint]:
    """Declared constraints on these unknowns whose other unknowns are already solved."""
    if not system.constraints:
        return []  # (the pending set below is n per block: n² in big scenes)
    mine, pending = set(unknowns), set(system.unknowns) - set(progress.solved) - set(unknowns)
    return [
        c
        for c in system.constraints
        if c.relation.free_symbols & mine and not c.relation.free_symbols & pending
    ]


def _checks_for(
    unknowns: list[sympy.Symbol],
    surplus: tuple[int, ...],
    system: EquationSystem,
    progress: _Progress,
) -> list[tuple[int, Equation]]:
    """Surplus equations on these unknowns whose other unknowns are already solved."""
    if not surplus:
        return []
    mine, pending = set(unknowns), set(system.unknowns) - set(progress.solved) - set(unknowns)
    chosen = []
    for i in surplus:
        names = system.equations[i].residual.free_symbols
        if names & mine and not names & pending:
            chosen.append((i, system.equations[i]))
    return chosen


def _check_surplus(
    surplus: tuple[int, ...], system: EquationSystem, progress: _Progress, quick: bool = False
) -> tuple[int, ...]:
    """Substitute the answers into the surplus equations: redundant or conflicting."""
    unsolved = set(system.unknowns) - set(progress.solved)
    redundant = []
    for i in surplus:
        equation = system.equations[i]
        verdict = is_satisfied(equation_residual(i, equation, progress.given, unsolved, quick))
        if verdict is True:
            redundant.append(i)
        elif verdict is False:
            progress.conflicting.add(i)
        else:
            label = system.equations[i].label
            progress.messages.append(f"{label} could not be checked: it holds unsolved unknowns")
    return tuple(redundant)


def _status(progress: _Progress) -> Status:
    if progress.conflicting:
        return "inconsistent"
    if progress.no_valid_root:
        return "no_valid_root"
    if progress.failed:
        return "failed"
    if progress.undetermined:
        return "underdetermined"
    return "solved"


def _structure_messages(structure: Structure, system: EquationSystem) -> list[str]:
    """Plain-language notes on what the structure analysis found."""
    messages = []
    if structure.undetermined:
        names = ", ".join(map(str, structure.undetermined))
        count = structure.missing_equations
        plural = "s" if count != 1 else ""
        messages.append(f"{names} need {count} more independent equation{plural}")
    return messages  # equations not needed: the "model only what is asked" check says so
