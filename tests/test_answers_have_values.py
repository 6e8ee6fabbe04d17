"""An answer that should be a number is a number, or a failed check and a non-zero exit,
never text with a null value and exit 0 (issue 25 item 4; issue 26: a threshold carried on
in a define line).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.pipeline import solve_text
from dynsolve.render.json import render_json
from dynsolve.render.terminal import render_text
from dynsolve.system import SolveOptions

MODES = ("exact", "numeric", "auto")
G = 9.81

# Pushed down at θ = 30° below the horizontal: N = m g + P sin θ, about to slip when
# P cos θ = μs N, so P_s = μs m g/(cos θ − μs sin θ) = 0.4·98.1/(0.8660 − 0.2) = 58.90 N,
# and slips(G, P)/m = 5.890 m/s² (tests/test_thresholds.py derives P_s the same way).
BLOCK = """\
given:
  m = 10 kg
  P = 20 N
  theta = 30 deg
  mu_s = 0.4
  mu_k = 0.3
scene:
  body block: particle, mass m, at (0, 0)
  contact block at G: normal up, mu_s mu_s, mu_k mu_k
  force P on block at G: angle -theta
  gravity
find: P_s = slips(G, P)
define:
  r = slips(G, P)/m
  q = P_s/m
"""
T30 = math.radians(30)
P_SLIP = 0.4 * 10 * G / (math.cos(T30) - 0.4 * math.sin(T30))

# The steepest slope a block holds on: tan β = μs, β = atan 0.4 = 21.80°; twice it in rad
STEEPEST = """\
given:
  m = 10 kg
  mu_s = 0.4
  mu_k = 0.3
  theta = 10 deg
scene:
  body block: particle, mass m, at (0, 0)
  contact block at G: normal (-sin(theta), cos(theta)), mu_s mu_s, mu_k mu_k
  gravity
find: b = steepest(G)
define:
  r = steepest(G)*2
"""


def solve_cli(tmp_path: Path, text: str, *args: str):
    path = tmp_path / "spec.dyn"
    path.write_text(text, encoding="utf-8")
    return CliRunner().invoke(app, ["solve", str(path), *args])


@pytest.mark.parametrize("mode", MODES)
def test_a_define_built_on_a_threshold_has_its_value(tmp_path: Path, mode: str):
    result = solve_cli(tmp_path, BLOCK, "--mode", mode, "--format", "json")
    assert result.exit_code == 0, result.output
    answers = {a["name"]: a for a in json.loads(result.stdout)["answers"]}
    assert answers["P_s"]["value"] == pytest.approx(P_SLIP, rel=1e-6)
    assert answers["r"]["value"] == pytest.approx(P_SLIP / 10, rel=1e-6)
    assert answers["q"]["value"] == pytest.approx(P_SLIP / 10, rel=1e-6)
    terminal = solve_cli(tmp_path, BLOCK, "--mode", mode).stdout
    assert "slips(" not in terminal.split("Answers")[1]


@pytest.mark.parametrize("mode", MODES)
def test_a_define_built_on_steepest_has_its_value(tmp_path: Path, mode: str):
    result = solve_cli(tmp_path, STEEPEST, "--mode", mode, "--format", "json")
    assert result.exit_code == 0, result.output
    answers = {a["name"]: a for a in json.loads(result.stdout)["answers"]}
    assert answers["r"]["value"] == pytest.approx(2 * math.atan(0.4), rel=1e-6)


@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_an_answer_left_without_a_value_is_a_failed_check(monkeypatch, mode: str):
    # the threshold left unevaluated, as it was: the answer must not pass as text
    monkeypatch.setattr(
        "dynsolve.pipeline._View.with_thresholds", lambda self, expr: expr, raising=True
    )
    solution = solve_text(BLOCK, "b.dyn", SolveOptions(mode=mode))
    (check,) = [c for c in solution.checks if c.name == "value of r"]
    assert check.failed and "slips(G, 20) has no value" in check.detail
    assert not solution.passed  # the CLI exits 1
    data = json.loads(render_json(solution))
    assert {c["name"]: c["status"] for c in data["checks"]}["value of r"] == "failed"
    assert data["passed"] is False
    assert "✗  value of r" in render_text(solution)


def test_a_formula_in_t_or_in_symbolic_givens_is_an_answer(tmp_path: Path):
    # y(t) = v_0 sin θ t − g t²/2 is a formula by request; a symbolic W = m g likewise
    motion = "given:\n  v_0 = 3 m/s\nkinematics:\n  a_x = 0\n  a_y = -g\nfind: y_t = y(t)\n"
    symbolic = "given:\n  m: mass\nequations:\n  W = m*g\nfind: W\n"
    for text in (motion, symbolic):
        solution = solve_text(text, "f.dyn")
        assert solution.passed, [c for c in solution.checks if c.failed]
        assert not [c for c in solution.checks if c.name.startswith("value of")]
