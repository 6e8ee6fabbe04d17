"""The LaTeX renderer: escaping (unit and property-based), document content, pdflatex runs."""

from __future__ import annotations

import re
import shutil
import subprocess
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from latex_tools import compile_pdf
from specs import DRUM

from dynsolve.pipeline import solve_file
from dynsolve.render import latex
from dynsolve.render.latex import escape_latex, render_latex, safe_math
from dynsolve.results import (
    AnswerRow,
    Check,
    EquationRow,
    Formula,
    GivenRow,
    KeyComparison,
    Solution,
    Step,
)

REPO = Path(__file__).resolve().parents[1]

SPECS = {
    # the drum with LaTeX-special characters in a note
    "drum": DRUM.replace("(drum), CCW positive", "(drum) & 100% of the torque"),
    "roots": """\
problem: Positive root of a quadratic {with $ and #}
source: made up_for_tests ~ ^
given:
  k = 2 1/s^2   # stiffness per inertia
  c = 3 1/s     # damping per inertia
equations:
  w^2 - c*w - k = 0   # characteristic equation
  w >= 0              # ω ≥ 0: the positive root
find: w
answers:
  w = 3.56 rad/s
""",
    "symbolic": """\
problem: Free fall, symbolic
given:
  h: length           # drop height
  m = 2 kg            # mass (unused by v)
equations:
  m*g*h = m*v^2/2     # T₁ + V₁ = T₂ + V₂
find: v
answers:
  v = sqrt(2*g*h)
""",
    "fps": """\
problem: Crate pushed on a floor (FPS)
units: FPS
given:
  W = 40 lb        # crate weight
  P = 10 lb        # push
  mu_k = 0.2       # kinetic friction
equations:
  m = W/g                 # mass from weight
  N - W = 0               # ΣF_y = 0
  P - mu_k*N = m*a        # ΣF_x = m a_x
find: a [ft/s^2], N [lb]
answers:
  a = 1.61 ft/s^2
""",
}

NASTY = (
    'Σ \\ & % $ # _ { } ~ ^ < > | [x] "q" ² ³ m²·s⁻¹ ± ≤ ≥ − — – ° π ω α Ω ✓ ✗ é ñ ß ☃ 😀'
    " \n\n\t tab\x00nul\u200bzw ½ ﬁ ｆ ‰ 30°C x₁ \\\\ %comment"
)

TEXT_STRATEGY = st.one_of(
    st.text(),
    st.text(alphabet=st.sampled_from(list(NASTY) + list("αβγΔΣΩ²³⁻·±≤≥−—°✓\\&%$#_{}~^"))),
)

# Everything escape_latex may emit outside math, and what it may emit inside ``$...$``.
ESCAPE_TOKEN = re.compile(
    r"\\[&%$#_{}]|\\[A-Za-z]+\{\}|\\[\^~]\{\}|\\[`'^~\"=.uvHcr]\{\\?[A-Za-z]\}|\{[\[\]]\}"
)
MATH_SPAN = re.compile(r"\$([^$]*)\$")
MATH_BODY = re.compile(
    r"(?:\\[A-Za-z]+|\\mathrm\{[A-Z]\}|[ \-]"
    r"|\{\}[\^_]\{(?:[0-9a-z+\-=()/]|\{\\(?:circ|prime|prime\\prime)\})*\})*"
)
SPECIAL = set("\\&%$#_{}~^")


def unescaped_specials(out: str) -> set[str]:
    """The TeX special characters left in ``out`` once its escapes and math are taken out."""
    text = ESCAPE_TOKEN.sub("", out)
    for body in MATH_SPAN.findall(text):
        assert MATH_BODY.fullmatch(body), f"unexpected math {body!r} in {out!r}"
    return SPECIAL & set(MATH_SPAN.sub("", text))


# ---- escaping: unit tests


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("\\", r"\textbackslash{}"),
        ("&%$#_{}", r"\&\%\$\#\_\{\}"),
        ("~^", r"\~{}\^{}"),
        ("a < b > c | d", r"a \textless{} b \textgreater{} c \textbar{} d"),
        ("[x]", "{[}x{]}"),
        ('"q"', "''q''"),
        ("α", r"$\alpha$"),
        ("Σ", r"$\Sigma$"),
        ("Ωω", r"$\Omega \omega$"),
        ("m²", "m${}^{2}$"),
        ("s⁻²", "s${}^{-2}$"),
        ("30°", "30${}^{{\\circ}}$"),
        ("x₁₂", "x${}_{12}$"),
        ("a·b", r"a$\cdot$b"),
        ("± ≤ ≥ −", r"$\pm$ $\leq$ $\geq$ $-$"),
        ("α·β²", r"$\alpha \cdot \beta {}^{2}$"),
        ("✓ ✗", r"$\checkmark$ $\times$"),
        ("a — b – c", "a --- b -- c"),
        ("café naïve", r"caf\'{e} na\"{\i}ve"),
        ("ß", r"\ss{}"),
        ("½", "1/2"),
        ("☃", "?"),
        ("a\nb\tc", "a b c"),
        ("a\x00b\u200bc", "abc"),
        ("a\u00a0b\u202fc", "a b c"),
        ("", ""),
    ],
)
def test_escape_latex(text: str, expected: str) -> None:
    assert escape_latex(text) == expected


