"""Givens the problem never reads: a near-miss of a name that was defaulted is an error."""

from __future__ import annotations

import difflib
from collections.abc import Iterable
from typing import TYPE_CHECKING

from dynsolve.errors import Position, SpecError
from dynsolve.spec.ast import FindItem, Name, SceneStmt, Spec, children

if TYPE_CHECKING:
    from dynsolve.modes.equation_mode import GivenInfo


def unused_note(
    givens: Iterable[GivenInfo], used: set[str], expected: Iterable[str] = ()
) -> tuple[tuple[str, str], ...]:
    """A note naming every given that nothing reads (with its line), or no note; a given
    whose name is close to a used or ``expected`` name gets a did-you-mean.

    A given the problem states but does not need (a distractor, a value for a later part)
    is named rather than passed over in silence:

    >>> from dynsolve.modes.equation_mode import givens_of
    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("given:\\n  h = 2 m\\nequations:\\n  y = 1\\nfind: y", "k.dyn")
    >>> unused_note(givens_of(spec), {"y"})
    (('unused givens', 'h (line 2) is given but not used'),)
    >>> spec = parse_spec("given:\\n  h_l = 2 m\\nequations:\\n  y = h_1\\nfind: y", "k.dyn")
    >>> unused_note(givens_of(spec), {"y", "h_1"})[0][1]
    "h_l (line 2; did you mean 'h_1'?) is given but not used"
    """
    choices = sorted(set(used) | set(expected))
    unused = []
    for g in givens:
        if g.given is None or g.name in used:
            continue
        close = difflib.get_close_matches(g.name, [c for c in choices if c != g.name], 1, 0.6)
        mean = f"; did you mean '{close[0]}'?" if close else ""
        unused.append(f"{g.name} (line {g.given.line}{mean})")
    if not unused:
        return ()
    verb = "is" if len(unused) == 1 else "are"
    return (("unused givens", f"{', '.join(unused)} {verb} given but not used"),)


def check_near_misses(
    givens: Iterable[GivenInfo], used: set[str], defaulted: Iterable[str], file: str
) -> None:
    """Raise for a given that is never used while its name is a near miss of a name the
    problem took a default for (a typo ``x0`` for ``x_0`` would be solved with x_0 = 0).
    A near miss differs only in underscores or case.

    >>> from dynsolve.modes.equation_mode import givens_of
    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("given:\\n  x0 = 2 m\\nequations:\\n  y = 1\\nfind: y", "k.dyn")
    >>> try:
    ...     check_near_misses(givens_of(spec), {"y"}, ["x_0"], "k.dyn")
    ... except SpecError as error:
    ...     print(error.hint)
    did you mean 'x_0'?
    """
    missing = list(defaulted)
    for given in givens:
        if given.name in used or given.given is None:
            continue
        close = [n for n in missing if _spelling(n) == _spelling(given.name)]
        if close:
            line, column = (given.given.line, given.given.column) if given.given else (1, 1)
            raise SpecError(
                f"the given '{given.name}' is never used, and {close[0]} is not given "
                f"(it would be taken as 0)",
                Position(file, line, column),
                hint=f"did you mean '{close[0]}'?",
            )


def _spelling(name: str) -> str:
    """A name without underscores, in lower case: ``x0``, ``X_0`` and ``x_0`` agree.

    >>> _spelling("X_0")
    'x0'
    """
    return name.replace("_", "").lower()


def scene_reads(spec: Spec) -> set[str]:
    """Every name a scene spec may read: the names in its scene lines (expressions,
    loads and bodies named), its finds and their arguments, its define lines, and g
    when the scene has gravity or a weight.

    >>> from dynsolve.spec.parser import parse_spec
    >>> text = "given:\\n  m = 2 kg\\n  P = 5 N\\nscene:\\n  body B: particle, mass m\\n"
    >>> text += "  force P on B at B: right\\nfind: a = a(B)"
    >>> sorted(scene_reads(parse_spec(text, "s.dyn")) & {"m", "P", "g"})
    ['P', 'm']
    """
    found: set[str] = set()
    stack: list[object] = [*spec.scene, *spec.defines, *spec.finds]
    while stack:
        node = stack.pop()
        if isinstance(node, Name):
            found.add(node.text)
        elif isinstance(node, SceneStmt):
            found |= {node.name, node.body, node.other}
            if node.kind == "gravity" or any(p.key == "weight" for p in node.props):
                found.add("g")
        elif isinstance(node, FindItem):
            found.add(node.name)
            if node.ref is not None:
                found |= set(node.ref.args)
        stack.extend(children(node))
    return found
