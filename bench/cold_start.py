"""Cold-start benchmark: `dynsolve solve fa_hib_drum.dyn` against a bare sympy + pint script.

Both run as fresh processes, alternating, after one warm-up each (so the OS file
cache, pint's definition cache and dynsolve's unit cache are warm); the figure is
the median over the pairs and the ratio dynsolve / bare, in wall time and in CPU time
(user + system of the process and its worker; steadier on a shared machine).
Target: ratio <= 0.6.
dynsolve prints its full text derivation (to a pipe, as `dynsolve solve FILE | less`).

    python bench/cold_start.py [--pairs 11] [--no-unit-cache] [--all-problems] [--no-write]

writes its table to the section 'Cold start' of ``docs/benchmarks.md`` (bench/report.py).
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

from report import write_section

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


def timed(command: list[str], env: dict[str, str] | None = None) -> tuple[float, float]:
    """Wall seconds and CPU seconds (user + system, the process and its workers)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(
        command, check=False, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env
    )
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


HEADING = "## Cold start: `bench/cold_start.py`"
ABOUT = """A fresh `dynsolve solve problems/seed/fa_hib_drum.dyn` process (Hibbeler 17.11 as a
scene; full text derivation to a pipe) against a bare script that imports sympy and pint,
creates a default `pint.UnitRegistry()` and solves the drum's four equations with
`sympy.solve`. Fresh processes, alternating, one warm-up each (bytecode and unit cache
warm, as after installing and running once); medians over the pairs. CPU time is user +
system of the process and its worker (steadier than wall time on a shared machine)."""


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pairs", type=int, default=11, help="alternating pairs (at least 5)")
    parser.add_argument(
        "--no-unit-cache",
        action="store_true",
        help="turn dynsolve's unit-lookup cache off (every run imports pint: the first-run cost)",
    )
    parser.add_argument(
        "--all-problems", action="store_true", help="also time one cold solve of every bundled spec"
    )
    parser.add_argument("--no-write", action="store_true", help="print, do not update the doc")
    args = parser.parse_args()
    # as installed: bytecode written on the warm-up run and read after (a shell may set
    # PYTHONDONTWRITEBYTECODE, which would recompile every edited module on every run)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    if args.no_unit_cache:
        env["DYNSOLVE_CACHE_DIR"] = ""
    script = Path(sys.executable).parent / "dynsolve"  # the installed console script
    dynsolve = [str(script), "solve", str(DRUM)]
    bare = [sys.executable, "-c", BARE]
    timed(dynsolve, env), timed(bare, env)  # warm-up: OS file cache, pint's definition cache
    ours, theirs = [], []
    for _ in range(max(args.pairs, 5)):
        ours.append(timed(dynsolve, env))
        theirs.append(timed(bare, env))
    lines = [
        ABOUT,
        "",
        f"Pairs: {len(ours)}; unit cache {'off' if args.no_unit_cache else 'on'}.",
        "",
        "| time | dynsolve median (min) | bare script median (min) | ratio | target |",
        "|---|---|---|---|---|",
    ]
    for index, what in ((0, "wall"), (1, "CPU")):
        mine = [pair[index] for pair in ours]
        bare_runs = [pair[index] for pair in theirs]
        mine_median, bare_median = statistics.median(mine), statistics.median(bare_runs)
        lines.append(
            f"| {what} | {mine_median:.3f} s ({min(mine):.3f}) | {bare_median:.3f} s "
            f"({min(bare_runs):.3f}) | **{mine_median / bare_median:.2f}** | ≤ 0.60 |"
        )
    if args.all_problems:
        lines += ["", *_every_problem(script, env)]
    body = "\n".join(lines)
    print(body)
    if not args.no_write:
        command = " ".join(["python bench/cold_start.py", *sys.argv[1:]])
        write_section(HEADING, body, command)


def _every_problem(script: Path, env: dict[str, str]) -> list[str]:
    """One cold solve of every bundled spec, slowest first (target: none over 1.5 s wall).
    Each spec is solved once untimed first: the modules only it imports are compiled to
    bytecode then, as after a first run, and the timed run is the median of three."""
    rows = []
    for path in sorted((ROOT / "problems").rglob("*.dyn")):
        command = [str(script), "solve", str(path)]
        timed(command, env)  # warm-up: bytecode of the modules this spec needs
        runs = [timed(command, env) for _ in range(3)]
        wall = statistics.median(r[0] for r in runs)
        cpu = statistics.median(r[1] for r in runs)
        rows.append((wall, cpu, path.relative_to(ROOT).as_posix()))
    rows.sort(reverse=True)
    over = [r for r in rows if r[0] > 1.5]
    most_cpu = max(rows, key=lambda r: r[1])  # on a shared machine wall time waits for others
    lines = [
        f"Every bundled spec, cold `dynsolve solve` (median of three after a warm-up run): "
        f"slowest {rows[0][0]:.2f} s wall "
        f"({rows[0][2]}); {len(over)} of {len(rows)} over 1.5 s (target: none); the most CPU "
        f"{most_cpu[1]:.2f} s ({most_cpu[2]}), {sum(r[1] > 1.5 for r in rows)} over 1.5 s CPU. "
        "The ten slowest:",
        "",
        "| spec | wall s | CPU s |",
        "|---|---|---|",
    ]
    lines += [f"| {name} | {wall:.2f} | {cpu:.2f} |" for wall, cpu, name in rows[:10]]
    return lines


if __name__ == "__main__":
    main()
