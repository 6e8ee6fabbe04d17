"""Command-line habits: stdin, the format from -o's suffix, errors with a caret, every error
of a file at once, JSON errors, text from specs never read as rich markup."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from specs import DRUM
from typer.testing import CliRunner, Result

from dynsolve.cli import app

# Hibbeler 12e Example 17.11 (see tests/test_cli.py for the hand derivation):
# T = 14715/139 N = 105.86 N.
T_NEWTONS = 14715 / 139


def run(*args: str | Path, stdin: str | None = None) -> Result:
    result = CliRunner().invoke(app, [str(a) for a in args], input=stdin)
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise AssertionError(f"uncaught {result.exception!r}") from result.exception
    assert "Traceback" not in result.output
    return result


@pytest.fixture
def workdir(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_dash_reads_the_spec_from_stdin() -> None:
    result = run("solve", "-", "-f", "json", stdin=DRUM)
    assert result.exit_code == 0
    answers = {a["name"]: a for a in json.loads(result.stdout)["answers"]}
    assert answers["T"]["value"] == pytest.approx(T_NEWTONS, rel=1e-9)


def test_stdin_errors_name_stdin_and_quote_the_line() -> None:
    result = run("solve", "-", stdin=DRUM.replace("m_d = 60 kg ", "m_d = 60 kgs"))
    assert result.exit_code == 2
    assert "<stdin>:6:12: unknown unit 'kgs'" in result.stderr
    assert " 6 |   m_d = 60 kgs" in result.stderr
    # the caret sits under column 12 and spans the three letters of "kgs"
    caret = next(line for line in result.stderr.splitlines() if "^" in line)
    assert caret.index("^") - caret.index("|") - 1 == 12 and caret.count("^") == 3


@pytest.mark.parametrize(
    ("suffix", "marker"),
    [(".json", '"answers"'), (".md", "# Drum and hanging block"), (".tex", "\\documentclass")],
)
def test_the_output_format_follows_the_suffix(workdir: Path, suffix: str, marker: str) -> None:
    (workdir / "drum.dyn").write_text(DRUM)
    result = run("solve", "drum.dyn", "-o", f"out{suffix}")
    assert result.exit_code == 0
    assert marker in (workdir / f"out{suffix}").read_text()


def test_an_explicit_format_wins_over_the_suffix(workdir: Path) -> None:
    (workdir / "drum.dyn").write_text(DRUM)
    assert run("solve", "drum.dyn", "-o", "out.tex", "-f", "json").exit_code == 0
    assert json.loads((workdir / "out.tex").read_text())["answers"]


def test_pdf_without_pdflatex_is_a_clear_error(
    workdir: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import shutil

    (workdir / "drum.dyn").write_text(DRUM)
    monkeypatch.setattr(shutil, "which", lambda name: None)
    result = run("solve", "drum.dyn", "-o", "sheet.pdf")
    assert result.exit_code == 2
    assert "pdflatex is not installed" in result.stderr
    assert not (workdir / "sheet.pdf").exists()


@pytest.mark.latex
def test_pdf_is_compiled_when_pdflatex_is_there(workdir: Path) -> None:
    import shutil

    if shutil.which("pdflatex") is None:
        pytest.skip("pdflatex is not installed")
    (workdir / "drum.dyn").write_text(DRUM)
    assert run("solve", "drum.dyn", "-o", "sheet.pdf").exit_code == 0
    assert (workdir / "sheet.pdf").read_bytes().startswith(b"%PDF")


def test_every_bad_line_is_reported_at_once(workdir: Path) -> None:
    bad = DRUM.replace("T*r = I_O*alpha", "T*r = I_O*+*alpha").replace("a = alpha*r", "a = = r")
    (workdir / "drum.dyn").write_text(bad)
    result = run("solve", "drum.dyn")
    assert result.exit_code == 2
    assert result.stderr.count("error: drum.dyn:") == 2


def test_every_bad_unit_of_the_givens_at_once(workdir: Path) -> None:
    text = "given:\n  m = 2 kgs\n  v = 3 m/s2\nequations:\n  p = m*v\nfind: p\n"
    (workdir / "p.dyn").write_text(text)
    result = run("solve", "p.dyn")
    assert "p.dyn:2:9: unknown unit 'kgs' (hint: did you mean 'kg'?)" in result.stderr
    assert "p.dyn:3:11: unknown unit 's2' (hint: write the power with '^': 's^2')" in result.stderr


def test_json_errors_go_to_stdout_as_json(workdir: Path) -> None:
    (workdir / "drum.dyn").write_text(DRUM.replace("m_d = 60 kg ", "m_d = 60 kgs"))
    result = run("solve", "drum.dyn", "-f", "json")
    assert result.exit_code == 2
    error = json.loads(result.stdout)["error"]
    assert error == {
        "file": "drum.dyn",
        "line": 6,
        "column": 12,
        "message": "unknown unit 'kgs'",
        "hint": "did you mean 'kg'?",
    }


def test_check_table_keeps_square_brackets() -> None:
    # "[kg]" in a failure's detail is text, not rich markup: it must be printed as written
    from rich.console import Console

    from dynsolve.render.terminal import failures_table
    from dynsolve.results import Check

    console = Console(width=200, record=True, file=open("/dev/null", "w"))  # noqa: SIM115
    failure = Check("answer m", False, "expected m [kg] = 2; got 3 [kg]")
    console.print(failures_table([("[bold]d.dyn", failure), ("e.dyn", "bad [kg] unit")]))
    text = console.export_text()
    assert "expected m [kg] = 2; got 3 [kg]" in text
    assert "[bold]d.dyn" in text and "bad [kg] unit" in text


def test_help_shows_clean_metavars() -> None:
    result = CliRunner().invoke(app, ["solve", "--help"], terminal_width=120)
    assert "FILE" in result.stdout and "<path>" not in result.stdout
    result = CliRunner().invoke(app, ["check", "--help"], terminal_width=120)
    assert "{PATH...}" in result.stdout
