"""Put one student's given values (untrusted cell text) into a spec, checked and positioned.

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec("given:\\n  m = 50 kg\\nequations:\\n  W = m*g\\nfind: W\\n", "p.dyn")
>>> with_variant(spec, {"m": "45 kg"}, "s01").givens[0].quantity.text
'45'
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from dataclasses import replace

from dynsolve.errors import DynsolveError, Position, SpecError, UnitError
from dynsolve.quantities import resolve_quantity
from dynsolve.spec.ast import Quantity, Spec
from dynsolve.spec.parser import parse_quantity


class VariantError(SpecError):
    """A student's variant cannot be used: a bad cell, a wrong unit, an unknown given."""


@functools.lru_cache(maxsize=4096)
def read_cell(text: str) -> Quantity:
    """A cell's quantity, parsed once per distinct text (many students share values)."""
    return parse_quantity(text)


def with_variant(
    spec: Spec, cells: Mapping[str, str], student: str, where: Position | None = None
) -> Spec:
    """``spec`` with the givens in ``cells`` replaced and its answer key dropped (the key is
    the base problem's). An empty cell keeps the spec's value."""
    givens = {g.name: g for g in spec.givens}
    replaced = {}
    for name, text in cells.items():
        if not text.strip():
            continue
        given = givens.get(name)
        if given is None or given.quantity is None:
            raise VariantError(
                f"student {student}: '{name}' is not a given with a value in {spec.file}",
                where,
                hint="the variants file must come from this problem",
            )
        try:
            quantity = read_cell(text.strip())
            _, dim = resolve_quantity(quantity, spec.system, spec.file)
            _, expected = resolve_quantity(given.quantity, spec.system, spec.file)
        except DynsolveError as error:
            raise VariantError(
                f"student {student}: cannot read {name} = '{text[:40]}': {error.message}",
                where,
                hint=error.hint,
            ) from None
        if dim != expected:
            raise UnitError(
                f"student {student}: {name} = '{text[:40]}' is {dim.name}, but {name} is "
                f"{expected.name}",
                where,
                hint="write the value in a unit of the given's dimension",
            )
        at = given.quantity  # errors later point at the spec's given
        replaced[name] = replace(given, quantity=replace(quantity, line=at.line, column=at.column))
    return replace(
        spec,
        givens=tuple(replaced.get(g.name, g) for g in spec.givens),
        answers=(),
    )
