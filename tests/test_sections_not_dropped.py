"""Nothing a user writes is silently ignored (issue 25 item 3): a section header with
nothing under it is an error at the header, as is a scene beside kinematics (see
tests/test_reserved_names.py)."""

from __future__ import annotations

import pytest

from dynsolve.errors import SpecError
from dynsolve.spec.parser import parse_spec


@pytest.mark.parametrize(
    "section", ["given", "scene", "kinematics", "equations", "define", "answers", "vary"]
)
def test_an_empty_section_is_an_error_at_its_header(section: str):
    text = f"{section}:\nequations:\n  W = 2*g\nfind: W\n"
    if section == "equations":
        text = "equations:\ngiven:\n  m = 2 kg\nfind: W\n"
    with pytest.raises(SpecError, match=f"section '{section}:' is empty") as caught:
        parse_spec(text, "e.dyn")
    assert (caught.value.position.line, caught.value.position.column) == (1, 1)
    assert "indent the lines" in str(caught.value)
