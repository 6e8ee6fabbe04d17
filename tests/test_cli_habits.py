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


BARE_ANGLE = "given:\n  m = 2 kg\n  theta = 30\nequations:\n  W = m*g*sin(theta)\nfind: W\n"


def test_a_bare_number_in_sin_is_a_warning(workdir: Path) -> None:
    # sin(30 rad) = -0.988: the writer almost surely meant 30 deg (W sin 30° = 9.81 N)
    (workdir / "w.dyn").write_text(BARE_ANGLE)
    data = json.loads(run("solve", "w.dyn", "-f", "json").stdout)
    assert len(data["warnings"]) == 1
    assert "theta = 30 (line 3) has no unit" in data["warnings"][0]
    assert "1719°" in data["warnings"][0]  # 30 rad = 30·180/π = 1718.9°
    terminal = run("solve", "w.dyn").stdout
    assert "warning: bare angle" in terminal


INCLINE = """\
given:
  m = 5 kg
  beta = 20
  d = 2 m
scene:
  body block: particle, mass m, at (0, 0)
  contact block at G: normal angle pi/2 - beta, smooth
  gravity
  travel block: by d, angle -beta
find: v = speed(block)
"""


def test_a_bare_number_in_a_scene_angle_is_a_warning(workdir: Path) -> None:
    # regression (newcomer report): 'angle -beta' with beta = 20 read 20 rad with every
    # check green and no word (v = 5.99 m/s where 20° gives √(2 g d sin 20°) = 3.66 m/s)
    (workdir / "i.dyn").write_text(INCLINE)
    (warning,) = json.loads(run("solve", "i.dyn", "-f", "json").stdout)["warnings"]
    assert "beta = 20 (line 3) has no unit, so 'angle" in warning and "1146°" in warning


def test_an_angle_in_degrees_is_not_a_warning(workdir: Path) -> None:
    (workdir / "w.dyn").write_text(BARE_ANGLE.replace("theta = 30", "theta = 30 deg"))
    assert json.loads(run("solve", "w.dyn", "-f", "json").stdout)["warnings"] == []


def test_a_mass_in_pounds_is_a_warning_at_its_line(workdir: Path) -> None:
    text = "units: FPS\ngiven:\n  m = 40 lb\n  a = 3 ft/s^2\nequations:\n  F = m*a\nfind: F\n"
    (workdir / "f.dyn").write_text(text)
    data = json.loads(run("solve", "f.dyn", "-f", "json").stdout)
    assert any("m = 40 lb (line 3) is a force" in w for w in data["warnings"])


def test_fps_givens_are_shown_in_fps_base_units(workdir: Path) -> None:
    # 6 in = 0.5 ft; 2 lb stays 2 lb (FPS base units: ft, slug, s; lb for force)
    text = "units: FPS\ngiven:\n  r = 6 in\n  W = 2 lb\nequations:\n  M = W*r\nfind: M\n"
    (workdir / "m.dyn").write_text(text)
    data = json.loads(run("solve", "m.dyn", "-f", "json").stdout)
    bases = {g["name"]: g["base"] for g in data["givens"]}
    assert bases["r"] == "0.5 ft" and bases["W"] == "2 lb"
    assert "in FPS" in CliRunner().invoke(app, ["solve", "m.dyn"], terminal_width=120).stdout


def test_a_misspelt_unknown_is_named_in_the_error(workdir: Path) -> None:
    text = (
        "given:\n  I = 2 kg*m^2\n  r = 0.5 m\n  M = 3 N*m\n"
        "equations:\n  M = I*alpha\n  a = alpah*r\nfind: alpha, a\n"
    )
    (workdir / "t.dyn").write_text(text)
    result = run("solve", "t.dyn")
    assert result.exit_code == 2
    assert "'alpah' (line 7) and 'alpha' (line 6) differ by one slip" in result.stderr


def test_a_misspelt_given_is_a_warning(workdir: Path) -> None:
    # omga is a new unknown solved from the second equation; omega (the given) is unused
    text = (
        "given:\n  omega = 2 rad/s\n  r = 0.5 m\n  v = 3 m/s\n"
        "equations:\n  v = omga*r\nfind: omga\n"
    )
    (workdir / "t.dyn").write_text(text)
    data = json.loads(run("solve", "t.dyn", "-f", "json").stdout)
    assert "'omga' (line 6) looks like a misspelling of 'omega'" in " ".join(data["warnings"])


def test_pdflatex_is_limited_in_cpu_seconds_not_wall_time(monkeypatch: pytest.MonkeyPatch) -> None:
    # issue 25, item 12: on a busy machine (load 9 on 2 cores) a wall-clock limit stopped
    # pdflatex; the limit is its CPU seconds (RLIMIT_CPU), with a wall-clock backstop of
    # 10 times that against a hang. A process that computes past the limit gets SIGXCPU.
    import signal
    import subprocess
    import sys

    from dynsolve import pdf

    monkeypatch.setattr(pdf, "PDFLATEX_SECONDS", 1)
    limit = pdf.cpu_limit()
    if limit is None:
        pytest.skip("no RLIMIT_CPU on this platform")
    burn = [sys.executable, "-c", "while True: pass"]
    done = subprocess.run(burn, preexec_fn=limit, timeout=60, check=False)
    assert done.returncode == -signal.SIGXCPU
    # a process that waits (as behind others for a core) is not stopped by the limit
    wait = [sys.executable, "-c", "import time; time.sleep(1.5)"]
    assert subprocess.run(wait, preexec_fn=limit, timeout=60, check=False).returncode == 0
