"""Compile a LaTeX solution sheet to PDF with pdflatex (``-o sheet.pdf``).

The document is dynsolve's own output (every spec text in it escaped); pdflatex runs
with shell escape off, in a fresh temporary folder, non-interactively, under a limit of
CPU seconds (``RLIMIT_CPU``, where the platform has it: a busy machine slows the wall
clock, not the work) with a generous wall-clock backstop against a hang.

>>> import shutil
>>> shutil.which("pdflatex") is None or compile_pdf(
...     "\\\\documentclass{article}\\\\begin{document}x\\\\end{document}").startswith(b"%PDF")
True
"""

from __future__ import annotations

import shutil
import signal
import subprocess
import tempfile
from collections.abc import Callable, Mapping
from pathlib import Path

from dynsolve.errors import DynsolveError

PDFLATEX_SECONDS = 60  # CPU seconds per pass (wall seconds where there is no RLIMIT_CPU)
WALL_FACTOR = 10  # the wall-clock backstop, in CPU limits
PACKAGES = "texlive-latex-base texlive-latex-recommended texlive-pictures texlive-science"


class PdfError(DynsolveError):
    """pdflatex is missing or could not compile the sheet."""


def compile_pdf(latex: str, files: Mapping[str, bytes] | None = None) -> bytes:
    """The PDF of the LaTeX document ``latex`` (two passes, for references); ``files`` are
    written beside it first (a figure it includes, by its bare name)."""
    pdflatex = shutil.which("pdflatex")
    if pdflatex is None:
        raise PdfError(
            "cannot write a PDF: pdflatex is not installed",
            hint=f"install TeX Live (Debian: apt-get install {PACKAGES}), or write the "
            ".tex with -o sheet.tex",
        )
    with tempfile.TemporaryDirectory(prefix="dynsolve-pdf-") as folder:
        source = Path(folder) / "sheet.tex"
        source.write_text(latex, encoding="utf-8")
        for name, data in (files or {}).items():
            (Path(folder) / Path(name).name).write_bytes(data)
        command = [pdflatex, "-no-shell-escape", "-interaction=nonstopmode", "-halt-on-error"]
        limit = cpu_limit()
        for _ in range(2):
            try:
                done = subprocess.run(
                    [*command, source.name],
                    cwd=folder,
                    capture_output=True,
                    timeout=PDFLATEX_SECONDS * (WALL_FACTOR if limit else 1),
                    check=False,
                    stdin=subprocess.DEVNULL,
                    preexec_fn=limit,  # only sets a limit: safe between fork and exec
                )
            except subprocess.TimeoutExpired:
                raise PdfError(
                    f"pdflatex ran past {PDFLATEX_SECONDS * (WALL_FACTOR if limit else 1)} s "
                    "of wall time",
                    hint="write the .tex instead",
                ) from None
            if limit is not None and done.returncode == -getattr(signal, "SIGXCPU", 0):
                raise PdfError(
                    f"pdflatex ran past {PDFLATEX_SECONDS} s of CPU", hint="write the .tex instead"
                )
            if done.returncode != 0:
                log = done.stdout.decode("utf-8", errors="replace")
                first = next((line for line in log.splitlines() if line.startswith("!")), "")
                missing = "not found" in log and (".sty" in first or "File `" in log)
                raise PdfError(
                    f"pdflatex could not compile the sheet: {first or 'see its log'}",
                    hint=f"a LaTeX package is missing: install {PACKAGES} (TikZ, siunitx)"
                    if missing
                    else "write the .tex with -o sheet.tex and compile it yourself",
                )
        return (Path(folder) / "sheet.pdf").read_bytes()


def cpu_limit() -> Callable[[], None] | None:
    """A function that caps the CPU seconds of the process it runs in (pdflatex, before it
    starts), or None where the platform has no RLIMIT_CPU (Windows)."""
    try:
        import resource
    except ImportError:
        return None
    if not hasattr(resource, "RLIMIT_CPU"):
        return None

    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_CPU, (PDFLATEX_SECONDS, PDFLATEX_SECONDS + 5))

    return limit
