"""Display survey: sympy internals and unitless check values over the bundled problems.

Solves every ``problems/**/*.dyn`` in one process (exact mode unless ``--mode``), renders
each as JSON and counts, in the text a reader sees (steps' formulas, numbers and values,
discarded roots, notes, answers, givens, checks, assumptions, remarks), the strings that
hold ``polar_lift``, ``exp_polar``, ``Integral(``, ``Piecewise(``, ``hyper(``, ``Abs(``,
``**`` or an imaginary unit, and the check and assumption details with a bare number
before a relation (``= 19.77 ≥ 0``). Issue 25, items 13 and 14.

    python bench/display_survey.py [--mode exact|numeric|auto] [--list]
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from collections import Counter
from collections.abc import Iterator
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from dynsolve.errors import DynsolveError  # noqa: E402
from dynsolve.pipeline import solve_file  # noqa: E402
from dynsolve.render.json import solution_dict  # noqa: E402
from dynsolve.system import SolveOptions  # noqa: E402

KINDS = {
    "polar_lift": re.compile(r"polar_lift"),
    "exp_polar": re.compile(r"exp_polar"),
    "Integral": re.compile(r"Integral\("),
    "Piecewise": re.compile(r"Piecewise\("),
    "hyper": re.compile(r"hyper\("),
    "Abs(": re.compile(r"Abs\("),
    "**": re.compile(r"\*\*"),
    "imaginary I": re.compile(r"[-+*] *[0-9.]*\*?I\b(?! α)|\bI\*"),
}
BARE = re.compile(
    r"(?:= |at |acceleration |velocity )-?\d+(?:\.\d+)?(?:e[-+]?\d+)?(?= *(?:[≥≤<>]|\)|$|;|,))"
)


def shown_strings(data: dict) -> Iterator[tuple[str, str]]:
    """(where, text) of every string of a solution's JSON that a reader sees."""
    for step in data.get("steps", []):
        for row in step["results"]:
            for key in ("formula", "value", "substituted"):
                yield "step", row[key]
        for text in step["discarded"]:
            yield "step", text
        yield "note", step["note"]
    for answer in data.get("answers", []):
        yield "answer", answer["shown"]
    for given in data.get("givens", []):
        yield "given", given["written"]
    for check in data.get("checks", []) + data.get("assumptions", []):
        yield "check", check["detail"]
    for remark in data.get("remarks", []):
        yield "remark", remark


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mode", default="exact", choices=["exact", "numeric", "auto"])
    parser.add_argument("--list", action="store_true", help="name the problems of each kind")
    args = parser.parse_args()
    counts: Counter[str] = Counter()
    problems: dict[str, set[str]] = {}
    files = sorted((ROOT / "problems").rglob("*.dyn"))
    for path in files:
        try:
            data = solution_dict(solve_file(path, SolveOptions(mode=args.mode)))
        except DynsolveError:
            continue
        name = str(path.relative_to(ROOT / "problems"))
        for where, text in shown_strings(data):
            found = [kind for kind, pattern in KINDS.items() if pattern.search(text)]
            if where == "check" and BARE.search(text):
                found.append("bare number in a check")
            for kind in found:
                counts[kind] += 1
                problems.setdefault(kind, set()).add(name)
    print(f"{len(files)} problems, {args.mode} mode")
    for kind in (*KINDS, "bare number in a check"):
        print(f"{kind:24s} {counts[kind]:4d} strings in {len(problems.get(kind, ())):3d} problems")
        if args.list and kind in problems:
            print("    " + ", ".join(sorted(problems[kind])))
    print(json.dumps({k: counts[k] for k in (*KINDS, "bare number in a check")}))


if __name__ == "__main__":
    main()
