"""A check that did not run, or could not decide, is shown as not run (–) with its reason in
every format and mode, never as passed, and never fails the solution (issue 25 item 7).
The assumptions table and the checks table agree after a re-solve.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner, Result

from dynsolve.cli import app
from dynsolve.pipeline import solve_file

ROOT = Path(__file__).resolve().parent.parent
MODES = ("exact", "numeric", "auto")

# a collar on a rod pulled by a spring, every given a letter: nothing to integrate
COLLAR = ROOT / "problems" / "seed" / "we_seed_collar-symbolic.dyn"
# x = a − b ≥ 0: its sign is not known for letters a and b
CONSTRAINT = """\
given:
  a: length
  b: length
equations:
  x = a - b
  x >= 0
find: x
"""
# a pushed crate whose sizes and push are letters: where N acts is not known, nor whether
# N ≥ 0, so neither tipping nor the contact can be decided
TIPPING = """\
given:
  m: mass
  b: length
  h: length
  d: length
  P: force
  mu_k = 0.2
scene:
  body crate: mass m, block b by h, at (0, h/2)
  base C on crate: from (-b/2, -h/2) to (b/2, -h/2), mu_k mu_k, slides right
  force P on crate at (-b/2, d - h/2): right
  gravity
find: a = a_G(crate) [m/s^2]
"""
# a drum lowering a block on a cord, every given a letter: Newton–Euler at state 1 has no
# numbers, so whether the cord stays taut between the states is not checked
CORD = """\
given:
  m_d: mass
  k_O: length
  r: length
  m_b: mass
  h: length
scene:
  point O: (0, 0)
  body drum: mass m_d, gyration k_O, at (0, 0)
  body block: particle, mass m_b, at (r, -2*r)
  point A on drum: (r, 0)
  pin drum at O
  cord T: drum at A to block, down
  gravity
  travel block: by h, down
find: v = speed(block) [m/s]
"""
# a disk that rolls between two states: the friction rolling needs is not computed
ROLLS = ROOT / "problems" / "seed" / "rwe_seed_disk40lb.dyn"
# a projectile: the motion is integrated, there are no equations for a structure check
PROJECTILE = ROOT / "problems" / "kinematics" / "projectile.dyn"


def run(tmp_path: Path, source: str | Path, *args: str) -> Result:
    if isinstance(source, str):
        path = tmp_path / "spec.dyn"
        path.write_text(source, encoding="utf-8")
        source = path
    result = CliRunner().invoke(app, ["solve", str(source), *args])
    assert result.exception is None or isinstance(result.exception, SystemExit)
    return result


CASES = [
    (COLLAR, "simulation", "not simulated: symbolic givens"),
    (CONSTRAINT, "constraint x >= 0 (line 6)", "cannot be decided for symbolic givens"),
    (TIPPING, "assumption: no tipping on base C", "cannot be decided"),
    (TIPPING, "assumption: contact at C kept", "cannot be decided"),
    (PROJECTILE, "structure", "no equations to solve"),
    (CORD, "assumption: cord T taut between the states", "so it is not checked"),
    (ROLLS, "assumption: no slip at C", "the friction it needs between the states"),
]


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize(("source", "name", "why"), CASES)
def test_a_check_that_did_not_run_is_not_run_in_json(
    tmp_path: Path, mode: str, source: str | Path, name: str, why: str
):
    result = run(tmp_path, source, "--mode", mode, "--format", "json")
    assert result.exit_code == 0, result.output  # not run is not a failure
    checks = {c["name"]: c for c in json.loads(result.stdout)["checks"]}
    assert checks[name]["status"] == "not_run"
    assert checks[name]["passed"] is False
    assert why in checks[name]["detail"]


@pytest.mark.parametrize(("source", "name", "why"), CASES)
def test_a_check_that_did_not_run_is_marked_in_the_terminal(
    tmp_path: Path, source: str | Path, name: str, why: str
):
    result = run(tmp_path, source)
    assert result.exit_code == 0
    head = name[:30]  # a long name wraps in its column
    rows = [line for line in result.stdout.splitlines() if f"  {head}" in line]
    assert rows and all(row.startswith("–") for row in rows), result.stdout


@pytest.mark.parametrize(("source", "name", "why"), CASES[:3])
def test_markdown_and_latex_count_it_as_not_run(
    tmp_path: Path, source: str | Path, name: str, why: str
):
    markdown = run(tmp_path, source, "--format", "markdown").stdout
    assert any(row.startswith("| – |") and why in row for row in markdown.splitlines())
    assert "checks passed;" in markdown and "not run." in markdown
    assert "All " not in markdown.split("## Checks")[1].splitlines()[2]
    latex = run(tmp_path, source, "--format", "latex").stdout
    assert "\\item[--]" in latex and "(not run)" in latex


def test_undecided_assumptions_are_not_decided_in_the_assumptions_table(tmp_path: Path):
    text = run(tmp_path, TIPPING).stdout
    table = text.split("Assumptions")[1].split("Checks")[0]
    assert "–  no tipping on base C" in table and "✓" not in table
    markdown = run(tmp_path, TIPPING, "--format", "markdown").stdout
    assert "| – | no tipping on base C |" in markdown
    latex = run(tmp_path, TIPPING, "--format", "latex").stdout
    assert "(not decided)" in latex
    data = json.loads(run(tmp_path, TIPPING, "--format", "json").stdout)
    assert {a["name"]: a["status"] for a in data["assumptions"]}["no tipping on base C"] == (
        "not_run"
    )


def test_a_rejected_assumption_agrees_in_both_tables():
    # Hibbeler 12e Example 17.15: |F_A| = 300 N > μs N = 294.3 N, so the no-slip trial is
    # rejected and the answers are the slipping re-solve's (α = +0.428 rad/s²)
    solution = solve_file(ROOT / "problems" / "seed" / "gpm_seed_pole_slip.dyn")
    (assumption,) = [a for a in solution.assumptions if a.name == "no slip at A"]
    assert assumption.status == "failed"
    names = [c.name for c in solution.checks]
    assert "assumption: no slip at A" not in names  # it did not hold: never a ✓ under its name
    (check,) = [c for c in solution.checks if c.name == "assumption: no slip at A rejected"]
    assert check.status == "passed"
    assert check.detail.startswith("the answers are for the re-solved case")


@pytest.mark.parametrize("mode", MODES)
def test_dimensions_with_nothing_to_check_is_not_run(mode: str) -> None:
    """Newcomer round 8: momentum finds that need no equation showed "✓ dimensions …
    homogeneous (0 checked)", a pass for a check that checked nothing."""
    path = ROOT / "problems/angular_momentum/particle_momentum_about_point.dyn"
    result = CliRunner().invoke(app, ["solve", str(path), "--format", "json", "--mode", mode])
    assert result.exit_code == 0, result.output
    checks = {c["name"]: c for c in json.loads(result.output)["checks"]}
    assert checks["dimensions"]["status"] == "not_run"
    assert checks["dimensions"]["passed"] is False
