"""Cold-start benchmark: `dynsolve solve fa_hib_drum.dyn` against a bare sympy + pint script.

Both run as fresh processes, alternating, after one warm-up each (so the OS file
cache, pint's definition cache and dynsolve's unit cache are warm); the figure is
the median over the pairs and the ratio dynsolve / bare. Target: ratio <= 1.0.
dynsolve prints its full text derivation (to a pipe, as `dynsolve solve FILE | less`).

    python bench/cold_start.py [--pairs 7] [--no-unit-cache]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DRUM = ROOT / "problems" / "seed" / "fa_hib_drum.dyn"

# The baseline the issue names: import sympy and pint, create a default registry and
# solve the drum's four equations (Hibbeler 17.11) with sympy.solve.
BARE = """
import pint, sympy
ureg = pint.UnitRegistry()
I_O, T, alpha, a = sympy.symbols("I_O T alpha a")
m_d, k_O, r, m_b, g = 60, sympy.Rational(1, 4), sympy.Rational(2, 5), 20, sympy.Rational(981, 100)
equations = [
    sympy.Eq(I_O, m_d * k_O**2),
    sympy.Eq(T * r, I_O * alpha),
    sympy.Eq(m_b * g - T, m_b * a),
    sympy.Eq(a, alpha * r),
]
print(sympy.solve(equations, [I_O, T, alpha, a]))
"""


def timed(command: list[str], env: dict[str, str] | None = None) -> float:
    start = time.perf_counter()
    subprocess.run(
        command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env
    )
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pairs", type=int, default=7, help="alternating pairs (at least 5)")
    parser.add_argument(
        "--no-unit-cache",
        action="store_true",
        help="turn dynsolve's unit-lookup cache off (every run imports pint: the first-run cost)",
    )
    args = parser.parse_args()
    env = {**os.environ, "DYNSOLVE_CACHE_DIR": ""} if args.no_unit_cache else None
    script = Path(sys.executable).parent / "dynsolve"  # the installed console script
    dynsolve = [str(script), "solve", str(DRUM)]
    bare = [sys.executable, "-c", BARE]
    timed(dynsolve, env), timed(bare)  # warm-up: OS file cache, pint's definition cache
    ours, theirs = [], []
    for _ in range(max(args.pairs, 5)):
        ours.append(timed(dynsolve, env))
        theirs.append(timed(bare))
    ours_median, theirs_median = statistics.median(ours), statistics.median(theirs)
    print(f"pairs: {len(ours)}; unit cache {'off' if args.no_unit_cache else 'on'}")
    print(f"dynsolve solve fa_hib_drum.dyn  median {ours_median:.3f} s  (min {min(ours):.3f})")
    print(f"bare sympy+pint script          median {theirs_median:.3f} s  (min {min(theirs):.3f})")
    print(f"ratio dynsolve/bare: {ours_median / theirs_median:.2f}  (target <= 1.00)")


if __name__ == "__main__":
    main()
