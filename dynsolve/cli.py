"""The command line: parse options, call the core, render, print, and set the exit code.

The only module that prints. sympy and pint are imported inside the commands, so
``dynsolve --help`` stays fast.
"""

from __future__ import annotations

import enum
import os
import tempfile
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.console import Console

if TYPE_CHECKING:
    from dynsolve.results import Solution


class ExitCode(enum.IntEnum):
    """Process exit codes."""

    OK = 0  # solved; every check and answer passed
    FAILED = 1  # an answer or a check failed
    BAD_INPUT = 2  # the input or the command line is wrong


class OutputFormat(enum.StrEnum):
    """Formats of ``dynsolve solve``."""

    text = "text"
    json = "json"
    markdown = "markdown"
    latex = "latex"


class Mode(enum.StrEnum):
    """Solve modes: exact (rationals, radicals, formulas) or numeric (floating point)."""

    exact = "exact"
    numeric = "numeric"


app = typer.Typer(
    help="Solve and check engineering-dynamics problems written as plain-text .dyn specs.",
    no_args_is_help=True,
    add_completion=False,
    context_settings={"help_option_names": ["-h", "--help"]},
)
stdout = Console(highlight=False)
stderr = Console(stderr=True, highlight=False)
CHECK_PROGRESS_THRESHOLD = 8  # show a progress bar from this many files on


def _version(value: bool) -> None:
    if value:
        from dynsolve import __version__

        stdout.print(f"dynsolve {__version__}")
        raise typer.Exit()


@app.callback()
def main_callback(
    version: Annotated[
        bool, typer.Option("--version", callback=_version, is_eager=True, help="Show the version.")
    ] = False,
) -> None:
    """Solve and check engineering-dynamics problems written as plain-text .dyn specs.

    Write the problem in the spec language (docs/spec-language.md), then
    `dynsolve solve FILE` prints a unit-checked derivation, and
    `dynsolve check PATH...` compares every spec with its answer key.
    """


@app.command()
def solve(
    file: Annotated[Path, typer.Argument(help="The .dyn spec to solve.", show_default=False)],
    format: Annotated[
        OutputFormat, typer.Option("--format", "-f", help="Output format.")
    ] = OutputFormat.text,
    output: Annotated[
        Path | None,
        typer.Option("--output", "-o", help="Write to this file instead of the terminal."),
    ] = None,
    mode: Annotated[
        Mode, typer.Option(help="exact: rationals and formulas; numeric: floating point.")
    ] = Mode.exact,
    time_budget: Annotated[
        float,
        typer.Option(min=0.1, max=600, help="Seconds a nonlinear block may take symbolically."),
    ] = 5.0,
) -> None:
    """Solve one spec and show its unit-checked derivation.

    Shows the givens, each equation with its unit check, the solve order, the
    answers to 3 significant figures and the checks. Exit code 0 when every check
    and answer passes, 1 when one fails, 2 for bad input.
    """
    from dynsolve.errors import DynsolveError
    from dynsolve.pipeline import solve_file
    from dynsolve.system import SolveOptions

    if output is not None:
        _refuse_overwriting_input(file, output)
    try:
        solution = solve_file(file, SolveOptions(mode=mode.value, time_budget=time_budget))
    except DynsolveError as error:
        _report(error)
        raise typer.Exit(ExitCode.BAD_INPUT) from None
    _emit(solution, format, output)
    raise typer.Exit(ExitCode.OK if solution.passed else ExitCode.FAILED)


@app.command()
def check(
    paths: Annotated[
        list[Path],
        typer.Argument(help="Spec files or folders (searched for *.dyn).", show_default=False),
    ],
    mode: Annotated[Mode, typer.Option(help="Solve mode for every spec.")] = Mode.exact,
) -> None:
    """Solve every .dyn spec under PATHS and compare it with its answer key.

    Prints a table of the failures and ends with 'N passed, M failed'. Exit code 0
    only when all pass; 1 when an answer or check fails; 2 when a spec is malformed.
    """
    from dynsolve.errors import DynsolveError
    from dynsolve.pipeline import solve_file
    from dynsolve.render.terminal import failures_table
    from dynsolve.system import SolveOptions

    files = _collect(paths)
    options = SolveOptions(mode=mode.value)
    failures: list[tuple[str, object]] = []
    passed = failed = 0
    worst = ExitCode.OK
    for file in _progress(files):
        try:
            solution = solve_file(file, options)
        except DynsolveError as error:
            failures.append((str(file), str(error)))
            failed += 1
            worst = ExitCode.BAD_INPUT
            continue
        if solution.passed:
            passed += 1
            continue
        failed += 1
        worst = max(worst, ExitCode.FAILED)
        failures.extend((str(file), c) for c in solution.checks if not c.passed)
    if failures:
        stdout.print(failures_table(failures))  # type: ignore[arg-type]
    stdout.print(f"{passed} passed, {failed} failed")
    raise typer.Exit(worst)


def _collect(paths: list[Path]) -> list[Path]:
    files: list[Path] = []
    for path in paths:
        if path.is_dir():
            files.extend(sorted(path.rglob("*.dyn")))
        elif path.is_file():
            files.append(path)
        else:
            _fail(f"{path}: no such file or folder", "check the path")
    if not files:
        _fail("no .dyn files found", "pass spec files or folders that hold them")
    return files


def _progress(files: list[Path]):  # type: ignore[no-untyped-def]
    if len(files) < CHECK_PROGRESS_THRESHOLD or not stderr.is_terminal:
        yield from files
        return
    from rich.progress import track

    yield from track(files, description="checking", console=stderr, transient=True)


def _emit(solution: Solution, format: OutputFormat, output: Path | None) -> None:
    from dynsolve.render import renderer

    if output is None and format is OutputFormat.text:
        from dynsolve.render.terminal import solution_renderable

        stdout.print(solution_renderable(solution))
        return
    text = renderer(format.value)(solution)
    if output is None:
        stdout.out(text, end="", highlight=False)
        return
    _write_atomically(output, text)
    stderr.print(f"wrote {output}")


def _refuse_overwriting_input(spec: Path, output: Path) -> None:
    same = output.exists() and spec.exists() and output.resolve() == spec.resolve()
    if same or output.suffix.lower() == ".dyn":
        _fail(f"refusing to write output to {output}: it is a spec file", "choose another -o path")
    if output.is_dir():
        _fail(f"cannot write {output}: it is a folder", "give a file name, e.g. -o out.tex")


def _fail(message: str, hint: str) -> None:
    stderr.out(f"error: {message} (hint: {hint})", highlight=False)
    raise typer.Exit(ExitCode.BAD_INPUT)


def _write_atomically(path: Path, text: str) -> None:
    """Write via a temporary file and rename, so a failure never leaves half a file."""
    directory = path.resolve().parent
    if not directory.is_dir():
        _fail(f"cannot write {path}: folder {directory} does not exist", "create it first")
    handle, temporary = tempfile.mkstemp(dir=directory, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as stream:
            stream.write(text)
        os.chmod(temporary, _file_mode(path))
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


def _file_mode(path: Path) -> int:
    """The mode an ordinary new file gets (or the existing file's), not mkstemp's 0600."""
    if path.exists():
        return path.stat().st_mode & 0o777
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask


def _report(error: Exception) -> None:
    from dynsolve.errors import DynsolveError

    assert isinstance(error, DynsolveError)
    for each in (error, *getattr(error, "others", ())):
        stderr.out(f"error: {each}", highlight=False)


def main() -> None:
    """Console-script entry point."""
    app()
