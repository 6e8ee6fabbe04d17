"""Draw a sweep: each answer against one swept given, or as contours over two.

Where the regime changes (the no-slip check fails and the point is solved slipping, a cord
goes slack, a body tips or loses contact) a dashed line marks the change and the regimes
are shaded and named in the legend; over two givens the regimes' boundaries are drawn as
dashed contours. A change of a stated direction (cw to ccw) is marked by a dotted line.
matplotlib's Agg backend draws it (no display needed).

>>> import numpy as np
>>> from dynsolve.spec.parser import parse_spec
>>> from dynsolve.parametric.evaluate import sweep_points
>>> from dynsolve.parametric.ranges import Axis
>>> text = "given:\\n  m = 2 kg\\n  F = 10 N\\nequations:\\n  F = m*a\\nfind: a"
>>> spec = parse_spec(text, "p.dyn")
>>> axis = Axis("m", "kg", np.array([1.0, 2.0, 4.0]), 1.0)
>>> sweep_plot(sweep_points(spec, (axis,), (axis.values,), (3,)), ".svg")[:5]
b'<?xml'
"""

from __future__ import annotations

import io
import itertools
import re

import numpy as np

from dynsolve.errors import SpecError
from dynsolve.names import pretty
from dynsolve.parametric.evaluate import Answer, Sweep
from dynsolve.parametric.table import header

MAX_PANELS = 6  # answers drawn (the table has every one)
_SHADES = ("#4c72b0", "#dd8452", "#55a868", "#c44e52", "#8172b3", "#937860")


def not_plottable(axes: int) -> SpecError:
    """The error for a sweep of ``axes`` givens: a plot shows one or two."""
    return SpecError(
        f"a plot shows a sweep of one or two givens, not {axes}",
        hint="sweep one or two givens with --plot, or write the table with -o",
    )


