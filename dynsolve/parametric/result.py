"""A sweep for Python: its givens and answers as pint quantity arrays, shaped as passed.

>>> import numpy as np
>>> from dynsolve.spec.parser import parse_spec
>>> from dynsolve.parametric.evaluate import sweep_points
>>> from dynsolve.parametric.ranges import Axis
>>> text = "given:\\n  m = 2 kg\\n  F = 10 N\\nequations:\\n  F = m*a\\nfind: a"
>>> axis = Axis("m", "kg", np.array([1.0, 2.0, 4.0, 5.0]), 1.0)
>>> result = SweepResult(sweep_points(parse_spec(text, "p.dyn"), (axis,), (axis.values,), (2, 2)))
>>> result["a"]
<Quantity([[10.   5. ]
 [ 2.5  2. ]], 'meter / second ** 2')>
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from dynsolve.parametric.evaluate import Sweep

if TYPE_CHECKING:
    import pint


@dataclass(frozen=True)
class SweepResult:
    """Every point of a sweep. ``result["alpha"]`` is a pint quantity array (an answer in
    its display unit, a magnitude where ``directions`` states a sense; or a swept given),
    shaped as the values passed (a grid for ranges); NaN where a point has no answer
    (``notes`` says why). ``regime`` and ``path`` say, per point, which assumptions fail
    there and whether the closed form or a full solve answered it."""

    sweep: Sweep

    @property
    def shape(self) -> tuple[int, ...]:
        """The shape of every array."""
        return self.sweep.shape

    @property
    def answers(self) -> dict[str, pint.Quantity]:
        """Every answer by name."""
        from dynsolve.units import registry

        ureg = registry()
        return {
            a.name: ureg.Quantity(a.values.reshape(self.shape), a.unit or "dimensionless")
            for a in self.sweep.answers
        }

    @property
    def givens(self) -> dict[str, pint.Quantity]:
        """Every swept given by name, at every point."""
        from dynsolve.units import registry

        ureg = registry()
        return {
            axis.name: ureg.Quantity(
                self.sweep.givens[axis.name].reshape(self.shape), axis.unit or "dimensionless"
            )
            for axis in self.sweep.axes
        }

    @property
    def regime(self) -> np.ndarray:
        """Per point: "as assumed", "slips at C", "cord T goes slack", … ("" none made)."""
        return self.sweep.regimes.astype(str).reshape(self.shape)

    @property
    def path(self) -> np.ndarray:
        """Per point: "closed form" or "per point" (a full solve)."""
        return self.sweep.paths.astype(str).reshape(self.shape)

    @property
    def notes(self) -> dict[int, str]:
        """Flat point index → why that point lacks an answer."""
        return dict(self.sweep.notes)

    def directions(self, name: str) -> np.ndarray:
        """The sense of an answer at every point ("cw", "down", …; "" where none)."""
        answer = next((a for a in self.sweep.answers if a.name == name), None)
        if answer is None:
            raise KeyError(f"{name!r} is not an answer")
        words = answer.directions or ("",) * self.sweep.size
        return np.asarray(words, dtype=str).reshape(self.shape)

    def __getitem__(self, name: str) -> pint.Quantity:
        found = {**self.givens, **self.answers}
        if name not in found:
            raise KeyError(f"{name!r} is not swept or an answer; there are {', '.join(found)}")
        return found[name]

    def to_csv(self) -> str:
        """The table as CSV text (one row per point), as ``dynsolve sweep -o x.csv``."""
        from dynsolve.parametric.table import csv_text

        return csv_text(self.sweep)

    def plot(self, suffix: str = ".png") -> bytes:
        """The plot as image bytes (.png, .svg or .pdf), as ``dynsolve sweep --plot``."""
        from dynsolve.parametric.plot import sweep_plot

        return sweep_plot(self.sweep, suffix)

    def _repr_png_(self) -> bytes | None:
        if len(self.sweep.axes) == 1 or len(self.shape) == 2:
            return self.plot(".png")
        return None