def test_escape_latex_keeps_plain_text() -> None:
    plain = "Drum and hanging block (Hibbeler 12e Example 17.11), 60-kg drum: ok? yes!"
    assert escape_latex(plain) == plain


@pytest.mark.parametrize(
    ("fragment", "expected"),
    [
        (
            r"\frac{I_{O} g m_{b}}{I_{O} + m_{b} r^{2}}",
            r"\frac{I_{O} g m_{b}}{I_{O} + m_{b} r^{2}}",
        ),
        (r"50\,\mathrm{N·m}", r"50\,\mathrm{N \cdot m}"),
        ("α", r" \alpha "),
        ("x²", "x {}^{2} "),
        ("a—b", r"a\text{---}b"),
        ("50% #1 $", r"50\% \#1 \$"),
        (r"50\% done", r"50\% done"),
        ("a\nb", "a b"),
    ],
)
def test_safe_math(fragment: str, expected: str) -> None:
    assert safe_math(fragment) == expected


# ---- escaping: properties


@given(TEXT_STRATEGY)
def test_escape_latex_is_ascii_without_unescaped_specials(text: str) -> None:
    out = escape_latex(text)
    assert out.isascii()
    assert all(c.isprintable() for c in out)
    assert unescaped_specials(out) == set()


@given(st.text(alphabet=st.sampled_from(list("abcXYZ019 .,;:!?()+-=*/@'"))))
def test_escape_latex_leaves_safe_ascii_alone(text: str) -> None:
    assert escape_latex(text) == text


@given(TEXT_STRATEGY)
def test_safe_math_is_ascii(text: str) -> None:
    out = safe_math(text)
    assert out.isascii()
    assert all(c.isprintable() for c in out)
    assert not re.search(r"(?<!\\)[%#$]", out)


# ---- documents


def nasty_solution(text: str = NASTY) -> Solution:
    """A hand-built solution with ``text`` in every plain-text field."""
    return Solution(
        file=f"{text}.dyn",
        title=text,
        source=text,
        system=text,
        mode="equations",
        givens=(
            GivenRow("m_d", text, text, text, False, "m_{d}", "60\\,\\mathrm{kg}"),
            GivenRow("L", text, text, text, True, "L", "\\text{symbolic}"),
        ),
        equations=(
            EquationRow(3, text, "T r = I_{O} α", text, text, True, False),
            EquationRow(4, text, "ω \\ge 0", text, text, False, True),
        ),
        steps=(
            Step(
                1,
                (3, 4, 5),
                ("T", "omega"),
                text,
                (
                    Formula("T", text, "\\frac{a}{b}", text, "106\\,\\mathrm{N}"),
                    Formula("omega", "", "", text, "3.00\\,\\mathrm{rad/s}"),
                ),
                (text, text),
                text,
            ),
            Step(
                2,
                (7, 9),
                ("theta_ddot",),
                text,
                (Formula("theta_ddot", text, "x", text, "x"),),
                (),
                "",
            ),
        ),
        answers=(
            AnswerRow("T", 105.9, "N", "106 N", text, "106\\,\\mathrm{N}", "up"),
            AnswerRow("omega", None, "rad/s", "not determined", "", "", ""),
        ),
        checks=(Check(text, True, text), Check(text, False, text)),
        key=(KeyComparison("T", text, text, False, text),),
        status=text,
        messages=(text, text),
    )


def solve_spec(tmp_path: Path, name: str) -> Solution:
    path = tmp_path / f"{name}.dyn"
    path.write_text(SPECS[name], encoding="utf-8")
    return solve_file(path)


def assert_document(tex: str, solution: Solution) -> None:
    """The skeleton, the title and every answer's shown value are in the document."""
    lines = tex.splitlines()
    assert lines[0] == r"\documentclass[11pt]{article}"
    assert lines[-1] == r"\end{document}"
    assert r"\begin{document}" in lines
    assert tex.isascii()
    assert f"\\section*{{{escape_latex(solution.title)}}}" in tex
    for answer in solution.answers:
        if answer.latex:
            assert safe_math(answer.latex).strip() in tex
        else:
            assert escape_latex(answer.shown) in tex


@pytest.mark.parametrize("name", sorted(SPECS))
def test_document_content(tmp_path: Path, name: str) -> None:
    solution = solve_spec(tmp_path, name)
    tex = render_latex(solution)
    assert_document(tex, solution)
    for heading in ("Given", "Equations", "Solution", "Answers", "Checks"):
        assert f"\\subsection*{{{heading}}}" in tex


