"""Parametric sweeps: ``dynsolve sweep`` through typer's CliRunner, and ``dynsolve.sweep``.

Expected values are textbook formulas, worked by hand:

- the drum and hanging block, Hibbeler 12e Example 17.11 (problems/seed/fa_hib_drum.dyn):
  ΣM_O = I_O α with T r, and m_b g − T = m_b a, a = α r, give
  α = m_b g r / (m_b r² + m_d k_O²), T = m_b (g − α r), a = α r (down, the drum turns cw);
- the disk on an incline (problems/seed/gpm_seed_incline_threshold.dyn, Hibbeler 17-94
  style): rolling, a_G = g sin β / (1 + k²/R²) = (2/3) g sin β, α = a_G/R and the friction
  it needs F = m a_G / 2 = (1/3) m g sin β; no slip needs F ≤ μs N = μs m g cos β, that is
  tan β ≤ 3 μs = tan β* (tan β* = μs (1 + R²/k²) with k² = R²/2): 0.6 for μs = 0.2. Past it,
  sliding with F = μk N: a_G = g (sin β − μk cos β), α = μk N R / (m R²/2) = 2 μk g cos β / R.
"""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np
import pint
import pytest
from typer.testing import CliRunner, Result

import dynsolve
from dynsolve.cli import app
from dynsolve.errors import DynsolveError
from dynsolve.parametric.command import sweep_spec
from dynsolve.parametric.evaluate import sweep_points
from dynsolve.parametric.ranges import Axis
from dynsolve.safe_csv import escape_cell as safe_cell
from dynsolve.spec.parser import parse_file, parse_spec
from dynsolve.units import registry

ROOT = Path(__file__).resolve().parent.parent
DRUM = ROOT / "problems" / "seed" / "fa_hib_drum.dyn"
INCLINE = ROOT / "problems" / "seed" / "gpm_seed_incline_threshold.dyn"
G = 9.81
M_D, K_O, R_DRUM = 60.0, 0.25, 0.4  # the drum's givens (Hibbeler 17.11)
M_DISK, R_DISK, MU_S, MU_K = 5.0, 0.2, 0.2, 0.15  # the incline's givens


def drum_alpha(m_b: float, r: float = R_DRUM) -> float:
    """Hibbeler 17.11: α = m_b g r / (m_b r² + m_d k_O²)."""
    return m_b * G * r / (m_b * r**2 + M_D * K_O**2)


def run(*args: str | Path) -> Result:
    result = CliRunner().invoke(app, ["sweep", *(str(a) for a in args)])
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise AssertionError(f"uncaught {result.exception!r}") from result.exception
    assert "Traceback" not in result.output
    return result


def read_csv(path: Path) -> list[dict[str, str]]:
    with path.open(encoding="utf-8", newline="") as handle:
        return list(csv.DictReader(handle))


def test_drum_table_matches_hibbeler_formula(tmp_path: Path) -> None:
    out = tmp_path / "drum.csv"
    result = run(DRUM, "m_b=10..30 kg", "--points", "5", "-o", out)
    assert result.exit_code == 0, result.output
    rows = read_csv(out)
    assert [float(r["m_b [kg]"]) for r in rows] == [10, 15, 20, 25, 30]
    for row in rows:
        m_b = float(row["m_b [kg]"])
        alpha = drum_alpha(m_b)
        assert float(row["alpha [rad/s^2]"]) == pytest.approx(alpha, rel=1e-9)
        assert float(row["T [N]"]) == pytest.approx(m_b * (G - alpha * R_DRUM), rel=1e-9)
        assert float(row["a [m/s^2]"]) == pytest.approx(alpha * R_DRUM, rel=1e-9)
        assert (row["alpha direction"], row["a direction"]) == ("cw", "down")
        assert (row["regime"], row["path"]) == ("as assumed", "closed form")
    assert "5 points of" in result.stdout
    assert "closed form: 5 points" in result.stdout
    assert "11.29" in result.stdout  # m_b = 20 kg: 78.48/6.95 = 11.29 rad/s², the textbook's


def test_step_percent_and_other_units_follow_the_vary_grammar(tmp_path: Path) -> None:
    out = tmp_path / "step.csv"
    assert run(DRUM, "m_b=10..30 kg step 0.5", "-o", out).exit_code == 0
    assert len(read_csv(out)) == 41  # (30 − 10)/0.5 + 1
    spread = tmp_path / "spread.csv"
    assert run(DRUM, "m_b=±10%", "--points", "3", "-o", spread).exit_code == 0
    assert [float(r["m_b [kg]"]) for r in read_csv(spread)] == pytest.approx([18, 20, 22])
    grams = tmp_path / "grams.csv"
    assert run(DRUM, "m_b=10000..30000 g", "--points", "3", "-o", grams).exit_code == 0
    for row in read_csv(grams):
        alpha = drum_alpha(float(row["m_b [g]"]) / 1000)
        assert float(row["alpha [rad/s^2]"]) == pytest.approx(alpha, rel=1e-9)


