"""Scaling benchmark: generated specs of growing size, solved in-process (issue 14, part 5).

Four families, generated as in ``tests/test_large_specs.py`` (which checks their
answers): a chain of n blocks joined by cords on a smooth floor (scene mode, 3 equations
and 3 unknowns per block), a linkage of n bars in a zigzag of sliders (2 velocity
equations and 2 unknowns per bar), a chain of n equations ``x_i = x_{i-1} + c``, and a dense
n-unknown linear system with n-term sums built from a known solution. Each size is solved
after a warm-up, sympy's cache cleared, ``--repeat`` times (1 by default); the figure is the
least CPU time (``process_time``) of parse + build + solve + checks (on a shared machine a
single run can be slowed by the others' load), and the growth exponent is the log-log
slope between the two largest sizes. The solver is imported as the CLI's worker imports
it (:func:`dynsolve.startup.import_solver`: the import's objects frozen out of the garbage
collector's passes), so the figure is the work a `dynsolve solve` of the spec does. The
baseline, in the same run, is ``numpy.linalg.solve`` of the same linear system (what a
hand-written numeric script would do).

    python bench/scaling.py [--repeat N] [--no-write]
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))

from dynsolve.startup import import_solver  # noqa: E402

import_solver()  # as the CLI's worker does, before anything else of dynsolve

import numpy as np  # noqa: E402
import sympy  # noqa: E402
from report import write_section  # noqa: E402
from test_large_specs import block_chain, dense_system, equation_chain, linkage_chain  # noqa: E402

from dynsolve.pipeline import solve_text  # noqa: E402

HEADING = "## Scaling: `bench/scaling.py`"
FAMILIES = {
    "block chain (scene), n bodies": (block_chain, (10, 20, 40, 80, 160)),
    "linkage chain (scene), n bars": (linkage_chain, (10, 20, 50)),
    "equation chain, n equations": (equation_chain, (40, 80, 160, 320)),
    "dense linear system, n unknowns": (lambda n: dense_system(n)[0], (10, 20, 40, 80, 100)),
}


def cpu_seconds(text: str, repeat: int = 1) -> float:
    """The least CPU time of ``repeat`` solves of ``text``, each from a cleared sympy cache."""
    best = math.inf
    for _ in range(repeat):
        sympy.core.cache.clear_cache()
        start = time.process_time()
        solution = solve_text(text, "generated.dyn")
        best = min(best, time.process_time() - start)
        assert all(check.passed for check in solution.checks), "a generated spec failed a check"
    return best


def numpy_seconds(n: int, repeat: int = 20) -> float:
    """``numpy.linalg.solve`` of a dense n × n system (the same shape), mean CPU time."""
    rng = np.random.default_rng(1)
    matrix = rng.integers(-3, 4, (n, n)).astype(float) + np.eye(n) * 4 * n
    rhs = rng.integers(-9, 10, n).astype(float)
    start = time.process_time()
    for _ in range(repeat):
        np.linalg.solve(matrix, rhs)
    return (time.process_time() - start) / repeat


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=1, help="solves per size; the least")
    parser.add_argument("--no-write", action="store_true", help="print, do not update the doc")
    args = parser.parse_args()
    cpu_seconds(equation_chain(5))  # warm-up: imports, parser, unit cache
    lines = [
        "Generated specs solved in-process (parse, build, solve, checks); CPU seconds, the "
        f"least of {args.repeat} solve{'s' if args.repeat > 1 else ''} per size after a "
        "warm-up, sympy's cache cleared before each. Growth: the log-log slope "
        "between the two largest sizes. Targets: 160 bodies and 320 equations each under 1 s, "
        "growth ≤ n^1.2, a 100-unknown dense system solved; a 50-bar linkage under 1 s with "
        "growth ≤ n² (issue 11).",
        "",
        "| family | n | dynsolve CPU s | numpy.linalg.solve s (same n) |",
        "|---|---|---|---|",
    ]
    growth = []
    for family, (make, sizes) in FAMILIES.items():
        times = []
        for n in sizes:
            seconds = cpu_seconds(make(n), args.repeat)
            times.append(seconds)
            lines.append(f"| {family} | {n} | {seconds:.2f} | {numpy_seconds(n):.1e} |")
            print(lines[-1], flush=True)
        slope = math.log(times[-1] / times[-2]) / math.log(sizes[-1] / sizes[-2])
        growth.append(f"{family}: n^{slope:.2f}")
    lines += ["", "Growth between the two largest sizes: " + "; ".join(growth) + "."]
    body = "\n".join(lines)
    print(body)
    if not args.no_write:
        write_section(HEADING, body, " ".join(["python bench/scaling.py", *sys.argv[1:]]))


if __name__ == "__main__":
    main()
