"""The handout a teacher posts (issue 29, deliverable 3): no spec internals (line tags, file
name, source text unless asked), a failed trial shown before its failure is stated, and no
raw ASCII mathematics in the typeset text, in LaTeX and HTML alike."""

from __future__ import annotations

import re
import shutil
import subprocess
from html.parser import HTMLParser
from pathlib import Path

import pytest
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.pipeline import solve_file
from dynsolve.render.html import render_html
from dynsolve.render.latex import caption_latex, render_latex
from dynsolve.render.markdown import render_markdown

ROOT = Path(__file__).resolve().parents[1]
SEED = ROOT / "problems" / "seed"
POLE = SEED / "gpm_seed_pole_slip.dyn"  # Hibbeler 12e Example 17.15: no slip fails
CUBE = SEED / "ci_seed_cube_lip.dyn"  # its source: line states the answer
SEEDS = [
    "fa_hib_drum",
    "gpm_seed_pole_slip",
    "ci_seed_cube_lip",
    "rwe_seed_disk40lb",
    "we_seed_collar",
    "3d_seed_plate_diagonal",
    "moi_hib_plate_hole",
    "ci_seed_cube_lip-symbolic",
    "3d_seed_bar_shaft",
]


@pytest.fixture(scope="module")
def solutions():
    return {name: solve_file(SEED / f"{name}.dyn") for name in SEEDS}


# ---- what the handout's text is, outside its mathematics and figures

_ENVIRONMENTS = re.compile(r"\\begin\{(tikzpicture|equation\*|align\*)\}.*?\\end\{\1\}", re.S)
_MATH = re.compile(r"(?<!\\)\$[^$]*(?<!\\)\$|\\\[.*?\\\]", re.S)


def latex_prose(tex: str) -> str:
    """The document's body without its displayed and inline mathematics or pictures."""
    body = tex.split("\\begin{document}", 1)[1]
    return _STARRED.sub(" ", _MATH.sub(" ", _ENVIRONMENTS.sub(" ", body)))


_STARRED = re.compile(r"\\[a-zA-Z]+\*")  # \section*


class _Prose(HTMLParser):
    """The text a reader sees outside <math>, <svg>, <style> and <title>."""

    def __init__(self) -> None:
        super().__init__()
        self.text: list[str] = []
        self._hidden = 0

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self._hidden += tag in ("math", "svg", "style", "title")

    def handle_endtag(self, tag: str) -> None:
        self._hidden -= tag in ("math", "svg", "style", "title")

    def handle_data(self, data: str) -> None:
        if not self._hidden:
            self.text.append(data)


def html_prose(page: str) -> str:
    parser = _Prose()
    parser.feed(page)
    parser.close()
    return "\n".join(parser.text)


# ---- no spec internals


@pytest.mark.parametrize("name", SEEDS)
def test_the_latex_handout_numbers_its_equations_and_names_no_spec(solutions, name) -> None:
    solution = solutions[name]
    tex = render_latex(solution, "handout")
    assert "(line " not in tex and "(lines " not in tex
    assert name not in tex and ".dyn" not in tex
    assert caption_latex(solution.source) not in tex
    tags = [int(n) for n in re.findall(r"\\tag\*\{\((\d+)\)\}", tex)]
    assert tags == list(range(1, len(tags) + 1))  # (1), (2), … in order
    assert tags or not solution.equations


@pytest.mark.parametrize("name", SEEDS)
def test_the_html_handout_numbers_its_equations_and_names_no_spec(solutions, name) -> None:
    solution = solutions[name]
    page = render_html(solution, "handout")
    prose = html_prose(page)
    assert "(line " not in prose and "(lines " not in prose
    assert name not in page and not re.search(r"\.dyn\b", page)
    assert solution.source.strip() and solution.source not in prose
    tags = [int(n) for n in re.findall(r'<span class="tag">\((\d+)\)</span>', page)]
    assert tags == list(range(1, len(tags) + 1))
    assert tags or not solution.equations


def test_the_source_line_that_gives_the_answer_away_is_left_out_unless_asked(tmp_path) -> None:
    # the cube's source: line ends "(answer v > 4 sqrt(a g (sqrt2-1)/3))"
    for fmt in ("latex", "html", "markdown"):
        plain = CliRunner().invoke(app, ["solve", str(CUBE), "--format", fmt, "--handout"])
        assert plain.exit_code == 0, plain.output
        assert "answer v" not in plain.stdout and "cube tips over lip" not in plain.stdout
        cited = CliRunner().invoke(
            app, ["solve", str(CUBE), "--format", fmt, "--handout", "--source"]
        )
        assert cited.exit_code == 0, cited.output
        assert "cube tips over lip" in cited.stdout, fmt
    key = CliRunner().invoke(app, ["solve", str(CUBE), "--format", "latex", "--key"]).stdout
    assert "cube tips over lip" in key  # whoever marks sees where it comes from


