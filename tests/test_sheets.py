"""Solution sheets: the full sheet, the handout a teacher gives out, the marker's key; the
PDF they compile to is not blank."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.pipeline import solve_file
from dynsolve.render.latex import render_latex
from dynsolve.render.markdown import render_markdown

ROOT = Path(__file__).resolve().parent.parent
CRATE = ROOT / "problems" / "seed" / "tr_hib_crate.dyn"  # Hibbeler 12e Example 17.7


@pytest.fixture(scope="module")
def crate():
    return solve_file(CRATE)


@pytest.mark.parametrize("render", [render_latex, render_markdown])
def test_the_handout_has_the_derivation_but_no_key(crate, render) -> None:
    sheet = render(crate, "handout")
    assert "Equations" in sheet and "Answers" in sheet
    for internal in ("tr_hib_crate.dyn", "status", "Answer key", "off by", "Checks"):
        assert internal not in sheet, internal


@pytest.mark.parametrize("render", [render_latex, render_markdown])
def test_the_key_has_answers_key_and_checks_only(crate, render) -> None:
    sheet = render(crate, "key")
    assert "Answer key" in sheet and "Checks" in sheet and "off by" in sheet
    assert "Equations" not in sheet and "Given" not in sheet


def test_answers_keep_their_direction(crate) -> None:
    # Hibbeler 17.7: a_G = 10.0 m/s^2 to the right, N_C = 490 N up
    assert "right" in render_markdown(crate).split("## Answers")[1].split("## Checks")[0]
    assert " up" in render_latex(crate).split("Answers")[1]


def test_handout_and_key_together_are_refused(tmp_path: Path) -> None:
    result = CliRunner().invoke(app, ["solve", str(CRATE), "--handout", "--key"])
    assert result.exit_code == 2 and "two different sheets" in result.stderr


@pytest.mark.latex
@pytest.mark.parametrize("layout", ["--handout", "--key"])
def test_the_pdf_pages_are_not_blank(tmp_path: Path, layout: str) -> None:
    if shutil.which("pdflatex") is None or shutil.which("pdftoppm") is None:
        pytest.skip("pdflatex or pdftoppm (poppler-utils) is not installed")
    pdf = tmp_path / "sheet.pdf"
    result = CliRunner().invoke(app, ["solve", str(CRATE), "-o", str(pdf), layout])
    assert result.exit_code == 0, result.output
    subprocess.run(
        ["pdftoppm", "-gray", "-r", "20", "-f", "1", "-l", "1", str(pdf), str(tmp_path / "p")],
        check=True,
        timeout=60,
    )
    (page,) = tmp_path.glob("p*.pgm")
    pixels = page.read_bytes().split(b"\n", 3)[3]  # P5 header: magic, size, maxval
    dark = sum(1 for value in pixels if value < 128)
    assert dark > 0.005 * len(pixels)  # text and rules, not an empty page


# ---- the motion plot in the sheet (issue 12 part 6: "the same figure in the LaTeX sheet")
CAR = ROOT / "problems" / "kinematics" / "car_braking.dyn"


def test_a_kinematics_sheet_includes_its_motion_plot_written_beside_it(tmp_path: Path) -> None:
    tex = tmp_path / "car.tex"
    result = CliRunner().invoke(app, ["solve", str(CAR), "-o", str(tex)])
    assert result.exit_code == 0, result.output
    figure = tmp_path / "car-motion.pdf"
    assert figure.read_bytes().startswith(b"%PDF")
    sheet = tex.read_text()
    assert "\\usepackage{graphicx}" in sheet
    assert "\\includegraphics[width=0.85\\linewidth]{car-motion.pdf}" in sheet


def test_a_scene_sheet_or_the_key_has_no_motion_plot(tmp_path: Path) -> None:
    for spec, layout, name in ((CRATE, [], "crate.tex"), (CAR, ["--key"], "key.tex")):
        CliRunner().invoke(app, ["solve", str(spec), "-o", str(tmp_path / name), *layout])
        assert "includegraphics" not in (tmp_path / name).read_text()
    assert not list(tmp_path.glob("*-motion.pdf"))


@pytest.mark.latex
def test_a_kinematics_pdf_compiles_with_its_plot(tmp_path: Path) -> None:
    if shutil.which("pdflatex") is None or shutil.which("pdftotext") is None:
        pytest.skip("pdflatex or pdftotext (poppler-utils) is not installed")
    pdf = tmp_path / "car.pdf"
    result = CliRunner().invoke(app, ["solve", str(CAR), "-o", str(pdf)])
    assert result.exit_code == 0, result.output
    text = subprocess.run(
        ["pdftotext", str(pdf), "-"], capture_output=True, text=True, check=True, timeout=60
    ).stdout
    assert "Figure 1: The motion" in text
    assert not list(tmp_path.glob("*-motion.pdf"))  # compiled in, not left beside it
