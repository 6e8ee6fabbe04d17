"""The README stays true: its spec listings are the bundled files they name, and its first
command names a bundled file."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text()


@pytest.mark.parametrize(
    "name", ["problems/seed/fa_hib_drum.dyn", "problems/equations/fa_hib_drum.dyn"]
)
def test_listed_spec_is_the_bundled_file(name: str) -> None:
    text = (ROOT / name).read_text()
    body = text[text.index("problem:") :].rstrip("\n")
    assert f"```\n{body}\n```" in README


def test_first_command_solves_a_bundled_file() -> None:
    first = re.search(r"```sh\n(.*?)```", README, re.S)
    assert first is not None
    files = re.findall(r"dynsolve solve (\S+\.dyn)", first.group(1))
    assert files and all((ROOT / f).is_file() for f in files)
    assert "Python >= 3.11" in first.group(1)


def test_readme_cites_nothing_outside_the_project() -> None:
    assert "shared/" not in README and "../" not in README
    for target in re.findall(r"\]\(([^)#]+)\)", README):
        if not target.startswith("http"):
            assert (ROOT / target).exists(), target
