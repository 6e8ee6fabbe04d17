"""The Python API (``dynsolve.solve``, ``dynsolve.check``) and the example notebook."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import dynsolve
from dynsolve.errors import DynsolveError

ROOT = Path(__file__).resolve().parent.parent
DRUM = ROOT / "problems" / "seed" / "fa_hib_drum.dyn"
WEIGHT = "given:\n  m = 2 kg\nequations:\n  W = m*g\nfind: W\n"


def test_solve_a_path_gives_pint_quantities() -> None:
    # Hibbeler 12e Example 17.11: alpha = m_b g r / (I_O + m_b r^2) = 78.48/6.95 = 11.29 rad/s^2,
    # T = I_O alpha / r = 105.9 N, a = alpha r = 4.517 m/s^2
    result = dynsolve.solve(DRUM)
    assert result.passed
    assert result["alpha"].to("rad/s^2").magnitude == pytest.approx(78.48 / 6.95, rel=1e-9)
    assert result["T"].to("N").magnitude == pytest.approx(3.75 * 78.48 / 6.95 / 0.4, rel=1e-9)
    assert result["a"].to("ft/s^2").magnitude == pytest.approx(
        78.48 / 6.95 * 0.4 / 0.3048, rel=1e-9
    )


def test_solve_text_and_str_path_agree() -> None:
    from_text = dynsolve.solve(DRUM.read_text())
    from_str = dynsolve.solve(str(DRUM))
    assert from_text["T"] == from_str["T"]


def test_lb_is_a_force_in_answers() -> None:
    # 40 lb weight: m = W/g = 40/32.2 = 1.242 slug (g = 32.2 ft/s^2 in FPS)
    spec = "units: FPS\ngiven:\n  W = 40 lb\nequations:\n  m = W/g\nfind: m [slug]\n"
    mass = dynsolve.solve(spec)["m"]
    assert mass.to("slug").magnitude == pytest.approx(40 / 32.2, rel=1e-12)


def test_symbolic_answer_is_its_formula() -> None:
    spec = "given:\n  m: mass\nequations:\n  W = m*g\nfind: W\n"
    assert "m" in dynsolve.solve(spec)["W"]


def test_bad_spec_raises_with_position() -> None:
    with pytest.raises(DynsolveError, match="did you mean 'kg'") as caught:
        dynsolve.solve("given:\n  m = 2 kgs\nequations:\n  W = m*g\nfind: W\n")
    assert caught.value.position is not None
    assert (caught.value.position.line, caught.value.position.column) == (2, 9)


def test_unknown_answer_name_lists_answers() -> None:
    result = dynsolve.solve(WEIGHT)
    with pytest.raises(KeyError, match="the answers are W"):
        result["w"]


def test_time_budget_stops_a_runaway_spec() -> None:
    from dynsolve.budget import OverBudget

    spec = "given:\n  a = 2\nequations:\n  x^7 + a*x^3 + sin(x) = exp(x) + y\n  y = x\nfind: x, y\n"
    with pytest.raises(OverBudget):
        dynsolve.solve(spec, time_budget=0.1)


def test_displays_show_the_answers() -> None:
    result = dynsolve.solve(DRUM)
    assert "106 N" in result._repr_markdown_()
    html = result._repr_html_()
    assert html.startswith("<") and "106" in html
    assert result._repr_latex_().startswith("$$\\begin{aligned}")


def test_check_reports_passed_failed_and_malformed(tmp_path: Path) -> None:
    (tmp_path / "good.dyn").write_text(WEIGHT + "answers:\n  W = 19.6 N\n")
    (tmp_path / "wrong.dyn").write_text(WEIGHT + "answers:\n  W = 30 N\n")
    (tmp_path / "bad.dyn").write_text(WEIGHT.replace("2 kg", "2 kgs"))
    results = {Path(c.file).name: c for c in dynsolve.check([tmp_path])}
    assert results["good.dyn"].passed
    assert not results["wrong.dyn"].passed and results["wrong.dyn"].failed
    assert results["bad.dyn"].errors and "kgs" in results["bad.dyn"].errors[0]


def test_example_notebook_runs(monkeypatch: pytest.MonkeyPatch) -> None:
    # the notebook is the project's own file: its code cells run in order in one namespace
    notebook = json.loads((ROOT / "examples" / "python-api.ipynb").read_text())
    monkeypatch.chdir(ROOT)
    namespace: dict[str, object] = {}
    for cell in notebook["cells"]:
        if cell["cell_type"] == "code":
            exec(compile("".join(cell["source"]), "python-api.ipynb", "exec"), namespace)
    assert namespace["result"].passed  # type: ignore[attr-defined]
    assert namespace["mass"].to("kg").magnitude == pytest.approx(40 / 32.2 * 14.593903, rel=1e-6)  # type: ignore[attr-defined]
    checks = namespace["checks"]
    assert not any(c.failed for c in checks)  # type: ignore[attr-defined]
