"""Sweep benchmark: `dynsolve sweep` against one cold solve, and the closed form against a full
solve per point (exact and numeric), at several point counts and scales.

Two measurements, in one run:

- cold: a fresh `dynsolve sweep problems/seed/fa_hib_drum.dyn "m_b=1..100 kg" --points
  10000 -o FILE` process against a fresh `dynsolve solve` of the same spec (the baseline),
  alternating, one warm-up each; medians of wall and CPU time (user + system of the process
  and its worker). Target: ratio <= 3.
- in one process, for the drum's block mass m_b over scale·(1..100) kg: the sweep by the
  closed form (`sweep_points`: symbolic build, lambdify, check by full solves, vectorized
  evaluation) at each point count, against a full solve per point in exact and in numeric
  mode, timed on ``--sample`` points spread over the range and extrapolated to every point;
  error = the largest relative difference, over every answer at the sampled points, from
  the exact solve (target <= 1e-9 for the closed form).

    python bench/sweep.py [--pairs 5] [--sample 12] [--counts 100,1000,10000,100000]
                          [--scales 1e-6,1,1e6] [--no-write]

writes its table to the section 'Parametric sweep' of docs/benchmarks.md (bench/report.py).
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from report import write_section  # noqa: E402

from dynsolve.parametric.evaluate import Sweep, sweep_points  # noqa: E402
from dynsolve.parametric.ranges import Axis  # noqa: E402
from dynsolve.spec.parser import parse_file  # noqa: E402
from dynsolve.system import SolveOptions  # noqa: E402

DRUM = ROOT / "problems" / "seed" / "fa_hib_drum.dyn"
HEADING = "## Parametric sweep: `bench/sweep.py`"
ABOUT = """`dynsolve sweep` of the drum's block mass (Hibbeler 17.11,
`problems/seed/fa_hib_drum.dyn`, m_b over scale·(1..100) kg; α, T and a at every point). See
the script's docstring for what each figure includes. The closed form's total is mostly its
one-time build (the first row also warms sympy's caches); the evaluation grows with the
points. Numeric mode gives the exact solve's floats here (the drum is linear: both round
once). On a shared machine wall times wait for other work; CPU times are steadier."""


def timed(command: list[str]) -> tuple[float, float]:
    """Wall seconds and CPU seconds (user + system, the process and its workers)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(
        command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=ROOT
    )
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def cold(pairs: int) -> list[str]:
    """Fresh `dynsolve sweep` (10,000 points, table written) against fresh `dynsolve solve`."""
    with tempfile.TemporaryDirectory() as folder:
        table = Path(folder) / "sweep.csv"
        python = [sys.executable, "-m", "dynsolve"]  # this checkout's code, for both
        sweep = [
            *python,
            "sweep",
            str(DRUM),
            "m_b=1..100 kg",
            "--points",
            "10000",
            "-o",
            str(table),
        ]
        solve = [*python, "solve", str(DRUM)]
        timed(sweep), timed(solve)  # warm-up: bytecode, pint's definition cache
        ours, theirs = [], []
        for _ in range(pairs):
            ours.append(timed(sweep))
            theirs.append(timed(solve))
    lines = [
        f"Cold processes, {pairs} alternating pairs:",
        "",
        "| time | sweep, 10,000 points, median (min) | one solve, median (min) | ratio | target |",
        "|---|---|---|---|---|",
    ]
    for index, what in ((0, "wall"), (1, "CPU")):
        mine = [pair[index] for pair in ours]
        base = [pair[index] for pair in theirs]
        lines.append(
            f"| {what} | {statistics.median(mine):.3f} s ({min(mine):.3f}) | "
            f"{statistics.median(base):.3f} s ({min(base):.3f}) | "
            f"**{statistics.median(mine) / statistics.median(base):.2f}** | ≤ 3 |"
        )
    return lines


def largest_error(fast: Sweep, slow: Sweep, rows: np.ndarray) -> float:
    """The largest relative difference, over every answer at ``rows`` of ``fast``."""
    worst = 0.0
    for mine, exact in zip(fast.answers, slow.answers, strict=True):
        a, b = mine.values[rows], exact.values
        worst = max(worst, float(np.max(np.abs(a - b) / np.maximum(np.abs(b), 1e-300))))
    return worst


def per_point(spec: object, masses: np.ndarray, mode: str) -> tuple[Sweep, float]:
    """A full solve of each of ``masses`` in ``mode``; the result and seconds per point."""
    axis = Axis("m_b", "kg", masses, 1.0)
    start = time.perf_counter()
    result = sweep_points(
        spec, (axis,), (masses,), (len(masses),), options=SolveOptions(mode=mode), vectorize=False
    )  # type: ignore[arg-type]
    return result, (time.perf_counter() - start) / len(masses)


def in_process(counts: list[int], scales: list[float], sample: int) -> list[str]:
    spec = parse_file(DRUM)
    lines = [
        "In one process (per-point times: the mean over the sampled points, extrapolated):",
        "",
        "| scale | points | closed form: total (build + check; evaluate) | per point, exact | "
        "per point, numeric | ratio exact / closed form | largest error: closed form | "
        "largest error: numeric |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for scale in scales:
        for count in counts:
            masses = np.linspace(1.0, 100.0, count) * scale
            axis = Axis("m_b", "kg", masses, 1.0)
            start = time.perf_counter()
            fast = sweep_points(spec, (axis,), (masses,), (count,))
            total = time.perf_counter() - start
            rows = np.unique(np.linspace(0, count - 1, min(sample, count)).round().astype(int))
            exact, exact_each = per_point(spec, masses[rows], "exact")
            numeric, numeric_each = per_point(spec, masses[rows], "numeric")
            paths = fast.counts()
            note = "" if not paths["per point"] else f" ({paths['per point']} per point)"
            numeric_error = largest_error(numeric, exact, np.arange(len(rows)))
            lines.append(
                f"| {scale:g} | {count:,}{note} | {total:.2f} s ({fast.build_seconds:.2f}; "
                f"{fast.evaluate_seconds:.4f}) | {exact_each * count:.1f} s | "
                f"{numeric_each * count:.1f} s | {exact_each * count / total:.0f}x | "
                f"{largest_error(fast, exact, rows):.1e} | {numeric_error:.1e} |"
            )
            print(lines[-1], flush=True)
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pairs", type=int, default=5)
    parser.add_argument("--sample", type=int, default=12, help="points solved one by one")
    parser.add_argument("--counts", default="100,1000,10000,100000")
    parser.add_argument("--scales", default="1e-6,1,1e6")
    parser.add_argument("--no-write", action="store_true", help="print, do not update the doc")
    args = parser.parse_args()
    os.environ.pop("PYTHONDONTWRITEBYTECODE", None)  # as installed: bytecode kept
    counts = [int(c) for c in args.counts.split(",")]
    scales = [float(s) for s in args.scales.split(",")]
    lines = [ABOUT, "", *cold(args.pairs), ""]
    print("\n".join(lines), flush=True)
    lines += in_process(counts, scales, args.sample)
    body = "\n".join(lines)
    print(body)
    if not args.no_write:
        write_section(HEADING, body, " ".join(["python bench/sweep.py", *sys.argv[1:]]))


if __name__ == "__main__":
    main()