def test_incline_slips_past_the_threshold_and_is_marked(tmp_path: Path) -> None:
    out = tmp_path / "incline.csv"
    plot = tmp_path / "incline.png"
    result = run(
        INCLINE, "tan_beta=0.3..0.9 step 0.05", "--answers", "a_G,alpha,F", "-o", out,
        "--plot", plot,
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    rows = read_csv(out)
    assert len(rows) == 13
    for row in rows:
        tan_beta = float(row["tan_beta"])
        sin, cos = tan_beta / math.hypot(1, tan_beta), 1 / math.hypot(1, tan_beta)
        if tan_beta <= 3 * MU_S + 1e-12:  # rolls: tan β ≤ μs (1 + R²/k²) = 0.6
            assert row["regime"] == "as assumed"
            a_G = 2 / 3 * G * sin
            friction = M_DISK * a_G / 2
            assert friction <= MU_S * M_DISK * G * cos * (1 + 1e-9)
        else:  # slides: F = μk N
            assert row["regime"] == "slips at C"
            a_G = G * (sin - MU_K * cos)
            friction = MU_K * M_DISK * G * cos
        alpha = 2 * MU_K * G * cos / R_DISK if tan_beta > 0.6 + 1e-12 else a_G / R_DISK
        assert float(row["a_G [m/s^2]"]) == pytest.approx(a_G, rel=1e-9)
        assert float(row["alpha [rad/s^2]"]) == pytest.approx(alpha, rel=1e-9)
        assert float(row["F [N]"]) == pytest.approx(friction, rel=1e-9)
    threshold = next(r for r in rows if float(r["tan_beta"]) == 0.6)
    assert threshold["path"] == "per point"  # impending slip: at the condition's edge
    assert all(r["path"] == "closed form" for r in rows if r is not threshold)
    assert "the regime changes between tan_beta = 0.6000 and 0.6500" in result.stdout
    assert "as assumed → slips at C" in result.stdout
    assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_find_without_closed_form_is_solved_per_point_and_says_why(tmp_path: Path) -> None:
    out = tmp_path / "incline.csv"
    result = run(INCLINE, "tan_beta=0.3..0.5", "--points", "2", "-o", out)
    assert result.exit_code == 0, result.output
    rows = read_csv(out)
    assert [r["path"] for r in rows] == ["per point", "per point"]
    assert "steepest" in result.stdout
    # the steepest slope it rolls down: tan β* = 0.6, β* = atan 0.6 = 30.96°
    assert float(rows[0]["beta_max [deg]"]) == pytest.approx(math.degrees(math.atan(0.6)))


def test_two_ranges_give_a_grid_and_a_contour_plot(tmp_path: Path) -> None:
    out = tmp_path / "grid.csv"
    plot = tmp_path / "grid.svg"
    result = run(DRUM, "m_b=10..30 kg", "r=0.3..0.5 m", "--points", "3", "-o", out, "--plot", plot)
    assert result.exit_code == 0, result.output
    rows = read_csv(out)
    pairs = [(float(r["m_b [kg]"]), float(r["r [m]"])) for r in rows]
    assert pairs == [(m, r) for m in (10, 20, 30) for r in (0.3, 0.4, 0.5)]  # long format
    for row, (m_b, r) in zip(rows, pairs, strict=True):
        assert float(row["alpha [rad/s^2]"]) == pytest.approx(drum_alpha(m_b, r), rel=1e-9)
    assert "9 points (3 × 3 grid)" in result.stdout
    assert b"<svg" in plot.read_bytes()[:500]


def test_json_table(tmp_path: Path) -> None:
    out = tmp_path / "drum.json"
    assert (
        run(DRUM, "m_b=10..20 kg", "--points", "2", "--answers", "alpha", "-o", out).exit_code == 0
    )
    document = json.loads(out.read_text(encoding="utf-8"))
    assert [c["name"] for c in document["columns"]] == [
        "m_b [kg]", "alpha [rad/s^2]", "alpha direction", "regime", "path",
    ]  # fmt: skip
    first = document["points"][0]
    assert first["alpha [rad/s^2]"] == pytest.approx(drum_alpha(10), rel=1e-12)
    assert document["paths"] == {"closed form": 2, "per point": 0}


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["m_x=1..2 kg"], "<range 1>:1:1: 'm_x' is not a given"),
        (["m_b=1..2 m"], "'m_b' is mass (given in kg), but its range is length"),
        (["m_b=2..2 kg"], "the range of 'm_b' is empty"),
        (["m_b=3..2 kg"], "runs backwards"),
        (["m_b=1..2 kg", "r=0.1..0.5 m", "--points", "1001"], "the limit is 1000000"),
        (["m_b=1..2 kg step 0.5", "--points", "3"], "has a step and --points is given too"),
        (["m_b=1..2 kg", "m_b=3..4 kg"], "'m_b' is swept twice"),
        (["m_b=1..2 kg", "--answers", "alpha,beta"], "'beta' is not a find"),
        (["m_b=1..2 kg", "-o", "table.txt"], "use .csv or .json"),
        (["m_b=1..2 kg", "r=1..2 m", "k_O=1..2 m", "--plot", "x.png"], "one or two givens"),
    ],
)
def test_bad_input_is_a_clear_error(args: list[str], message: str, tmp_path: Path) -> None:
    result = run(DRUM, *[str(tmp_path / a) if a.endswith((".txt", ".png")) else a for a in args])
    assert result.exit_code == 2
    assert message in " ".join(result.stderr.split())
    assert "hint" in result.stderr


