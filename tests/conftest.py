"""Fixtures shared by the test modules."""

import os
import shutil

import pytest
from hypothesis import settings


@pytest.fixture
def pdflatex() -> str:
    """pdflatex's path; skipped when missing, unless CI is set (CI installs texlive)."""
    path = shutil.which("pdflatex")
    if path:
        return path
    if os.environ.get("CI"):
        pytest.fail("pdflatex is missing although CI is set: install texlive-latex-recommended")
    pytest.skip("pdflatex is not installed")


# No per-example deadline: CI machines are shared and slower than a laptop; the
# examples are bounded by their strategies instead.
settings.register_profile("dynsolve", deadline=None)
settings.load_profile("dynsolve")
