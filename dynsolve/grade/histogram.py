"""The class's score distribution as a PNG or SVG histogram (matplotlib, no display).

>>> import pathlib, tempfile
>>> path = pathlib.Path(tempfile.mkdtemp()) / "h.svg"
>>> write_histogram([100.0, 50.0, 66.7], path, "Drum")
>>> path.read_text().startswith("<?xml")
True
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

FORMATS = (".png", ".svg")


def write_histogram(scores: Sequence[float], path: Path, title: str) -> None:
    """Draw the scores (0-100 %) in 10 % bins to ``path`` (.png or .svg)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    plt.rcParams["svg.hashsalt"] = "dynsolve"  # the same scores give the same file
    figure, axes = plt.subplots(figsize=(6, 3.5))
    axes.hist(scores, bins=[10 * i for i in range(11)], edgecolor="black")
    axes.set_xlabel("score (%)")
    axes.set_ylabel("students")
    axes.set_title(f"{title}: {len(scores)} students")
    axes.set_xlim(0, 100)
    figure.tight_layout()
    metadata = {"Date": None} if path.suffix.lower() == ".svg" else {"Software": None}
    figure.savefig(path, metadata=metadata)
    plt.close(figure)
