"""Renderers: turn a :class:`~dynsolve.results.Solution` into text, JSON, Markdown, LaTeX or HTML.

They never compute and never print; the CLI chooses one and writes its output.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Literal

from dynsolve.results import Solution

Format = Literal["text", "json", "markdown", "latex", "html"]
Layout = Literal["full", "handout", "key"]


def sheet_plan(layout: Layout) -> tuple[str, ...]:
    """The sections of a LaTeX, Markdown or HTML document, in order, for ``layout``.

    >>> sheet_plan("key")
    ('title', 'answers', 'key', 'checks')
    >>> "key" in sheet_plan("handout") or "checks" in sheet_plan("handout")
    False
    """
    derivation = (
        "givens", "free_body", "assumptions", "trials", "equations", "energy", "steps", "answers"
    )  # fmt: skip
    if layout == "key":
        return ("title", "answers", "key", "checks")
    if layout == "handout":
        return ("handout_title", "warnings", *derivation)
    return ("title", "warnings", *derivation, "key", "checks")


def renderer(fmt: Format, layout: Layout = "full") -> Callable[[Solution], str]:
    """The function rendering ``fmt`` as a string (``text`` renders without colour);
    ``layout`` (``full``, ``handout``, ``key``) shapes the LaTeX, Markdown and HTML documents.

    >>> renderer("json").__name__
    'render_json'
    """
    if fmt == "json":
        from dynsolve.render.json import render_json

        return render_json
    if fmt == "markdown":
        from dynsolve.render.markdown import render_markdown

        return functools.partial(render_markdown, layout=layout)
    if fmt == "latex":
        from dynsolve.render.latex import render_latex

        return functools.partial(render_latex, layout=layout)
    if fmt == "html":
        from dynsolve.render.html import render_html

        return functools.partial(render_html, layout=layout)
    from dynsolve.render.terminal import render_text

    return render_text