def test_drum_reads_like_a_solution(tmp_path: Path) -> None:
    tex = render_latex(solve_spec(tmp_path, "drum"))
    assert "Hibbeler 12e Example 17.11" in tex
    assert r"$m_{d}$ & $\qty{60}{kg}$ & 60" in tex  # siunitx for every quantity
    assert r"I_{O} = m_{d} k_{O}^{2} \tag*{(line 12)}" in tex
    # the caption's symbols typeset as mathematics, the words around them escaped
    assert r"$\Sigma M_{O}$ = $I_{O}$ $\alpha$ (drum) \& 100\% of the torque" in tex
    assert r"{[}force, N{]}~$\checkmark$" in tex
    assert r"Equations (lines 13--15) give $T$, $\alpha$ and $a$ (linear):" in tex
    # formula, then the givens put in (I_O = 3.75 kg·m², g = 9.81, m_b = 20 kg, r = 0.4 m), then T
    assert (
        r"T &= \frac{I_{O} g m_{b}}{I_{O} + m_{b} r^{2}} = "
        r"\frac{3.75 \cdot 9.81 \cdot 20}{3.75 + 20 \cdot 0.4^{2}} = \qty{106}{N}"
    ) in tex
    assert "11.3 rad/s${}^{2}$ $\\pm$ 0.5\\%" in tex  # the answer key, units prettified
    assert "All 6 checks passed." in tex


def test_discarded_roots_are_listed(tmp_path: Path) -> None:
    solution = solve_spec(tmp_path, "roots")
    assert solution.steps[0].discarded
    tex = render_latex(solution)
    assert "Discarded roots:" in tex
    assert "violates w \\textgreater{}= 0" in tex


def test_failed_checks_and_missing_answers_are_shown() -> None:
    tex = render_latex(nasty_solution("plain"))
    assert r"\textbf{1 of 2 checks failed.}" in tex
    assert r"\item[$\times$] \textbf{plain} (failed): plain" in tex
    assert r"\textit{not determined}" in tex
    assert r"\textbf{dimensions differ}" in tex
    assert "Constraint: plain" in tex


def test_nasty_text_is_escaped_everywhere() -> None:
    solution = nasty_solution()
    tex = render_latex(solution)
    assert_document(tex, solution)
    assert escape_latex(NASTY) in tex
    assert "\x00" not in tex


# ---- pdflatex


def pdf_text(pdf: Path) -> str | None:
    """The PDF's text, or None without pdftotext."""
    tool = shutil.which("pdftotext")
    if tool is None:
        return None
    result = subprocess.run([tool, str(pdf), "-"], capture_output=True, text=True, check=True)
    return result.stdout


@pytest.mark.latex
@pytest.mark.parametrize("name", sorted(SPECS))
def test_spec_compiles(tmp_path: Path, name: str, pdflatex: str) -> None:
    solution = solve_spec(tmp_path, name)
    pdf = compile_pdf(render_latex(solution), tmp_path, pdflatex)
    text = pdf_text(pdf)
    if text is not None:
        assert " ".join(solution.title.split()[:3]) in " ".join(text.split())


@pytest.mark.latex
def test_nasty_solution_compiles(tmp_path: Path, pdflatex: str) -> None:
    compile_pdf(render_latex(nasty_solution()), tmp_path, pdflatex)


@pytest.mark.latex
def test_every_mapped_character_compiles(tmp_path: Path, pdflatex: str) -> None:
    tables = (latex._TEXT_SPECIAL, latex._TEXT_UNICODE, latex._GREEK, latex._SYMBOLS,
              latex._SUPERSCRIPTS, latex._SUBSCRIPTS)  # fmt: skip
    mapped = "".join(char for table in tables for char in table)
    accented = "àáâãāăȧäåőǎç ÀÉÎÕÜ íïĳ"
    everything = " ".join([mapped, accented, "".join(map(chr, range(32, 127)))])
    compile_pdf(render_latex(nasty_solution(everything)), tmp_path, pdflatex)


@pytest.mark.latex
@settings(
    max_examples=4, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(st.lists(TEXT_STRATEGY, min_size=1, max_size=8))
def test_random_text_compiles(pdflatex: str, texts: list[str]) -> None:
    tex = render_latex(nasty_solution(" | ".join(texts)))
    with tempfile.TemporaryDirectory() as directory:
        compile_pdf(tex, Path(directory), pdflatex)


def repo_specs() -> list[Path]:
    return sorted(REPO.glob("problems/**/*.dyn"))


@pytest.mark.latex
@pytest.mark.parametrize("spec", repo_specs(), ids=lambda p: str(p.relative_to(REPO)))
def test_repo_problem_compiles(spec: Path, tmp_path: Path, pdflatex: str) -> None:
    solution = solve_file(spec)  # every bundled problem must solve
    tex = render_latex(solution)
    assert_document(tex, solution)
    compile_pdf(tex, tmp_path, pdflatex)


def test_numbers_put_in_a_product_keep_their_dots():
    # newcomer report: the sheet printed "(−6.372) 10 · 1" for α m r_G with the numbers in
    from dynsolve.pipeline import solve_text

    spec = "given:\n  m = 10 kg\n  a = -2 m/s^2\nequations:\n  F = m*a\nfind: F\n"
    tex = render_latex(solve_text(spec))
    assert "(-2) \\cdot 10" in tex or "10 \\cdot (-2)" in tex
