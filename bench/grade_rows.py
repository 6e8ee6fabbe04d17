"""Grading benchmark: `dynsolve grade` on N synthetic students of the drum problem.

Writes an answers CSV of N rows (3 parts each; a quarter wrong in ways the diagnosis
names, the rest right to 3-4 figures, every cell distinct), then times one fresh
`dynsolve grade PROBLEM ANSWERS -o report.csv` process (start-up, the one solve, the
mistakes' re-solves, grading, the journal and the report) and reads its peak memory
from the child's rusage.

    python bench/grade_rows.py [--rows 10000]
"""

from __future__ import annotations

import argparse
import random
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DRUM = ROOT / "problems" / "seed" / "fa_hib_drum.dyn"
# Hibbeler 12e Example 17.11 by hand: alpha = 11.292 rad/s^2 cw, T = 105.86 N, a = 4.5168 down
ALPHA, T, A = 11.292, 105.86, 4.5168


def answers(rows: int, seed: int = 1) -> str:
    """N rows: right answers with rounding noise, and x10 / g = 1 mistakes."""
    rng = random.Random(seed)
    lines = ["student,alpha,T,a"]
    for index in range(rows):
        slip = rng.choice((1.0, 1.0, 1.0, 10.0, 1 / 9.81))
        noise = 1 + rng.uniform(-0.004, 0.004)
        lines.append(
            f"s{index:06d},{ALPHA * slip * noise:.4g} rad/s^2 cw,{T * noise:.4g} N,"
            f"{A * noise:.4g} m/s^2 down"
        )
    return "\n".join(lines) + "\n"


def main() -> None:
    """Run the benchmark and print the figures."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--rows", type=int, default=10_000)
    args = parser.parse_args()
    folder = Path(tempfile.mkdtemp())
    sheet = folder / "answers.csv"
    sheet.write_text(answers(args.rows))
    command = [sys.executable, "-m", "dynsolve", "grade", str(DRUM), str(sheet)]
    start = time.perf_counter()
    subprocess.run([*command, "-o", str(folder / "report.csv")], check=True, capture_output=True)
    seconds = time.perf_counter() - start
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    print(f"{args.rows} rows x 3 parts: {seconds:.2f} s wall, peak {peak:.0f} MB")


if __name__ == "__main__":
    main()