def sweep_plot(result: Sweep, suffix: str = ".png") -> bytes:
    """The figure of ``result`` in the format of ``suffix`` (.png, .svg or .pdf)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    if len(result.axes) not in (1, 2):
        raise not_plottable(len(result.axes))
    if len(result.axes) == 2 and len(result.shape) != 2:
        raise SpecError(
            "two givens are drawn as contours over a grid; these points are not one",
            hint="sweep two ranges, or pass values shaped as a grid (numpy.meshgrid)",
        )
    answers = result.answers[:MAX_PANELS]
    if len(result.axes) == 1:
        figure, panels = plt.subplots(len(answers), 1, figsize=(7, 2.3 * len(answers) + 0.6))
        for panel, answer in zip(np.atleast_1d(panels), answers, strict=True):
            _line(panel, result, answer)
    else:
        columns = min(2, len(answers))
        lines = -(-len(answers) // columns)
        figure, panels = plt.subplots(lines, columns, figsize=(6 * columns, 4.6 * lines))
        panels = np.atleast_1d(panels).ravel()
        for panel, answer in zip(panels, answers, strict=False):
            _contour(figure, panel, result, answer)
        for panel in panels[len(answers) :]:
            panel.set_visible(False)
    figure.suptitle(result.title or result.file)
    figure.tight_layout()
    buffer = io.BytesIO()
    figure.savefig(buffer, format=suffix.lstrip(".") or "png")
    plt.close(figure)
    return buffer.getvalue()


def _line(panel: object, result: Sweep, answer: Answer) -> None:
    """One answer against the swept given, its regimes shaded and their changes marked."""
    axis = result.axes[0]
    x = result.givens[axis.name]
    order = np.argsort(x, kind="stable")
    x, y, regimes = x[order], answer.values[order], result.regimes[order]
    breaks = np.flatnonzero(regimes[1:] != regimes[:-1]) + 1  # a jump is not joined up
    for xs, ys in zip(np.split(x, breaks), np.split(y, breaks), strict=True):
        panel.plot(xs, ys, color="black", linewidth=1.2)  # type: ignore[attr-defined]
    names = list(dict.fromkeys(regimes.tolist()))
    if len(names) > 1:
        starts = [0, *(np.flatnonzero(regimes[1:] != regimes[:-1]) + 1).tolist(), len(x)]
        shown: set[str] = set()
        for begin, end in itertools.pairwise(starts):
            left = (x[begin - 1] + x[begin]) / 2 if begin else x[0]
            right = (x[end - 1] + x[end]) / 2 if end < len(x) else x[-1]
            regime = str(regimes[begin]) or "no assumption"
            colour = _SHADES[names.index(regimes[begin]) % len(_SHADES)]
            panel.axvspan(  # type: ignore[attr-defined]
                left, right, color=colour, alpha=0.15, label=None if regime in shown else regime
            )
            shown.add(regime)
            if begin:
                panel.axvline(left, color=colour, linestyle="--", linewidth=1)  # type: ignore[attr-defined]
        panel.legend(fontsize=7, loc="best")  # type: ignore[attr-defined]
    if answer.directions:
        words = np.asarray(answer.directions, dtype=object)[order]
        for i in np.flatnonzero(words[1:] != words[:-1]):
            turned = words[i] and words[i + 1] and not re.search(r"\d", words[i] + words[i + 1])
            if turned:  # cw → ccw; not 16.7° → 16.8°, nor a point without an answer
                middle = (x[i] + x[i + 1]) / 2
                panel.axvline(middle, color="grey", linestyle=":", linewidth=1)  # type: ignore[attr-defined]
                panel.annotate(  # type: ignore[attr-defined]
                    f"{words[i]} → {words[i + 1]}", (middle, 0.95),
                    xycoords=("data", "axes fraction"), fontsize=7, ha="center", va="top",
                )  # fmt: skip
    panel.set_xlabel(header(pretty(axis.name), axis.unit))  # type: ignore[attr-defined]
    panel.set_ylabel(header(pretty(answer.name), answer.unit))  # type: ignore[attr-defined]
    panel.grid(True, linewidth=0.3)  # type: ignore[attr-defined]


def _contour(figure: object, panel: object, result: Sweep, answer: Answer) -> None:
    """One answer as filled contours over the two swept givens, regime boundaries dashed."""
    first, second = result.axes
    X = result.givens[first.name].reshape(result.shape)
    Y = result.givens[second.name].reshape(result.shape)
    Z = np.ma.masked_invalid(answer.values.reshape(result.shape))
    if Z.count():
        filled = panel.contourf(X, Y, Z, levels=14, cmap="viridis")  # type: ignore[attr-defined]
        figure.colorbar(filled, ax=panel, label=header(pretty(answer.name), answer.unit))  # type: ignore[attr-defined]
    names = list(dict.fromkeys(result.regimes.tolist()))
    if len(names) > 1:
        codes = np.asarray([names.index(r) for r in result.regimes]).reshape(result.shape)
        panel.contour(  # type: ignore[attr-defined]
            X, Y, codes, levels=np.arange(len(names) - 1) + 0.5, colors="white",
            linestyles="--", linewidths=1.5,
        )  # fmt: skip
        for code, name in enumerate(names):
            where = np.argwhere(codes == code)
            i, j = where[len(where) // 2]
            panel.annotate(  # type: ignore[attr-defined]
                str(name) or "no assumption", (X[i, j], Y[i, j]), fontsize=7, color="white",
                ha="center", bbox={"facecolor": "black", "alpha": 0.4, "linewidth": 0},
            )  # fmt: skip
    panel.set_xlabel(header(pretty(first.name), first.unit))  # type: ignore[attr-defined]
    panel.set_ylabel(header(pretty(second.name), second.unit))  # type: ignore[attr-defined]
    panel.set_title(header(pretty(answer.name), answer.unit), fontsize=9)  # type: ignore[attr-defined]
