"""Compile LaTeX in tests."""

import subprocess
from pathlib import Path


def compile_pdf(tex: str, directory: Path, pdflatex: str) -> Path:
    """Run pdflatex once on ``tex`` in ``directory``; the PDF it wrote."""
    source = directory / "solution.tex"
    source.write_text(tex, encoding="ascii")
    result = subprocess.run(
        [pdflatex, "-interaction=nonstopmode", "-halt-on-error", source.name],
        cwd=directory,
        capture_output=True,
        text=True,
        errors="replace",
        timeout=300,
        stdin=subprocess.DEVNULL,
    )
    assert result.returncode == 0, result.stdout[-3000:]
    pdf = directory / "solution.pdf"
    assert pdf.is_file() and pdf.stat().st_size > 0
    return pdf
