"""Renderers: turn a :class:`~dynsolve.results.Solution` into text, JSON, Markdown or LaTeX.

They never compute and never print; the CLI chooses one and writes its output.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Literal

from dynsolve.results import Solution

Format = Literal["text", "json", "markdown", "latex"]


def renderer(fmt: Format) -> Callable[[Solution], str]:
    """The function rendering ``fmt`` as a string (``text`` renders without colour).

    >>> renderer("json").__name__
    'render_json'
    """
    if fmt == "json":
        from dynsolve.render.json import render_json

        return render_json
    if fmt == "markdown":
        from dynsolve.render.markdown import render_markdown

        return render_markdown
    if fmt == "latex":
        from dynsolve.render.latex import render_latex

        return render_latex
    from dynsolve.render.terminal import render_text

    return render_text
