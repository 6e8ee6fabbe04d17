"""Work and energy term by term (issue 12, part 1): T1, each U(1→2) with its value, T2."""

from __future__ import annotations

import json
from pathlib import Path

from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.pipeline import solve_file

DISK = Path(__file__).resolve().parent.parent / "problems" / "seed" / "rwe_seed_disk40lb.dyn"


def test_the_disk_against_a_spring_term_by_term():
    # seed notes (40-lb disk, 15 ft·lb couple, spring wound at the top): from rest T1 = 0;
    # U_M = M Δθ = 15 (0.5/0.8) = 9.375 ft·lb; U_S = −½ k s₂² with s₂ = 2 s_G = 1 ft: −5 ft·lb;
    # U(1→2) = −5 + 9.375 = 4.375 ft·lb; T2 = T1 + ΣU = 4.375 ft·lb (by hand)
    terms = {t.name: t for t in solve_file(DISK).energy}
    assert list(terms) == ["T1", "U_S", "U_M", "U_12", "omega_2", "T2"]
    assert terms["omega_2"].formula == "v_2_disk/r"  # rolling: ω₂ = v₂/r, before T2 uses it
    assert terms["U_12"].value == "4.38 lb·ft"
    assert terms["T1"].value == "0 lb·ft"
    assert terms["U_S"].value == "-5.00 lb·ft" and terms["U_S"].formula == "-2*k*s_G^2"
    assert terms["U_M"].value == "9.38 lb·ft" and terms["U_M"].formula == "M*s_G/r"
    assert terms["T2"].value == "4.38 lb·ft"
    assert "v_2_disk" in terms["T2"].formula  # T2 in the unknown speed, valued at the answer


def test_the_terms_are_in_every_output():
    runner = CliRunner()
    text = runner.invoke(app, ["solve", str(DISK)]).stdout
    assert "Work and energy, term by term" in text
    data = json.loads(runner.invoke(app, ["solve", str(DISK), "-f", "json"]).stdout)
    assert [t["name"] for t in data["energy"]] == ["T1", "U_S", "U_M", "U_12", "omega_2", "T2"]
    markdown = runner.invoke(app, ["solve", str(DISK), "-f", "markdown"]).stdout
    assert "## Work and energy" in markdown
    latex = runner.invoke(app, ["solve", str(DISK), "-f", "latex"]).stdout
    assert "Work and energy" in latex and "\\frac{M s_{G}}{r}" in latex


def test_a_problem_at_an_instant_has_no_energy_terms():
    drum = DISK.parent / "fa_hib_drum.dyn"
    assert solve_file(drum).energy == ()