def test_unit_error_points_into_the_range() -> None:
    result = run(DRUM, "m_b=1..2 m")
    assert "<range 1>:1:10" in result.stderr  # the unit's column in 'm_b=1..2 m'
    assert "m_b=1..2 m" in result.stderr  # the range quoted with a caret


def test_csv_cells_are_safe_for_spreadsheets() -> None:
    assert safe_cell("=HYPERLINK(1)") == "'=HYPERLINK(1)"
    assert safe_cell("+1+2") == "'+1+2"
    assert safe_cell("-x") == "'-x"
    assert safe_cell("@x") == "'@x"
    assert safe_cell("-2.5e-3") == "-2.5e-3"  # a plain number stays a number
    assert safe_cell("cw") == "cw"


def test_closed_form_agrees_with_exact_solves_at_10000_points() -> None:
    spec = parse_file(DRUM)
    result = sweep_spec(spec, ["m_b=1..100 kg"], points=10_000)
    assert result.counts() == {"closed form": 10_000, "per point": 0}
    alpha = result.answers[0].values
    masses = result.givens["m_b"]
    assert np.allclose(alpha, drum_alpha(masses), rtol=1e-12, atol=0)  # type: ignore[arg-type]
    sample = np.array([0, 1234, 5000, 9999])
    axis = Axis("m_b", "kg", masses[sample], 1.0)
    exact = sweep_points(spec, (axis,), (axis.values,), (4,), vectorize=False)
    assert list(exact.paths) == ["per point"] * 4
    for fast, slow in zip(result.answers, exact.answers, strict=True):
        assert np.allclose(fast.values[sample], slow.values, rtol=1e-9, atol=0)


def test_api_returns_pint_arrays() -> None:
    masses = registry().Quantity(np.array([10.0, 20.0, 30.0]), "kg")
    result = dynsolve.sweep(DRUM, m_b=masses)
    alpha = result["alpha"]
    assert alpha.shape == (3,)
    assert alpha.to("rad/s^2").magnitude == pytest.approx(drum_alpha(masses.magnitude), rel=1e-9)
    assert result["m_b"].to("g").magnitude.tolist() == [10_000, 20_000, 30_000]
    assert result.path.tolist() == ["closed form"] * 3
    assert result.directions("alpha").tolist() == ["cw"] * 3


def test_api_plain_numbers_grids_and_errors() -> None:
    grid = np.meshgrid([10.0, 20.0], [0.3, 0.4], indexing="ij")
    result = dynsolve.sweep(DRUM, m_b=grid[0], r=grid[1], answers=["alpha"])
    assert result["alpha"].shape == (2, 2)
    assert result["alpha"].magnitude[1, 0] == pytest.approx(drum_alpha(20, 0.3), rel=1e-9)
    other = pint.UnitRegistry()  # a quantity of the caller's own registry converts too
    grams = dynsolve.sweep(DRUM, m_b=other.Quantity([20_000.0], "gram"), answers=["alpha"])
    assert grams["alpha"].magnitude[0] == pytest.approx(78.48 / 6.95, rel=1e-9)  # 17.11
    with pytest.raises(DynsolveError, match="'m_b' is given in kg; its values are in meter"):
        dynsolve.sweep(DRUM, m_b=other.Quantity([1.0], "m"))
    ranges = dynsolve.sweep(DRUM, m_b="10..30 kg", r="0.3..0.5 m", points=3)
    assert ranges["T"].shape == (3, 3)
    with pytest.raises(DynsolveError, match="not a given"):
        dynsolve.sweep(DRUM, mass=[1.0])
    with pytest.raises(DynsolveError, match="cannot be mixed"):
        dynsolve.sweep(DRUM, m_b="10..30 kg", r=[0.3])


