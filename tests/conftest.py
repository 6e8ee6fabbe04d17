"""Fixtures shared by the test modules."""

import os
import shutil
import subprocess

import pytest
from hypothesis import settings


@pytest.fixture
def pdflatex() -> str:
    """pdflatex's path, with TikZ and siunitx; skipped when missing, unless CI is set (CI
    installs texlive-latex-recommended, texlive-pictures and texlive-science)."""
    path = shutil.which("pdflatex")
    kpsewhich = shutil.which("kpsewhich")
    packages = [
        name
        for name in ("tikz.sty", "siunitx.sty")
        if not kpsewhich
        or not subprocess.run([kpsewhich, name], capture_output=True, text=True).stdout.strip()
    ]
    if path and not packages:
        return path
    missing = "pdflatex" if not path else ", ".join(packages)
    if os.environ.get("CI"):
        pytest.fail(
            f"{missing} missing although CI is set: install texlive-latex-recommended, "
            "texlive-pictures and texlive-science"
        )
    pytest.skip(f"{missing} is not installed")


# No per-example deadline: CI machines are shared and slower than a laptop; the
# examples are bounded by their strategies instead.
settings.register_profile("dynsolve", deadline=None)
settings.load_profile("dynsolve")
