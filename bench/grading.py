"""Grading benchmark: expected answers of 10,000 students, each with their own variant.

Draws each student's givens from the problem's ``vary:`` section (as ``dynsolve variants``
does, without solving each), then times, in one process:

- the one-time build: the symbolic solve with the varied givens as symbols, ``lambdify``
  to numpy, and its check by full solves of a sample of variants (first, middle, last,
  and the one nearest each condition's edge);
- the vectorized evaluation of every student (cells read and converted, answers and
  conditions computed, per-student results built);
- the baseline: a full solve per variant (``dynsolve solve``'s path, no rendering),
  measured on a sample (``--sample``, default 50) and extrapolated to every student.

Ratio = extrapolated per-variant time / vectorized evaluation time (target >= 100), and
also against build + evaluation. Peak memory: traced Python allocations of a second,
identical run (``tracemalloc``), and the process's peak resident size.

    python bench/grading.py [--students 10000] [--sample 50] [--problem P] [--no-write]

writes its table to the section 'Grading' of docs/benchmarks.md (bench/report.py).
"""

from __future__ import annotations

import argparse
import resource
import statistics
import sys
import time
import tracemalloc
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from report import write_section  # noqa: E402

from dynsolve.grade.expected import expected_answers, per_variant  # noqa: E402
from dynsolve.grade.vary import draw, vary_plan  # noqa: E402
from dynsolve.spec.parser import parse_file  # noqa: E402
from dynsolve.system import SolveOptions  # noqa: E402

DEFAULT_PROBLEM = ROOT / "examples" / "grading" / "drum.dyn"


HEADING = "## Grading: `bench/grading.py`"
ABOUT = (
    "Expected answers of every student, each with their own variant of the problem "
    "(drawn as `dynsolve variants` draws them): the vectorized closed form against a full "
    "solve per variant (timed on a sample, extrapolated). See the script's docstring for "
    "what each figure includes."
)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--students", type=int, default=10_000)
    parser.add_argument("--sample", type=int, default=50)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--problem", type=Path, default=DEFAULT_PROBLEM)
    parser.add_argument("--no-write", action="store_true", help="print, do not update the doc")
    args = parser.parse_args()

    spec = parse_file(args.problem)
    plan = vary_plan(spec)
    if not plan:
        sys.exit(f"{args.problem} has no vary: section (add one, see docs/grading.md)")
    options = SolveOptions()
    start = time.perf_counter()
    variants = {f"s{i:05d}": draw(plan, args.seed, f"s{i:05d}") for i in range(args.students)}
    drawing = time.perf_counter() - start

    result = expected_answers(spec, variants, options)
    failed = sum(1 for s in result if result[s].error)

    students = list(variants)
    step = max(1, len(students) // args.sample)
    sample = students[::step][: args.sample]
    times = []
    for student in sample:
        start = time.perf_counter()
        per_variant(spec, student, variants[student], options)
        times.append(time.perf_counter() - start)
    per_solve = statistics.mean(times)
    extrapolated = per_solve * args.students

    tracemalloc.start()
    expected_answers(spec, variants, options)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024  # KiB on Linux

    rows = [
        (
            "problem",
            str(args.problem.relative_to(ROOT) if args.problem.is_absolute() else args.problem),
        ),
        ("students", f"{args.students} ({failed} failed)"),
        ("path", result.path + (f" ({result.reason})" if result.reason else "")),
        ("drawing the variants", f"{drawing:.2f} s (not in the figures below)"),
        ("one-time build (solve, lambdify, checks)", f"{result.build_seconds:.2f} s"),
        ("vectorized evaluation, all students", f"{result.evaluate_seconds:.3f} s (target < 2 s)"),
        (f"per-variant solve, mean of {len(sample)}", f"{per_solve * 1000:.1f} ms"),
        ("per-variant, extrapolated to all", f"{extrapolated:.0f} s"),
        (
            "ratio per-variant / vectorized",
            f"{extrapolated / result.evaluate_seconds:.0f}x (target >= 100x)",
        ),
        (
            "ratio per-variant / (build + vectorized)",
            f"{extrapolated / (result.build_seconds + result.evaluate_seconds):.0f}x",
        ),
        ("peak traced memory (tracemalloc)", f"{peak / 2**20:.1f} MiB"),
        ("peak resident size of the process", f"{rss:.0f} MiB"),
    ]
    width = max(len(name) for name, _ in rows)
    for name, value in rows:
        print(f"{name:<{width}}  {value}")
    if not args.no_write:
        body = "\n".join(
            [ABOUT, "", "| figure | value |", "|---|---|"]
            + [f"| {name} | {value} |" for name, value in rows]
        )
        write_section(HEADING, body, " ".join(["python bench/grading.py", *sys.argv[1:]]))


if __name__ == "__main__":
    main()
