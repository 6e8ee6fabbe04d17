"""Fixtures shared by the test modules."""

import contextlib
import linecache
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


@pytest.fixture
def chromium() -> str:
    """Debian's headless Chromium (the ``chromium`` package); skipped when missing, unless CI
    is set (CI installs it)."""
    path = shutil.which("chromium")
    if path:
        return path
    if os.environ.get("CI"):
        pytest.fail("chromium missing although CI is set: install Debian's chromium package")
    pytest.skip("chromium is not installed")


# No per-example deadline: CI machines are shared and slower than a laptop; the
# examples are bounded by their strategies instead.
settings.register_profile("dynsolve", deadline=None)
settings.load_profile("dynsolve")


# sympy's lambdify puts each generated function's source in linecache and removes it with
# a weakref finalizer when the function is collected; a collection that runs inside
# linecache.checkcache's loop (doctest calls it before every example) then deletes a key
# the loop is about to read: a KeyError that fails an unrelated doctest now and then.
_checkcache = linecache.checkcache


def _tolerant_checkcache(filename: str | None = None) -> None:
    with contextlib.suppress(KeyError):  # an entry collected while the cache was checked
        _checkcache(filename)


linecache.checkcache = _tolerant_checkcache