def test_the_markdown_handout_leaves_out_the_source_and_line_numbers_too(solutions) -> None:
    solution = solutions["fa_hib_drum"]
    assert "Hibbeler" not in render_markdown(solution, "handout")
    assert "Hibbeler" in render_markdown(solution, "full")
    handout = render_markdown(solutions["gpm_seed_pole_slip"], "handout")
    assert "(line " not in handout and "(lines " not in handout and "| No. |" in handout
    assert "Equations (3) and (5) give" in handout  # the trial's ΣM_A and no-slip relation


# ---- every symbol typeset

_RAW_LATEX = re.compile(r"\*|\\_|sqrt\(|\\\^\{\}|\\textasciicircum")
_RAW_HTML = re.compile(r"\*|_|sqrt\(|\^")


@pytest.mark.parametrize("name", SEEDS)
def test_the_handouts_have_no_raw_ascii_maths_in_their_text(solutions, name) -> None:
    solution = solutions[name]
    tex_prose = latex_prose(render_latex(solution, "handout"))
    raw = [line for line in tex_prose.splitlines() if _RAW_LATEX.search(line)]
    assert not raw, raw
    page_prose = html_prose(render_html(solution, "handout"))
    raw = [line for line in page_prose.splitlines() if _RAW_HTML.search(line)]
    assert not raw, raw


def test_the_disk_springs_stretch_is_typeset(solutions) -> None:
    # the spring's caption in the spec says "s_2 = 2*s_G": the sheet writes 2 s_G
    tex = render_latex(solutions["rwe_seed_disk40lb"], "handout")
    assert "2*" not in tex and "= 2$s_{G}$" in tex


def test_touching_formulas_do_not_open_display_maths() -> None:
    assert "$$" not in caption_latex("αH_G and (Ḣ_G + ω × H_G)_y")


# ---- the failed trial first, then its failure, then the re-solve


def test_the_failed_trial_comes_before_its_failure_and_the_re_solve(solutions) -> None:
    # Hibbeler 17.15: no slip needs F = 300 N > μs N = 294.3 N, so the pole slips
    tex = render_latex(solutions["gpm_seed_pole_slip"], "handout")
    trial = tex.index("Trial: no slip at A")
    assert trial < tex.index("(\\textbf{fails})") and trial < tex.index("Check:")
    assert tex.index("Check:") < tex.index("\\subsection*{Assumptions}")
    assert tex.index("\\subsection*{Assumptions}") < tex.index("Equations (re-solved)")
    # the trial's F_A + P = m a_Gx and the re-solve's -μk N_A + P = m a_Gx: two numbers
    assert "F_{A} + P = a_{Gx} m \\tag*{(1)}" in tex
    assert re.search(r"- N_\{A\} \\mu_\{k\} \+ P = a_\{Gx\} m \\tag\*\{\((\d+)\)\}", tex)[1] != "1"


def test_the_html_page_shows_the_trial_before_its_failure(solutions) -> None:
    prose = html_prose(render_html(solutions["gpm_seed_pole_slip"], "handout"))
    trial = prose.index("Trial: no slip at A")
    assert trial < prose.index("(fails)") and prose.index("Assumptions") > trial
    assert prose.index("Equations (re-solved)") > prose.index("(fails)")


# ---- the pages are filled


@pytest.mark.latex
def test_the_pole_handouts_first_page_is_filled(tmp_path: Path) -> None:
    # the free-body diagram once went whole to page 2, leaving half of page 1 empty
    if shutil.which("pdflatex") is None or shutil.which("pdftotext") is None:
        pytest.skip("pdflatex or pdftotext (poppler-utils) is not installed")
    pdf = tmp_path / "pole.pdf"
    result = CliRunner().invoke(app, ["solve", str(POLE), "-o", str(pdf), "--handout"])
    assert result.exit_code == 0, result.output
    first = subprocess.run(
        ["pdftotext", "-f", "1", "-l", "1", str(pdf), "-"],
        capture_output=True,
        text=True,
        check=True,
        timeout=60,
    ).stdout
    assert "Free-body diagrams" in first and "pole (body)" in first
