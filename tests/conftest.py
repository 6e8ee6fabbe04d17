"""Fixtures shared by the test modules."""

import os
import shutil

import pytest


@pytest.fixture
def pdflatex() -> str:
    """pdflatex's path; skipped when missing, unless CI is set (CI installs texlive)."""
    path = shutil.which("pdflatex")
    if path:
        return path
    if os.environ.get("CI"):
        pytest.fail("pdflatex is missing although CI is set: install texlive-latex-recommended")
    pytest.skip("pdflatex is not installed")
