"""Formulas shown stay as tidy as they were (issue 14: simplify only where it pays).

``tests/data/formula_forms.json`` holds, for every bundled problem solved in exact
mode, each formula dynsolve prints (equations, solve steps, answers' exact forms) as
it printed them just before cheap tidying replaced ``sympy.simplify`` (2026-11-24). It is a
record of *form*, not of values (the values are checked against textbook answers by
each problem's ``answers:`` key): a printed formula may get shorter, never longer.
A problem bundled later is added, as it prints when added, with
``DYNSOLVE_REGENERATE_FORMS=1 pytest tests/test_formula_forms.py`` (recorded problems are
kept); after a deliberate change of form, ``DYNSOLVE_REGENERATE_FORMS=all`` records them all
again. A bundled problem missing from the record fails the test, so none goes unwatched.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from dynsolve.pipeline import solve_file
from dynsolve.render.json import render_json
from dynsolve.system import SolveOptions

ROOT = Path(__file__).resolve().parent.parent
RECORD = ROOT / "tests" / "data" / "formula_forms.json"
PROBLEMS = sorted((ROOT / "problems").rglob("*.dyn"))
SLACK = 2  # characters: a different but equally tidy order of terms may print a little longer


def printed_forms(path: Path) -> dict[str, str]:
    """Every formula the JSON output of ``path`` prints, keyed by where it appears."""
    data = json.loads(render_json(solve_file(path, SolveOptions(mode="exact"))))
    forms: dict[str, str] = {}
    for equation in data["equations"]:
        forms[f"equation {equation['line']}"] = equation["text"]
    for step in data["steps"]:
        for result in step["results"]:
            if result.get("formula"):
                forms[f"step {step['index']} {result['name']}"] = result["formula"]
    for answer in data["answers"]:
        if answer.get("exact"):
            forms[f"answer {answer['name']}"] = answer["exact"]
    return forms


def _name(path: Path) -> str:
    return path.relative_to(ROOT / "problems").as_posix()


@pytest.mark.skipif(
    not os.environ.get("DYNSOLVE_REGENERATE_FORMS"), reason="regenerates the record on request"
)
def test_regenerate_the_record() -> None:
    kept = {}
    if os.environ["DYNSOLVE_REGENERATE_FORMS"] != "all" and RECORD.exists():
        kept = json.loads(RECORD.read_text(encoding="utf-8"))
    record = {_name(p): kept.get(_name(p)) or printed_forms(p) for p in PROBLEMS}
    RECORD.write_text(json.dumps(record, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")


@pytest.mark.parametrize("path", PROBLEMS, ids=_name)
def test_no_printed_formula_got_longer(path: Path) -> None:
    record = json.loads(RECORD.read_text(encoding="utf-8"))
    assert _name(path) in record, "not recorded yet: DYNSOLVE_REGENERATE_FORMS=1 adds it"
    before = record[_name(path)]
    now = printed_forms(path)
    longer = {
        where: (before[where], text)
        for where, text in now.items()
        if where in before and len(text) > len(before[where]) + SLACK
    }
    assert not longer, longer


def test_the_roots_of_a_shown_formula_are_combined_where_positive():
    # issue 12 (combined radicals): the disk's speed from work and energy,
    # v = sqrt(2 g r s_G (M − 2 k r s_G) / (W (k_G² + r²))), not seven separate square roots
    forms = printed_forms(ROOT / "problems" / "seed" / "rwe_seed_disk40lb.dyn")
    step = next(text for where, text in forms.items() if where.startswith("step"))
    assert step.count("sqrt") <= 2
    assert "sqrt(g*r*s_G*(M - 2*k*r*s_G)/(W*(k_G^2 + r^2)))" in step
