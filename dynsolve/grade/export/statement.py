"""A question's statement as HTML: the title, the givens and what to find, with the spec's
text escaped and inert to the template engines that read it (PrairieLearn's mustache,
Moodle's ``{name}`` wildcards): each ``{`` of it is written ``&#123;``.

>>> panel = statement("div", "Push {x}", [("m", "{m} kg", "mass <b>")], ["Find a in m/s^2."])
>>> print(*to_html(panel).split("<p>Given:</p>"), sep="\\n")
<div><p>Push &#123;x}</p>
<ul><li>m = {m} kg (mass &lt;b&gt;)</li></ul><p>Find a in m/s^2.</p></div>
"""

from __future__ import annotations

from collections.abc import Sequence
from xml.etree import ElementTree

from dynsolve.grade.export.table import Part
from dynsolve.names import pretty

_BRACE = "\ue000"  # a private-use stand-in for a "{" of the spec's text, until serialized


def statement(
    tag: str, title: str, givens: Sequence[tuple[str, str, str]], asked: Sequence[str]
) -> ElementTree.Element:
    """The statement in a ``tag`` element. ``givens``: (name, value, description), where
    the value is the export's own markup (``66 kg``, ``{{params.m}}``, ``{m} kg``) and
    the name and description are the spec's text."""
    root = ElementTree.Element(tag)
    ElementTree.SubElement(root, "p").text = _inert(title)
    ElementTree.SubElement(root, "p").text = "Given:"
    items = ElementTree.SubElement(root, "ul")
    for name, value, description in givens:
        note = f" ({_inert(description)})" if description else ""
        ElementTree.SubElement(items, "li").text = f"{_inert(pretty(name))} = {value}{note}"
    for line in asked:
        ElementTree.SubElement(root, "p").text = line
    return root


def to_html(element: ElementTree.Element) -> str:
    """The element as HTML (custom elements get an end tag, never ``<x />``)."""
    html = ElementTree.tostring(element, encoding="unicode", method="html")
    return html.replace(_BRACE, "&#123;")


def asked(part: Part) -> str:
    """What the student is asked for: ``Find a in m/s^2.`` (``the magnitude of`` when the
    key has a direction; Greek names as letters, ``α``)."""
    name = pretty(part.name)
    what = f"the magnitude of {name}" if part.directed else name
    return f"Find {what}" + (f" in {part.unit}." if part.unit else ".")


def _inert(text: str) -> str:
    return text.replace(_BRACE, "").replace("{", _BRACE)
