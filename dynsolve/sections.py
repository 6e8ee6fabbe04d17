"""Combine an ``equations:`` section with a ``kinematics:`` or ``scene:`` section.

Beside a motion or a scene, an equation may only define a new quantity from givens,
finds and earlier definitions (``c_w = y_w - h``): it becomes a ``define:`` line
(:mod:`dynsolve.derived`), dimension-checked and reported like one. Anything else (an
equation to be solved, a relation, a given redefined) cannot join a motion that is
integrated or a scene whose equations dynsolve writes, and is a positioned error
rather than a section silently ignored.

>>> from dynsolve.spec.parser import parse_spec
>>> text = "given:\\n  h = 1 m\\nkinematics:\\n  x = h\\nequations:\\n  c = x_1 - h\\n"
>>> text += "find: x_1 = x(t)"
>>> spec = combine_sections(parse_spec(text, "k.dyn"))
>>> [line.lhs.text for line in spec.defines], spec.equations
(['c'], ())
"""

from __future__ import annotations

from dataclasses import replace

from dynsolve.errors import Position, SpecError
from dynsolve.spec.ast import Name, Spec


def combine_sections(spec: Spec) -> Spec:
    """``spec`` with its ``equations:`` lines turned into ``define:`` lines when it also
    has a ``kinematics:`` or ``scene:`` section; a SpecError at the first line that is
    not a definition ``NAME = EXPRESSION`` of a new name."""
    if not spec.equations or not (spec.kinematics or spec.scene):
        return spec
    section = "kinematics:" if spec.kinematics else "scene:"
    taken = {g.name for g in spec.givens}
    finds = {item.name for item in spec.finds if item.ref is not None}
    defined = {line.lhs.text for line in spec.defines}  # type: ignore[union-attr]
    hint = (
        f"beside {section} an equation defines a new quantity from givens and finds, "
        "e.g. 'c_w = y_w - h' (list it in find); a system to solve belongs in a spec "
        "of its own (equation mode)"
    )
    for line in spec.equations:
        where = Position(spec.file, line.line, line.column)
        head = f"the equations: section cannot be combined with the {section} section"
        if line.relation != "=" or not isinstance(line.lhs, Name):
            raise SpecError(
                f"{head}: line {line.line} is not a definition NAME = expression",
                where,
                hint=hint,
            )
        name = line.lhs.text
        if name in taken or name in finds or name in defined:
            what = "a given" if name in taken else "a find" if name in finds else "defined"
            raise SpecError(
                f"{head}: '{name}' is already {what}, so line {line.line} would be an "
                "equation to solve, not a definition",
                where,
                hint=hint,
            )
        defined.add(name)
    return replace(spec, defines=(*spec.defines, *spec.equations), equations=())
