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


def sheet_plan(layout: Layout, source: bool | None = None) -> tuple[str, ...]:
    """The sections of a LaTeX, Markdown or HTML document, in order, for ``layout``.

    The spec's ``source:`` line shows on the full sheet and the key; on the handout only
    when asked (``source`` True): it can name the answer. A failed trial comes before the
    assumptions, which state how it failed and what held in the re-solve.

    >>> sheet_plan("key")
    ('title', 'source', 'answers', 'key', 'checks')
    >>> "key" in sheet_plan("handout") or "checks" in sheet_plan("handout")
    False
    >>> "source" in sheet_plan("handout"), "source" in sheet_plan("handout", source=True)
    (False, True)
    """
    derivation = (
        "givens", "free_body", "trials", "assumptions", "equations", "energy", "steps", "answers"
    )  # fmt: skip
    shown = ("source",) if (layout != "handout" if source is None else source) else ()
    if layout == "key":
        return ("title", *shown, "answers", "key", "checks")
    if layout == "handout":
        return ("handout_title", *shown, "warnings", *derivation)
    return ("title", *shown, "warnings", *derivation, "key", "checks")


def renderer(
    fmt: Format, layout: Layout = "full", source: bool | None = None
) -> Callable[[Solution], str]:
    """The function rendering ``fmt`` as a string (``text`` renders without colour);
    ``layout`` (``full``, ``handout``, ``key``) shapes the LaTeX, Markdown and HTML documents,
    ``source`` shows the spec's source line on them (None: not on the handout).

    >>> renderer("json").__name__
    'render_json'
    """
    if fmt == "json":
        from dynsolve.render.json import render_json

        return render_json
    if fmt == "markdown":
        from dynsolve.render.markdown import render_markdown

        return functools.partial(render_markdown, layout=layout, source=source)
    if fmt == "latex":
        from dynsolve.render.latex import render_latex

        return functools.partial(render_latex, layout=layout, source=source)
    if fmt == "html":
        from dynsolve.render.html import render_html

        return functools.partial(render_html, layout=layout, source=source)
    from dynsolve.render.terminal import render_text

    return render_text