def test_example_notebook_runs(monkeypatch: pytest.MonkeyPatch) -> None:
    # the notebook is the project's own file: its code cells run in order in one namespace
    notebook = json.loads((ROOT / "examples" / "sweep.ipynb").read_text(encoding="utf-8"))
    assert all(not c.get("outputs") for c in notebook["cells"])  # outputs cleared
    monkeypatch.chdir(ROOT)
    namespace: dict[str, object] = {}
    for cell in notebook["cells"]:
        if cell["cell_type"] == "code":
            exec(compile("".join(cell["source"]), "sweep.ipynb", "exec"), namespace)
    assert namespace["largest"] < 1e-12  # the closed form against Hibbeler 17.11's formula
    # the first slipping slope: past tan β* = 3 μs = 0.6, the next point of 0.3..0.9 by 0.01
    assert namespace["first_slip"] == pytest.approx(0.61)
    assert namespace["grid"]._repr_png_()[:4] == b"\x89PNG"  # type: ignore[attr-defined]


def test_a_point_whose_check_fails_has_no_values(tmp_path: Path) -> None:
    # equation mode writes no slip as the constraint F <= mu_s*N; with F = m g sin β / 3
    # (rolling) and N = m g cos β, it fails where tan β > 3 μs: μs = 0.1 at tan β = 0.6
    spec = ROOT / "problems" / "equations" / "gpm_seed_incline_threshold.dyn"
    out = tmp_path / "eq.csv"
    result = run(spec, "mu_s=0.1..0.3", "--points", "3", "-o", out)
    assert result.exit_code == 0, result.output
    rows = read_csv(out)
    assert rows[0]["regime"] == "a check fails"
    assert rows[0]["a_G [m/s^2]"] == ""  # no value computed under a failed constraint
    assert "no root satisfies the constraints" in rows[0]["note"]
    assert float(rows[2]["a_G [m/s^2]"]) == pytest.approx(2 / 3 * G * 0.6 / math.hypot(1, 0.6))


def test_too_many_full_solves_stop_early_with_the_reason() -> None:
    # beta_max (steepest) has no closed form: 1000 full solves of ~0.1-0.5 s each cannot
    # fit in 10 s, which the first few solves show
    result = run(INCLINE, "tan_beta=0.3..0.9", "--points", "1000", "--time-budget", "10")
    assert result.exit_code == 2
    stderr = " ".join(result.stderr.split())
    assert (
        "1000 points need a full solve each (beta_max (steepest) is answered per point)" in stderr
    )
    assert "--answers" in stderr


def test_vary_sections_still_need_a_step() -> None:
    # the sweep's optional step is the sweep's only: a vary: line without one is an error
    text = "given:\n  m = 50 kg\nvary:\n  m = 40..60 kg\nequations:\n  W = m*g\nfind: W\n"
    with pytest.raises(DynsolveError, match="cannot read the variation of 'm'"):
        parse_spec(text, "p.dyn")


def test_a_crate_that_tips_is_marked_and_left_without_values(tmp_path: Path) -> None:
    # problems/scenes/crate_push_tips.dyn (hand derivation in its header): sliding right,
    # N = m g = 490.5 N, F = μk N = 98.1 N, a = (P − 98.1)/50; ΣM_G = 0 puts N at
    # x = (0.45 P + 73.575)/490.5 from G, inside the base while x ≤ 0.5 m: P ≤ 381.5 N
    spec = ROOT / "problems" / "scenes" / "crate_push_tips.dyn"
    out = tmp_path / "tip.csv"
    plot = tmp_path / "tip.pdf"
    result = run(
        spec, "P=100..500 N", "--points", "9", "--answers", "a,x_C", "-o", out, "--plot", plot
    )
    assert result.exit_code == 0, result.output
    for row in read_csv(out):
        push = float(row["P [N]"])
        if push <= 381.5:
            assert row["regime"] == "as assumed"
            assert float(row["a [m/s^2]"]) == pytest.approx((push - 98.1) / 50, rel=1e-9)
            assert float(row["x_C [m]"]) == pytest.approx((0.45 * push + 73.575) / 490.5)
        else:
            assert row["regime"] == "tips on C"
            assert row["a [m/s^2]"] == row["x_C [m]"] == ""
    assert "as assumed → tips on C" in result.stdout
    assert plot.read_bytes()[:5] == b"%PDF-"


def test_an_unknown_unit_in_a_range_points_into_the_range() -> None:
    result = run(DRUM, "m_b=1..2 kgs")
    assert result.exit_code == 2
    assert "<range 1>:1:10: unknown unit 'kgs'" in result.stderr  # not the spec's line 1
    assert "did you mean 'kg'" in result.stderr
