"""Grading speed: `dynsolve grade` of 10,000 rows × 3 parts with diagnosis, against a baseline.

Writes a class of N students of the drum (Hibbeler 17.11 as a scene; the answers of
``bench/grade_rows.py``: a fifth with alpha ×10, a fifth with g left out, every cell
distinct), then times fresh processes, alternating, after one warm-up each:

- ``dynsolve grade DRUM ANSWERS -o report.csv`` (start-up, the solve, the mistakes'
  re-solves, reading, judging and diagnosing every cell, the journal, the report);
- the baseline, measured in the same run: ``dynsolve solve DRUM`` (start-up and the one
  solve every grade pays), so that a figure taken on a loaded machine still says how much
  the class itself costs (grade − baseline) and how it compares (the ratio).

Medians over the pairs, wall and CPU (user + system, steadier on a shared machine).
Target (issue 27): the whole grade of such a class in ≤ 3 s on an idle 2-core machine.
``--profile`` adds the in-process profile of one grade (top functions by own time).

    python bench/grade_speed.py [--rows 10000] [--pairs 3] [--profile] [--no-write]
"""

from __future__ import annotations

import argparse
import cProfile
import io
import os
import pstats
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from grade_rows import DRUM, answers
from report import write_section

ROOT = Path(__file__).resolve().parent.parent
HEADING = "## Grading 10,000 rows: `bench/grade_speed.py`"


def timed(command: list[str]) -> tuple[float, float]:
    """Wall seconds and CPU seconds (user + system) of a fresh process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def profile(sheet: Path, report: Path, top: int = 12) -> str:
    """The in-process profile of one grade: the ``top`` functions by own time."""
    sys.path.insert(0, str(ROOT))
    from dynsolve.grade.command import GradeRequest, grade

    request = GradeRequest(DRUM, sheet, report=report)
    grade(request)  # warm: the solve's caches, as in a fresh process after import
    profiler = cProfile.Profile()
    profiler.enable()
    grade(request)
    profiler.disable()
    out = io.StringIO()
    pstats.Stats(profiler, stream=out).sort_stats("tottime").print_stats(top)
    return out.getvalue()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=10_000)
    parser.add_argument("--pairs", type=int, default=3, help="alternating pairs")
    parser.add_argument("--profile", action="store_true", help="print an in-process profile")
    parser.add_argument("--no-write", action="store_true", help="print, do not update the doc")
    args = parser.parse_args()
    folder = Path(tempfile.mkdtemp())
    sheet, report = folder / "answers.csv", folder / "report.csv"
    sheet.write_text(answers(args.rows), encoding="utf-8")
    dynsolve = [sys.executable, "-m", "dynsolve"]
    grading = [*dynsolve, "grade", str(DRUM), str(sheet), "-o", str(report)]
    baseline = [*dynsolve, "solve", str(DRUM)]
    timed(grading), timed(baseline)  # warm-up: bytecode, the OS file cache, the unit cache
    ours, base = [], []
    for _ in range(max(args.pairs, 1)):
        ours.append(timed(grading))
        base.append(timed(baseline))
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    lines = [
        f"`dynsolve grade` of {args.rows:,} students × 3 parts of the drum (scene), diagnosis "
        "on, against `dynsolve solve` of the drum (start-up and the one solve) in the same "
        f"run; medians of {len(ours)} alternating pairs (load average {load:.2f} at the end).",
        "",
        "| time | grade | baseline (solve) | grade − baseline | ratio | target |",
        "|---|---|---|---|---|---|",
    ]
    for index, what in ((0, "wall"), (1, "CPU")):
        mine = statistics.median(pair[index] for pair in ours)
        theirs = statistics.median(pair[index] for pair in base)
        target = "≤ 3 s idle" if index == 0 else ""
        lines.append(
            f"| {what} | **{mine:.2f} s** | {theirs:.2f} s | {mine - theirs:.2f} s | "
            f"{mine / theirs:.2f} | {target} |"
        )
    body = "\n".join(lines)
    print(body)
    if args.profile:
        print(profile(sheet, folder / "profiled.csv"))
    if not args.no_write:
        write_section(HEADING, body, " ".join(["python bench/grade_speed.py", *sys.argv[1:]]))


if __name__ == "__main__":
    main()
