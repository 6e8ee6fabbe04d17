"""A rejected trial is shown in full: its equations and values, the check with numbers, the
verdict, and a remark when the re-solve reverses a sense (issue: try-then-check collapsed)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from dynsolve.pipeline import solve_file
from dynsolve.render.json import render_json
from dynsolve.render.latex import render_latex
from dynsolve.render.markdown import render_markdown
from dynsolve.render.terminal import render_text

ROOT = Path(__file__).resolve().parent.parent
# Hibbeler 12e Example 17.15 (seed notes): pole, m = 100 kg, I_G = 75 kg m², L = 3 m, P = 400 N
# 1 m below G. No-slip trial (a_A = 0): ΣM_A gives α = −P h/(I_G + m L²/4) ... by hand:
#   a_Gx = −α L/2, −P h_P = I_G α − (L/2) m a_Gx  ->  α = −4 P h_P/(4 I_G + L² m)
#   = −4·400·0.5/(300 + 900) = −0.667 rad/s² (cw), a_Gx = 1.00 m/s², F_A = m a_Gx − P = −300 N
#   |F_A| = 300 N > μs N = 0.3·981 = 294.3 N: A slips; re-solved: α = +0.428 rad/s² (ccw).
POLE = ROOT / "problems" / "seed" / "gpm_seed_pole_slip.dyn"


@pytest.fixture(scope="module")
def pole():
    return solve_file(POLE)


def test_the_trial_keeps_its_values_and_check(pole) -> None:
    (trial,) = pole.trials
    assert trial.assumption == "no slip at A"
    values = {r.name: r.value for step in trial.steps for r in step.results}
    assert values["alpha"] == "-0.667 rad/s²"
    assert values["a_Gx"] == "1.00 m/s²"
    assert values["F_A"] == "-300 N"
    assert "300 N > μs N = 294.3 N" in trial.verdict
    assert len(trial.equations) == 5  # ΣF_x, ΣF_y, ΣM_A, contact kept, no slip


def test_a_reversed_sense_is_remarked(pole) -> None:
    (trial,) = pole.trials
    (remark,) = trial.remarks
    assert remark.startswith("α changes sign: -0.667 rad/s² in the trial, 0.428 rad/s²")


@pytest.mark.parametrize("render", [render_text, render_markdown, render_latex])
def test_every_renderer_shows_the_trial(pole, render) -> None:
    out = render(pole)
    assert "Trial: no slip at A" in out
    assert out.index("Trial: no slip at A") < out.rindex("Equations")
    assert "changes sign" in out


def test_json_holds_the_trial(pole) -> None:
    data = json.loads(render_json(pole))
    assert data["trials"][0]["assumption"] == "no slip at A"


def test_no_trial_when_the_assumption_holds() -> None:
    # Hibbeler 17.11 drum: a pin and a cord, nothing assumed that could fail
    assert solve_file(ROOT / "problems" / "seed" / "fa_hib_drum.dyn").trials == ()


def test_each_step_puts_the_numbers_in(pole) -> None:
    # after the slip: α = (P (L/2 − h_P)·2 ... written as sympy orders it, with the givens put
    # in: L = 3 m, N_A = 981 N, μk = 0.25, P = 400 N, h_P = 0.5 m, I_G = 75 kg·m²;
    # (−735.75 + 1200 − 400)/150 = 0.428 rad/s² (Hibbeler 17.15)
    results = {r.name: r for step in pole.steps for r in step.results}
    alpha = results["alpha"]
    assert alpha.substituted == "(-3*981*0.25 + 3*400 - 2*400*0.5)/(2*75)"
    assert alpha.value == "0.428 rad/s²"
    assert "\\cdot" in alpha.substituted_latex


def test_the_structure_check_names_the_unknowns(pole) -> None:
    # Hibbeler 17.15 writes "five unknowns" before solving; the scene has four here:
    # F_A (μk N_A once slipping), N_A, a_Gx, a_Gy, α minus the friction now known
    structure = next(c for c in pole.checks if c.name == "structure")
    assert structure.detail.startswith("4 unknowns (")
    for name in ("N_A", "a_Gx", "a_Gy", "α"):
        assert name in structure.detail
