"""Render a :class:`~dynsolve.results.Solution` as a standalone LaTeX document for pdflatex.

The document needs Debian's ``texlive-latex-base``, ``texlive-latex-recommended`` (article,
amsmath, amssymb, booktabs, geometry) and ``texlive-science`` (siunitx: every quantity is a
``\\qty``); with free-body diagrams also ``texlive-pictures`` (TikZ, drawn by
:mod:`dynsolve.render.fbd_tikz`). Any full TeX distribution (TeX Live, MiKTeX) has them all.
It is pure ASCII and uses the default OT1 encoding, so the Computer Modern Type 1 fonts are
used and no font has to be generated. Plain text goes through :func:`escape_latex`; the LaTeX
fragments of the solution (``latex``, ``latex_name``, ``latex_value``, ``formula_latex``,
``value_latex``) go through :func:`safe_math`.

The linkage figure (a scene of bars) is a TikZ picture too
(:mod:`dynsolve.render.linkage_figure`).
"""

from __future__ import annotations

import itertools
import re
import unicodedata
from collections.abc import Callable, Iterable, Iterator, Sequence
from pathlib import PurePath

from dynsolve.format import and_list, pretty_unit
from dynsolve.names import GREEK, latex_name
from dynsolve.render import Layout, sheet_plan
from dynsolve.render.fbd_tikz import free_body_tikz
from dynsolve.render.numbering import BY_LINE, EquationTags, sheet_tags
from dynsolve.results import (
    FAILED,
    NOT_RUN,
    PASSED,
    AnswerRow,
    Assumption,
    Check,
    EnergyTerm,
    EquationRow,
    ForceRow,
    Formula,
    FreeBody,
    GivenRow,
    KeyComparison,
    LimitRemark,
    Remark,
    Solution,
    Step,
    Trial,
    check_counts,
)

PREAMBLE = r"""\documentclass[11pt]{article}
\usepackage[a4paper,margin=2.5cm]{geometry}
\usepackage{amsmath}
\usepackage{amssymb}
\usepackage{booktabs}
\usepackage{siunitx}
\usepackage{graphicx}
\newsavebox{\fitbox}
\newcommand{\fitmath}[2]{\sbox{\fitbox}{$\displaystyle #2$}%
\ifdim\wd\fitbox>#1\resizebox{#1}{!}{\usebox{\fitbox}}\else\usebox{\fitbox}\fi}
\allowdisplaybreaks
\renewcommand{\arraystretch}{1.25}
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.6ex}"""

# Only documents with a diagram load TikZ (Debian's texlive-pictures).
DIAGRAM_PREAMBLE = (
    r"\usepackage{tikz}\usetikzlibrary{arrows.meta,patterns,decorations.pathmorphing}"
)

# ---- escaping -------------------------------------------------------------------------

# A piece of escaped output: ("text", ...) in text mode, ("math", ...) a math-mode command,
# ("sup", ...) / ("sub", ...) the body of a superscript / subscript.
Piece = tuple[str, str]
Run = tuple[str, Iterator[Piece]]

_TEXT_SPECIAL = {
    "\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_",
    "{": r"\{", "}": r"\}", "~": r"\~{}", "^": r"\^{}", "<": r"\textless{}",
    ">": r"\textgreater{}", "|": r"\textbar{}", "[": "{[}", "]": "{]}", '"': "''",
}  # fmt: skip

_TEXT_UNICODE = {
    "\u2014": "---", "\u2013": "--", "\u2010": "-", "\u2011": "-", "\u2012": "-",
    "\u2018": "`", "\u2019": "'", "\u201a": ",", "\u201c": "``", "\u201d": "''",
    "\u201e": "''", "\u00ab": "''", "\u00bb": "''", "\u2026": r"\ldots{}",
    "\u00df": r"\ss{}", "\u00e6": r"\ae{}", "\u00c6": r"\AE{}",
    "\u0153": r"\oe{}", "\u0152": r"\OE{}", "\u00f8": r"\o{}", "\u00d8": r"\O{}",
    "\u0142": r"\l{}", "\u0141": r"\L{}", "\u0131": r"\i{}", "\u0237": r"\j{}",
    "\u00a1": "!", "\u00bf": "?", "\u00a9": "(c)", "\u00ae": "(R)", "\u2122": "(TM)",
    "\u2044": "/", "\u2215": "/",
}  # fmt: skip

_GREEK = {
    "α": r"\alpha", "β": r"\beta", "γ": r"\gamma", "δ": r"\delta", "ε": r"\epsilon",
    "ζ": r"\zeta", "η": r"\eta", "θ": r"\theta", "ι": r"\iota", "κ": r"\kappa",
    "λ": r"\lambda", "μ": r"\mu", "ν": r"\nu", "ξ": r"\xi", "ο": "o", "π": r"\pi",
    "ρ": r"\rho", "ς": r"\varsigma", "σ": r"\sigma", "τ": r"\tau", "υ": r"\upsilon",
    "φ": r"\phi", "χ": r"\chi", "ψ": r"\psi", "ω": r"\omega", "ϑ": r"\vartheta",
    "ϕ": r"\phi", "ϖ": r"\varpi", "ϱ": r"\varrho", "ϵ": r"\epsilon", "ϰ": r"\varkappa",
    "Α": r"\mathrm{A}", "Β": r"\mathrm{B}", "Γ": r"\Gamma", "Δ": r"\Delta",
    "Ε": r"\mathrm{E}", "Ζ": r"\mathrm{Z}", "Η": r"\mathrm{H}", "Θ": r"\Theta",
    "Ι": r"\mathrm{I}", "Κ": r"\mathrm{K}", "Λ": r"\Lambda", "Μ": r"\mathrm{M}",
    "Ν": r"\mathrm{N}", "Ξ": r"\Xi", "Ο": r"\mathrm{O}", "Π": r"\Pi", "Ρ": r"\mathrm{P}",
    "Σ": r"\Sigma", "Τ": r"\mathrm{T}", "Υ": r"\Upsilon", "Φ": r"\Phi", "Χ": r"\mathrm{X}",
    "Ψ": r"\Psi", "Ω": r"\Omega", "\u00b5": r"\mu", "\u2126": r"\Omega", "\u2206": r"\Delta",
}  # fmt: skip

_SYMBOLS = {
    "·": r"\cdot", "⋅": r"\cdot", "∙": r"\cdot", "×": r"\times", "÷": r"\div", "±": r"\pm",
    "∓": r"\mp", "−": "-", "∗": r"\ast", "≤": r"\leq", "≥": r"\geq", "⩽": r"\leq",
    "⩾": r"\geq", "≠": r"\neq", "≈": r"\approx", "≅": r"\cong", "≡": r"\equiv",
    "∼": r"\sim", "∝": r"\propto", "≪": r"\ll", "≫": r"\gg", "∞": r"\infty",
    "∂": r"\partial", "∇": r"\nabla", "∫": r"\int", "∑": r"\sum", "∏": r"\prod",
    "√": r"\surd", "→": r"\rightarrow", "←": r"\leftarrow", "↔": r"\leftrightarrow",
    "⇒": r"\Rightarrow", "⇐": r"\Leftarrow", "⇔": r"\Leftrightarrow", "↑": r"\uparrow",
    "↓": r"\downarrow", "↻": r"\circlearrowright", "↺": r"\circlearrowleft",
    "⟳": r"\circlearrowright", "⟲": r"\circlearrowleft", "✓": r"\checkmark",
    "✔": r"\checkmark", "✗": r"\times", "✘": r"\times", "∠": r"\angle", "⊥": r"\perp",
    "⟂": r"\perp", "∥": r"\parallel", "∈": r"\in", "•": r"\bullet", "∘": r"\circ",
    "ℓ": r"\ell", "ħ": r"\hbar", "⋯": r"\cdots", "†": r"\dagger", "‡": r"\ddagger",
    "§": r"\S", "¶": r"\P", "¬": r"\neg", "∧": r"\wedge", "∨": r"\vee",
}  # fmt: skip

_SUPERSCRIPTS = {
    "⁰": "0", "¹": "1", "²": "2", "³": "3", "⁴": "4", "⁵": "5", "⁶": "6", "⁷": "7",
    "⁸": "8", "⁹": "9", "⁺": "+", "⁻": "-", "⁼": "=", "⁽": "(", "⁾": ")", "ⁿ": "n",
    "ⁱ": "i", "ᐟ": "/", "°": r"{\circ}", "′": r"{\prime}", "″": r"{\prime\prime}",
}  # fmt: skip

_SUBSCRIPTS = {
    "₀": "0", "₁": "1", "₂": "2", "₃": "3", "₄": "4", "₅": "5", "₆": "6", "₇": "7",
    "₈": "8", "₉": "9", "₊": "+", "₋": "-", "₌": "=", "₍": "(", "₎": ")", "ₐ": "a",
    "ₑ": "e", "ₒ": "o", "ₓ": "x", "ₕ": "h", "ₖ": "k", "ₗ": "l", "ₘ": "m", "ₙ": "n",
    "ₚ": "p", "ₛ": "s", "ₜ": "t",
}  # fmt: skip

_ACCENTS = {
    "\u0300": "\\`", "\u0301": "\\'", "\u0302": "\\^", "\u0303": "\\~", "\u0304": "\\=",
    "\u0306": "\\u", "\u0307": "\\.", "\u0308": '\\"', "\u030a": "\\r", "\u030b": "\\H",
    "\u030c": "\\v", "\u0327": "\\c",
}  # fmt: skip

_MATH_UNSAFE = re.compile(r"(?<!\\)([%#$])")


def escape_latex(text: str) -> str:
    """Plain text as pure-ASCII LaTeX text mode: specials escaped, Unicode mapped or ``?``.

    Greek letters and mathematical signs become inline math, superscripts a ``{}^{...}``
    group, accented letters TeX accents, line breaks spaces; anything unknown becomes ``?``.

    >>> print(escape_latex("ΣM_O = I_O α & 50%"))
    $\\Sigma$M\\_O = I\\_O $\\alpha$ \\& 50\\%
    >>> print(escape_latex("2 m²·s⁻¹ — é ✓ ☃"))
    2 m${}^{2} \\cdot$s${}^{-1}$ --- \\'{e} $\\checkmark$ ?
    """
    pieces = [piece for char in text for piece in _char_pieces(char)]
    return "".join(_text_group(kind, list(run)) for kind, run in _runs(pieces, _text_kind))


def safe_math(fragment: str, siunitx: bool = True) -> str:
    """A LaTeX math fragment made pure ASCII and safe to put between math delimiters.

    Non-ASCII characters become math commands (or ``\\text{...}``), stray ``%``, ``#`` and
    ``$`` are escaped and line breaks become spaces; the LaTeX itself is trusted.

    >>> print(safe_math("T r = I_{O} α·2 — % x"))
    T r = I_{O}  \\alpha \\cdot 2 \\text{---} \\% x

    A number with its unit becomes siunitx's ``\\qty`` (the number's spacing, the unit
    upright, a power of ten typeset by siunitx), unless ``siunitx`` is False (MathJax):

    >>> print(safe_math(r"a = -1.23\\times 10^{-4}\\,\\mathrm{m/s^{2}}"))
    a = \\qty{-1.23e-4}{m/s^{2}}
    """
    if siunitx:
        fragment = _QUANTITY.sub(_qty, fragment)
    fragment = _MATH_UNSAFE.sub(r"\\\1", fragment)
    pieces: list[Piece] = []
    for char in fragment:
        if char.isascii():
            pieces.append(("raw", char if char.isprintable() else " "))
        else:
            pieces.extend(_char_pieces(char))
    return "".join(_math_group(kind, list(run)) for kind, run in _runs(pieces, _math_kind))


_QUANTITY = re.compile(
    r"(?<![\w.])(-?\d+(?:\.\d+)?)(?:\\times ?10\^\{(-?\d+)\})?\\,\\mathrm\{"
    r"((?:[A-Za-z]+|/|\\cdot ?|\^\{-?\d+(?:/\d+)?\}| |\(|\))+)\}"
)


def _qty(match: re.Match[str]) -> str:
    """``1.23\\times 10^{-4}\\,\\mathrm{N}`` as ``\\qty{1.23e-4}{N}`` (literal units)."""
    number = match[1] + (f"e{match[2]}" if match[2] else "")
    return f"\\qty{{{number}}}{{{match[3].strip()}}}"


def _char_pieces(char: str, decompose: bool = True) -> list[Piece]:
    """The escaped pieces for one character."""
    if char in _TEXT_SPECIAL:
        return [("text", _TEXT_SPECIAL[char])]
    if char.isascii():
        return [("text", char)] if char.isprintable() else _other_pieces(char, decompose)
    for table, kind in ((_TEXT_UNICODE, "text"), (_SUPERSCRIPTS, "sup"), (_SUBSCRIPTS, "sub")):
        if char in table:
            return [(kind, table[char])]
    if char in _GREEK:
        return [("math", _GREEK[char])]
    if char in _SYMBOLS:
        return [("math", _SYMBOLS[char])]
    return _other_pieces(char, decompose)


def _other_pieces(char: str, decompose: bool) -> list[Piece]:
    """Spaces, invisible characters, accented letters and compatibility forms."""
    category = unicodedata.category(char)
    if char.isspace() or category == "Zs":
        return [("text", " ")]
    if category in ("Cc", "Cf"):
        return []
    decomposed = unicodedata.normalize("NFKD", char)
    if not decompose or decomposed == char:
        return [("text", "?")]
    base = "".join(c for c in decomposed if not unicodedata.combining(c))
    accent = next((_ACCENTS[c] for c in decomposed if c in _ACCENTS), None)
    if accent and len(base) == 1 and base.isascii() and base.isalpha():
        letter = {"i": r"\i", "j": r"\j"}.get(base, base)
        return [("text", f"{accent}{{{letter}}}")]
    return [piece for c in base for piece in _char_pieces(c, decompose=False)]


def _runs(pieces: list[Piece], key: Callable[[Piece], str]) -> Iterator[Run]:
    return itertools.groupby(pieces, key=key)


def _text_kind(piece: Piece) -> str:
    return "text" if piece[0] == "text" else "math"


def _math_kind(piece: Piece) -> str:
    return piece[0] if piece[0] in ("raw", "text") else "math"


def _text_group(kind: str, pieces: list[Piece]) -> str:
    """In text mode: text as it is, a run of math pieces inside one ``$...$``."""
    return _concat(pieces) if kind == "text" else f"${_math_body(pieces)}$"


def _math_group(kind: str, pieces: list[Piece]) -> str:
    """In math mode: raw LaTeX as it is, text in ``\\text{}``, math pieces spaced."""
    if kind == "raw":
        return _concat(pieces)
    if kind == "text":
        return f"\\text{{{_concat(pieces)}}}"
    return f" {_math_body(pieces)} "


def _math_body(pieces: list[Piece]) -> str:
    """Math commands spaced apart; each run of super- or subscripts in one group."""
    out = []
    for kind, run in itertools.groupby(pieces, key=lambda p: p[0]):
        body = [text for _, text in run]
        if kind == "sup":
            out.append("{}^{" + "".join(body) + "}")
        elif kind == "sub":
            out.append("{}_{" + "".join(body) + "}")
        else:
            out.extend(body)
    return " ".join(out)


def _concat(pieces: list[Piece]) -> str:
    return "".join(text for _, text in pieces)


# ---- document -------------------------------------------------------------------------


def render_latex(solution: Solution, layout: Layout = "full", source: bool | None = None) -> str:
    """The solution as a standalone LaTeX document (article class) for pdflatex.

    ``layout``: ``full`` (everything), ``handout`` (the derivation a teacher hands out: no
    file name or status, no answer-key column, no checks, its equations numbered (1), (2), …
    rather than tagged by spec line) or ``key`` (the answers with the key and the checks, for
    whoever marks). ``source`` shows the spec's ``source:`` line (None: all but the handout,
    where it could give the answer away).

    >>> from dynsolve.results import AnswerRow, Solution
    >>> answer = AnswerRow("T", 105.86, "N", "106 N", "14715/139", "106\\\\,\\\\mathrm{N}", "")
    >>> doc = render_latex(Solution("d.dyn", "Drum & block", "Hibbeler 17.11", "SI",
    ...                             "equations", (), (), (), (answer,), (), (), "solved"))
    >>> doc.splitlines()[0], doc.splitlines()[-1]
    ('\\\\documentclass[11pt]{article}', '\\\\end{document}')
    >>> "\\\\section*{Drum \\\\& block}" in doc, "$\\\\qty{106}{N}$" in doc
    (True, True)

    In scene mode each body's free-body diagram is a TikZ picture (unknown forces dashed,
    red), its kinetic diagram beside it:

    >>> from dynsolve.results import Assumption, ForceRow, FreeBody
    >>> pull = ForceRow("T", "tension", "A", 0.4, 0.0, "down", 0.0, -1.0, False, "")
    >>> drum = FreeBody("drum", "disk", (0.4,), "rotation about O", (pull,), ("I_G α",), "O")
    >>> scene = Solution("d.dyn", "Drum", "", "SI", "scene", (), (), (), (), (), (), "solved",
    ...                  free_body=(drum,), assumptions=(Assumption("cord T taut", True, ""),))
    >>> tex = render_latex(scene)
    >>> "\\\\begin{tikzpicture}" in tex, "unknown,->" in tex, "$I_{G} \\\\, \\\\alpha$" in tex
    (True, True, True)
    >>> "\\\\item[$\\\\checkmark$] \\\\textbf{cord T taut} (holds)" in tex
    True
    """
    plan = sheet_plan(layout, source)
    key = solution.key if "key" in plan else ()
    cited = "source" in plan
    tags = sheet_tags(solution, numbered=layout == "handout")
    parts: dict[str, Callable[[], list[str]]] = {
        "title": lambda: [_title(solution, cited=cited)],
        "handout_title": lambda: [_title(solution, handout=True, cited=cited)],
        "warnings": lambda: [
            f"\\textbf{{Warning:}} {escape_latex(w)}\n" for w in solution.warnings
        ],
        "givens": lambda: [_givens_section(solution.givens, solution.system)],
        "free_body": lambda: (
            _sketch_section(solution)
            + _free_body_section(solution.free_body, solution.system)
            + _linkage_section(solution)
        ),
        "assumptions": lambda: _assumptions_section(solution.assumptions),
        "trials": lambda: [
            _trial_section(t, ts) for t, ts in zip(solution.trials, tags.trials, strict=True)
        ],
        "equations": lambda: [
            _resolved(_equations_section(solution.equations, tags.final), solution),
            *_second_moments_section(solution.second_moments, tags.final),
        ],
        "energy": lambda: _energy_section(solution.energy),
        "steps": lambda: [_resolved(_solution_section(solution.steps, tags.final), solution)],
        "answers": lambda: (
            [_answers_section(solution.answers, key)]
            + [f"\\textit{{Remark:}} {_remark(r)}\n" for r in solution.remarks]
            + [_figure_section(solution.figure)] * bool(solution.figure and "steps" in plan)
        ),
        "checks": lambda: [_checks_section(solution.checks)],
    }
    body = [section for name in plan if name in parts for section in parts[name]()]
    pictures = solution.free_body or solution.linkage is not None or solution.sketch is not None
    drawn = pictures and "free_body" in plan
    preamble = PREAMBLE + ("\n" + DIAGRAM_PREAMBLE if drawn else "")
    return "\n\n".join([preamble, r"\begin{document}", *body, r"\end{document}"]) + "\n"


def _resolved(section: str, solution: Solution) -> str:
    """After a failed trial, the final solve's heading says it is the re-solve.

    >>> _resolved("\\\\subsection*{Equations}", Solution("", "", "", "SI", "", (), (), (), (),
    ...           (), (), "", trials=(Trial("no slip", (), (), "fails"),)))
    '\\\\subsection*{Equations (re-solved)}'
    """
    if not solution.trials:
        return section
    return re.sub(r"^\\subsection\*\{(\w+)\}", r"\\subsection*{\1 (re-solved)}", section, count=1)


def _math(fragment: str) -> str:
    """Inline math, or nothing for an empty fragment."""
    fragment = safe_math(fragment).strip()
    return f"${fragment}$" if fragment else ""


def _name(name: str) -> str:
    return _math(latex_name(name))


def _title(solution: Solution, handout: bool = False, cited: bool = True) -> str:
    """The title, the source line when ``cited``, and (not on the handout) the spec's file
    name, status and solver messages."""
    title = escape_latex(solution.title.strip() or PurePath(solution.file).name or "Problem")
    lines = [f"\\section*{{{title}}}"]
    if cited and solution.source.strip():
        lines.append(f"{{\\large\\itshape {caption_latex(solution.source)}\\par}}")
    if handout:  # the handout names no file, status or solver remarks
        return "\n".join(lines)
    lines.append(r"\smallskip")
    lines.append(f"{{\\small {_summary(solution)}\\par}}")
    lines.extend(_messages(solution.messages))
    return "\n".join(lines)


def _summary(solution: Solution) -> str:
    spec = escape_latex(PurePath(solution.file).name)
    facts = [f"Spec \\texttt{{{spec}}}", f"units {escape_latex(solution.system)}"]
    facts.append(f"status \\textbf{{{escape_latex(solution.status)}}}")
    return "; ".join(facts) + "."


def _messages(messages: Sequence[str]) -> list[str]:
    if not messages:
        return []
    items = [f"\\item {escape_latex(m)}" for m in messages]
    return [r"\begin{itemize}", *items, r"\end{itemize}"]


def _table(spec: str, header: Sequence[str], rows: Iterable[Sequence[str]]) -> str:
    """A booktabs table; cells are LaTeX already."""
    lines = [r"\begin{center}", f"\\begin{{tabular}}{{{spec}}}", r"\toprule"]
    lines += [" & ".join(header) + r" \\", r"\midrule"]
    lines += [" & ".join(row) + r" \\" for row in rows]
    lines += [r"\bottomrule", r"\end{tabular}", r"\end{center}"]
    return "\n".join(lines)


# ---- given


def _givens_section(givens: Sequence[GivenRow], system: str) -> str:
    r"""The givens' table; quantities derived from them (r_G, I_O = I_G + m d²) follow as
    displayed equations, formula = numbers = value, where they have room.

    >>> rows = [GivenRow("m", "10 kg", "10 kg", "mass", False, "m", r"10\,kg"),
    ...         GivenRow("I_O", "", "", "I about O: I_G + m r_G^2", False, "I_{O}",
    ...                  r"\frac{m}{3} = 3.3\,kg")]
    >>> tex = _givens_section(rows, "SI")
    >>> r"\[ I_{O} = \frac{m}{3} = 3.3\,kg \]" in tex, "$I_{G}$" in tex  # no base value
    (True, True)
    """
    if not givens:
        return "\\subsection*{Given}\nNo givens."
    header = ["Symbol", "Value", f"{escape_latex(system)} value", "Description"]
    derived = [g for g in givens if not g.symbolic and "=" in g.latex_value]
    rows = [_given_cells(g) for g in givens if g not in derived]
    table = _table(r"@{}lllp{0.4\linewidth}@{}", header, rows) if rows else ""
    lines = [
        f"{_prose(g.description)}:\n\\[ {g.latex_name} = {g.latex_value}"
        + (f" = \\text{{{escape_latex(g.base)}}}" if g.base else "")
        + " \\]"
        for g in derived
    ]
    return "\n".join(["\\subsection*{Given}", table, *lines]).replace("\n\n", "\n")


def _prose(text: str) -> str:
    """A given's description with its symbols typeset as mathematics (as a caption's).

    >>> _prose("I about O: I_G + m r_G^2 (parallel axis)")
    'I about O: $I_{G}$ + m $r_{G}^{2}$ (parallel axis)'
    """
    return caption_latex(text.replace("^2", "²").replace("^3", "³"))


def _given_cells(given: GivenRow) -> list[str]:
    value = caption_latex(given.written) if given.symbolic else _math(given.latex_value)
    return [
        _math(given.latex_name),
        value,
        escape_latex(pretty_unit(given.base)),
        _prose(given.description),
    ]


# ---- equations


def _energy_section(terms: Sequence[EnergyTerm]) -> list[str]:
    """T1, each U(1→2) and T2 with formula and value (nothing without a travel)."""
    if not terms:
        return []
    rows = [
        [
            _math(latex_name(t.name)),
            _math(t.formula_latex),
            _math(t.value_latex),
            caption_latex(t.meaning),
        ]
        for t in terms
    ]
    title = "\\subsection*{Work and energy: $T_1 + \\Sigma U_{1 \\to 2} = T_2$, term by term}"
    return [
        title + "\n" + _table("@{}lllp{0.35\\linewidth}@{}", ["Term", "Formula", "Value", ""], rows)
    ]


def _equations_section(equations: Sequence[EquationRow], tags: EquationTags = BY_LINE) -> str:
    if not equations:
        return "\\subsection*{Equations}\nNo equations."
    return "\n\n".join(["\\subsection*{Equations}", *(_equation(e, tags) for e in equations)])


def _second_moments_section(rows: Sequence[EquationRow], tags: EquationTags = BY_LINE) -> list[str]:
    """The other moment point's equation (a check, not used to solve); nothing without one."""
    if not rows:
        return []
    title = "\\subsection*{A second moment point (a check, not used to solve)}"
    return ["\n\n".join([title, *(_equation(e, tags) for e in rows)])]


_SUBSCRIPTED = re.compile(
    r"\((?P<pbase>[A-Za-zα-ωΑ-ΩḢ]+)_(?P<inner>[A-Za-z0-9]+)\)_(?P<outer>[A-Za-z0-9]+)"  # (a_G)_x
    r"|(?P<op>[ΣΔ]?)(?P<base>[A-Za-zα-ωΑ-ΩḢ]+)"  # ΣF_x, r_G/A, r_G², v_2_disk, I_G,xx
    r"_(?P<sub>[A-Za-z0-9]+(?:[/,_][A-Za-z0-9]+)*)(?P<power>[²³]?)"
    r"|(?P<mu>μ)(?P<kind>[sk])(?![A-Za-z])"  # μs, μk: the coefficients of friction
    r"|\)_(?P<closed>[A-Za-z0-9]+)"  # (Ḣ_G + ω × H_G)_y: a component of a sum
    r"|(?P<dot>Ḣ)"  # Ḣ alone
)
_POWERS = {"²": "^{2}", "³": "^{3}", "": ""}
_BASES = {"Ḣ": r"\dot{H}"}  # a rate of change (Ḣ_G)
_ASCII_POWER = re.compile(r"(?:\*\*|\^)(?:\{(-?\d+)\}|(-?\d+))")
_TIMES_NUMBER = re.compile(r"(?<=\d)\*(?=[A-Za-zα-ωΑ-Ω(])")  # 2*s_G: 2s_G
_MINUS = re.compile(r"(?:^|(?<=[\s(=]))-(?=[\dA-Za-zα-ω√(.])")  # -0.667, -L: a minus sign
_TO_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


def ascii_maths(text: str) -> str:
    """Plain-text mathematics as it is typeset: powers as superscripts, a product as a
    centred dot (none after a number), ``sqrt(`` as ``√(``, a hyphen before a number or
    name as a minus sign.

    >>> ascii_maths("s_2 = 2*s_G, -L + sqrt(L**2 + s^2), 15 ft*lb")
    's_2 = 2s_G, −L + √(L² + s²), 15 ft·lb'
    >>> ascii_maths("no-slip: -0.667 rad/s (Example 17-94)")
    'no-slip: −0.667 rad/s (Example 17-94)'
    """
    text = _ASCII_POWER.sub(lambda m: (m[1] or m[2]).translate(_TO_SUPERSCRIPT), text)
    text = _TIMES_NUMBER.sub("", text.replace("sqrt(", "√("))
    return _MINUS.sub("−", text.replace("*", "·"))


def caption_latex(text: str) -> str:
    """A principle's caption with its symbols typeset as mathematics (subscripts, Σ),
    the words around them as text.

    >>> caption_latex("ΣF_x = m (a_G)_x (drum)")
    '$\\\\Sigma F_{x}$ = m $(a_{G})_{x}$ (drum)'
    >>> caption_latex("ΣM_O = I_O α, I_O = I_G + m r_G²")
    '$\\\\Sigma M_{O}$ = $I_{O}$ $\\\\alpha$, $I_{O}$ = $I_{G}$ + m $r_{G}^{2}$'
    >>> caption_latex("αH_G")
    '$\\\\alpha H_{G}$'
    """
    joined = "".join(
        f"${piece}$" if math else escape_latex(piece) for math, piece in caption_pieces(text)
    )
    return _TOUCHING.sub(" ", joined)  # "$\\alpha$$H_{G}$" would open display maths


_TOUCHING = re.compile(r"(?<!\\)\$\$")


def caption_pieces(text: str) -> list[tuple[bool, str]]:
    """A caption cut into (is it mathematics, piece): its symbols as LaTeX math, the words
    around them as they are (plain text, unescaped, its ASCII maths as :func:`ascii_maths`
    writes it), for the LaTeX and HTML renderers.

    >>> caption_pieces("ΣF_x = m")
    [(True, '\\\\Sigma F_{x}'), (False, ' = m')]
    >>> caption_pieces("no mu_s")  # a Greek letter spelt out
    [(False, 'no '), (True, '\\\\mu_{s}')]
    >>> caption_pieces("(Ḣ_G)_y = (Ḣ)_rel")
    [(True, '(\\\\dot{H}_{G})_{y}'), (False, ' = ('), (True, '\\\\dot{H})_{rel}')]
    >>> caption_pieces("v_2_disk > μs N")  # a name's every subscript; μs is μ_s
    [(True, 'v_{2,disk}'), (False, ' > '), (True, '\\\\mu_{s}'), (False, ' N')]
    """
    text = ascii_maths(text)
    out: list[tuple[bool, str]] = []
    last = 0
    for match in _SUBSCRIPTED.finditer(text):
        out.append((False, text[last : match.start()]))
        if match["pbase"]:
            base = _BASES.get(match["pbase"]) or safe_math(match["pbase"]).strip()
            math = f"({base}_{{{match['inner']}}})_{{{match['outer']}}}"
        elif match["dot"]:
            math = _BASES["Ḣ"]
        elif match["closed"]:
            math = f")_{{{match['closed']}}}"
        elif match["mu"]:
            math = f"\\mu_{{{match['kind']}}}"
        else:
            sigma = {"Σ": "\\Sigma ", "Δ": "\\Delta ", "": ""}[match["op"]]
            word = match["base"]  # a Greek letter spelt out (mu_s) is the letter
            base = _BASES.get(word) or (latex_name(word) if word in GREEK else _base_math(word))
            sub = match["sub"].replace("_", ",")
            math = f"{sigma}{base}_{{{sub}}}{_POWERS[match['power']]}"
        if out[-1] == (False, "") and len(out) > 1 and out[-2][0]:
            out[-2:] = [(True, out[-2][1] + math)]  # one formula, not two touching
        else:
            out.append((True, math))
        last = match.end()
    out.append((False, text[last:]))
    return [piece for piece in out if piece[1]]


def _base_math(word: str) -> str:
    """A subscripted name's base: a letter in italic, a word (``wheel`` of wheel_A) upright.

    >>> _base_math("F"), _base_math("wheel"), _base_math("αH")
    ('F', '\\\\mathrm{wheel}', '\\\\alpha H')
    """
    if len(word) > 1 and word.isascii() and word.isalpha():
        return f"\\mathrm{{{word}}}"
    return safe_math(word).strip()


def _equation(row: EquationRow, tags: EquationTags = BY_LINE) -> str:
    note = caption_latex(row.note)
    if row.constraint:
        note = "Constraint" + (f": {note}" if note else "")
    # the dimension flush right, on the caption's last line or (no room) the next: never
    # touching the caption's words (the TeXbook's trick for a right-set tail)
    right = r"\unskip\nobreak\hfil\penalty50\hskip1em\hbox{}\nobreak\hfill"
    head = f"\\noindent\\textit{{{note}}}{right}{{\\small {_dimension(row)}}}"
    return "\n".join([
        head,
        r"\begin{equation*}",
        f"{_fitted(safe_math(row.latex).strip() or '?', EQUATION_WIDTH)} "
        f"\\tag*{{{tags.tag(row)}}}",
        r"\end{equation*}",
    ])  # fmt: skip


_DIMENSION = re.compile(r"^(.*\S)\s+\[([^\[\]]*)\]$")


def _dimension(row: EquationRow) -> str:
    """``[force, N] ✓`` from ``force [N]``, or a marked mismatch."""
    match = _DIMENSION.match(row.dimension.strip())
    text = f"{match.group(1)}, {pretty_unit(match.group(2))}" if match else row.dimension.strip()
    shown = f"{{[}}{escape_latex(text)}{{]}}" if text else ""
    if row.dimension_ok:
        return f"{shown}~$\\checkmark$"
    return f"\\textbf{{dimensions differ}} {shown}~$\\times$"


# ---- solution steps


def _trial_section(trial: Trial, tags: EquationTags = BY_LINE) -> str:
    """A case assumed first: its equations and solve, then the check that rejected it."""
    equations = _equations_section(trial.equations, tags).replace(
        "\\subsection*{Equations}", "\\subsubsection*{Equations}"
    )
    steps = _solution_section(trial.steps, tags).replace(
        "\\subsection*{Solution}", "\\subsubsection*{Solution}"
    )
    title = f"\\subsection*{{Trial: {caption_latex(trial.assumption)} (assumed, then checked)}}"
    verdict = f"\\textbf{{Check:}} $\\times$ {caption_latex(trial.verdict)}"
    remarks = [f"\\textit{{Remark:}} {caption_latex(r)}" for r in trial.remarks]
    moments = [
        m.replace("\\subsection*", "\\subsubsection*", 1)
        for m in _second_moments_section(trial.second_moments, tags)
    ]
    return "\n\n".join([title, equations, steps, *moments, verdict, *remarks])


def _solution_section(steps: Sequence[Step], tags: EquationTags = BY_LINE) -> str:
    if not steps:
        return "\\subsection*{Solution}\nNo solve steps."
    return "\n\n".join(["\\subsection*{Solution}", *(_step(s, tags) for s in steps)])


def _step(step: Step, tags: EquationTags = BY_LINE) -> str:
    names = and_list([_name(n) for n in step.unknowns])
    lead = f"\\paragraph{{Step {step.index}.}} " + (
        caption_latex(step.heading) if step.heading else f"{tags.phrase(step.lines, '--')} {names}"
    )
    lines = [f"{lead} ({escape_latex(step.method)}):"]
    if step.results:
        rows = " \\\\\n".join(_result(r) for r in step.results)
        lines += [r"\begin{align*}", rows, r"\end{align*}"]
    lines += _discarded([tags.untagged(d) for d in step.discarded])
    if step.note.strip():
        lines.append(f"\\textit{{{caption_latex(step.note)}}}")
    return "\n".join(lines)


def _result(result: Formula) -> str:
    """``T &= \\frac{...}{...} = 106\\,\\mathrm{N}``; the value alone when no formula."""
    formula = safe_math(result.formula_latex).strip()
    value = safe_math(result.value_latex).strip()
    numbers = safe_math(result.substituted_latex).strip()
    parts = [p for p in (formula, numbers, value) if p]
    if len(parts) >= 2 and formula == value:
        parts = [formula]
    name = safe_math(latex_name(result.name))
    if _printed_length(" = ".join(parts)) <= ONE_LINE:
        return f"{name} &= " + " = ".join(parts or ["?"])
    # a long chain as a hand calculation sets it: one "=" per line, each kept on the page
    return " \\\\\n".join(
        f"{name if i == 0 else ''} &= {_fitted(part, STEP_WIDTH)}" for i, part in enumerate(parts)
    )


ONE_LINE = 70  # printed characters a step's chain may take on one line
EQUATION_WIDTH = r"0.85\linewidth"  # an equation beside its tag
STEP_WIDTH = r"0.8\linewidth"  # one side of a step's "=", after its name


def _printed_length(latex: str) -> int:
    """About how many characters ``latex`` prints (commands, braces and spaces dropped).

    >>> _printed_length(r"\\frac{a}{b} + \\sin{\\left(\\theta \\right)}")
    7
    """
    quiet = re.sub(r"\\(left|right|frac|mathrm|text|qty|displaystyle)\b|[{}\s^_]", "", latex)
    return len(re.sub(r"\\[a-zA-Z]+", "#", quiet))  # a command prints about one glyph


def _fitted(latex: str, width: str) -> str:
    """``latex`` shrunk to ``width`` where it would be wider (``\\fitmath`` of the preamble),
    as it is where it fits; short formulas are left as they are."""
    if _printed_length(latex) <= ONE_LINE:
        return latex
    return f"\\fitmath{{{width}}}{{{latex}}}"


def _discarded(discarded: Sequence[str]) -> list[str]:
    if not discarded:
        return []
    items = [f"\\item {caption_latex(pretty_unit(d))}" for d in discarded]
    return ["Discarded roots:", r"\begin{itemize}", *items, r"\end{itemize}"]


# ---- answers and checks


def _answers_section(answers: Sequence[AnswerRow], key: Sequence[KeyComparison]) -> str:
    if not answers:
        return "\\subsection*{Answers}\nNo answers."
    expected = {k.name: k for k in key}
    header = ["Quantity", "Value"] + (["Answer key", ""] if expected else [])
    rows = [_answer_cells(a, expected.get(a.name), bool(expected)) for a in answers]
    spec = "@{}ll" + ("lc" if expected else "") + "@{}"
    return "\\subsection*{Answers}\n" + _table(spec, header, rows)


def _figure_section(figure: str) -> str:
    """The motion plot (``dynsolve solve --plot``'s figure) as a float in the sheet.

    >>> print(_figure_section("sheet-motion.pdf").splitlines()[2])
    \\includegraphics[width=0.85\\linewidth]{sheet-motion.pdf}
    """
    return (
        "\\begin{figure}[ht]\n\\centering\n"
        f"\\includegraphics[width=0.85\\linewidth]{{{figure}}}\n"
        "\\caption{The motion: the laws against time (or the path), with their units.}\n"
        "\\end{figure}"
    )


def _remark(remark: Remark | LimitRemark) -> str:
    """A remark with its names typeset as mathematics.

    >>> _remark(Remark(("v_2",), ("m_A",)))
    '$v_{2}$ does not depend on $m_{A}$: the mass cancels'
    >>> print(_remark(LimitRemark("h", "v_1", "nearly from rest", "R/3", "R/3", "", "", ("g",))))
    as $v_{1}$ $\\to$ 0 (nearly from rest), $h$ $\\to$ $R/3$, whatever $g$
    """
    if isinstance(remark, LimitRemark):
        value = safe_math(remark.value_latex) if remark.value_latex else ""
        return remark.words(
            f"${latex_name(remark.given)}$",
            f"${latex_name(remark.answer)}$",
            f"${remark.formula_latex}$",
            f"${value}$ {escape_latex(remark.direction)}".strip() if value else "",
            [f"${latex_name(n)}$" for n in remark.whatever],
            to="$\\to$",
        )
    answers = [f"${latex_name(n)}$" for n in remark.answers]
    return remark.words(answers, [f"${latex_name(n)}$" for n in remark.masses])


def answers_math(solution: Solution) -> str:
    """The answers as one display-math block (what Jupyter shows for ``_repr_latex_``;
    MathJax has no siunitx, so units stay ``\\mathrm``).

    >>> answer = AnswerRow("T", 105.86, "N", "106 N", "14715/139", "106\\\\,\\\\mathrm{N}", "")
    >>> answers_math(Solution("t.dyn", "", "", "SI", "exact", (), (), (), (answer,), (), (), ""))
    '$$\\\\begin{aligned} T &= 106\\\\,\\\\mathrm{N} \\\\end{aligned}$$'
    """
    rows = [
        f"{latex_name(a.name)} &= "
        f"{safe_math(a.latex, siunitx=False).strip() or escape_latex(a.shown)}"
        for a in solution.answers
    ]
    return "$$\\begin{aligned} " + " \\\\ ".join(rows) + " \\end{aligned}$$" if rows else ""


def _answer_cells(answer: AnswerRow, key: KeyComparison | None, keyed: bool) -> list[str]:
    value = _math(answer.latex) or f"\\textit{{{escape_latex(answer.shown)}}}"
    if answer.direction:
        value += f" {escape_latex(answer.direction)}"
    cells = [_name(answer.name), value]
    if keyed:
        cells += [escape_latex(pretty_unit(key.expected)), _mark(key.passed)] if key else ["", ""]
    return cells


def _mark(passed: bool) -> str:
    return "$\\checkmark$" if passed else "$\\times$"


def _status_mark(status: str) -> str:
    """✓ passed, × failed, – not run (could not run or decide)."""
    return "--" if status == NOT_RUN else _mark(status == PASSED)


def _checks_section(checks: Sequence[Check]) -> str:
    if not checks:
        return "\\subsection*{Checks}\nNo checks."
    _, failed, not_run = check_counts(checks)
    verdict = f"All {len(checks)} checks passed."
    if not_run:
        verdict = f"{len(checks) - not_run} of {len(checks)} checks passed; {not_run} not run."
    if failed:
        verdict = f"\\textbf{{{failed} of {len(checks)} checks failed.}}"
        verdict += f" {not_run} not run." if not_run else ""
    items = [f"\\item[{_status_mark(c.status)}] {_check_text(c)}" for c in checks]
    return "\n".join(["\\subsection*{Checks}", verdict, r"\begin{itemize}", *items,
                      r"\end{itemize}"])  # fmt: skip


def _check_text(check: Check) -> str:
    detail = f": {escape_latex(pretty_unit(check.detail))}" if check.detail.strip() else ""
    status = {PASSED: "", FAILED: " (failed)", NOT_RUN: " (not run)"}[check.status]
    return f"\\textbf{{{escape_latex(check.name)}}}{status}{detail}"


# ---- free-body diagrams (scene mode)

_IDENTIFIER = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
_COMPONENT = re.compile(r"\(([A-Za-z][A-Za-z0-9_]*)\)_([A-Za-z0-9]+)")  # (a_G)_x


def _linkage_section(solution: Solution) -> list[str]:
    """The linkage drawn at the instant (a scene of bars), or nothing."""
    if solution.linkage is None:
        return []
    from dynsolve.render.linkage_figure import linkage_picture

    return [
        "\\subsection*{The linkage at the instant}",
        "\\begin{center}\n" + linkage_picture(solution.linkage) + "\n\\end{center}",
    ]


def _sketch_section(solution: Solution) -> list[str]:
    """The problem's figure (a planar scene: bodies, supports, loads), or nothing."""
    if solution.sketch is None:
        return []
    from dynsolve.render.scene_figure import scene_picture

    return [
        "\\subsection*{The scene}",
        "\\begin{center}\n" + scene_picture(solution.sketch) + "\n\\end{center}",
    ]


def _free_body_section(bodies: Sequence[FreeBody], system: str = "SI") -> list[str]:
    """The "Free-body diagrams" subsection, or nothing in equation mode."""
    if not bodies:
        return []
    return ["\\subsection*{Free-body diagrams}", *(_free_body(b, system) for b in bodies)]


def _length(metres: float, system: str) -> str:
    """A diagram's dimension in the sheet's units, to 3 significant figures.

    >>> print(_length(0.54, "SI"), _length(0.3048, "FPS"))
    $\\qty{0.54}{m}$ $\\qty{1}{ft}$
    """
    value, unit = (metres / 0.3048, "ft") if system.upper() == "FPS" else (metres, "m")
    return f"$\\qty{{{float(f'{value:.3g}'):g}}}{{{unit}}}$"


def _free_body(body: FreeBody, system: str = "SI") -> str:
    """One body: its picture, then the motion, the moment point and the kinetic terms."""
    shape = f" ({escape_latex(body.shape)})" if body.shape.strip() else ""
    facts = [f"\\textbf{{Motion:}} {caption_latex(body.motion) or '?'}."]
    if body.moment_point.strip():
        facts.append(f"\\textbf{{Moments about:}} {caption_latex(body.moment_point)}.")
    if body.kinetic:
        terms = ", ".join(_kinetic_term(t) for t in body.kinetic)
        facts.append(f"\\textbf{{Kinetic diagram:}} {terms}.")
    if any(not f.known for f in body.forces):
        facts.append("{\\small Unknown forces are dashed and red; known forces solid.}")
    if body.kinetic:
        facts.append("{\\small The kinetic diagram (blue, right of =) shows the senses assumed.}")
    # the heading kept with its picture; the facts below may go on to the next page, so a
    # body that does not fit whole leaves no half-empty page behind
    return "\n".join([
        r"\par\noindent\begin{minipage}{\linewidth}",
        f"\\subsubsection*{{{caption_latex(body.body) or '?'}{shape}}}",
        r"\begin{center}",
        free_body_picture(body, system),
        r"\end{center}",
        r"\end{minipage}\par",
        " \\\\\n".join(facts),
        r"\par\medskip",
    ])  # fmt: skip


def free_body_picture(body: FreeBody, system: str = "SI") -> str:
    """The body's free-body diagram (and kinetic diagram) as TikZ, its labels typeset as
    on the sheet: force names as math, dimensions in the sheet's units."""
    return free_body_tikz(body, _force_label, _kinetic_term, lambda d: _length(d, system))


def _kinetic_term(term: str) -> str:
    """``m a_Gx`` as ``$m \\, a_{Gx}$`` and ``m (a_G)_x`` as ``$m \\, (a_{G})_{x}$`` when
    every word is a name, a component of one, or Greek (with a power); else as text.

    >>> print(_kinetic_term("m (a_G)_x"), _kinetic_term("m ω² r_G"))
    $m \\, (a_{G})_{x}$ $m \\, \\omega^{2} \\, r_{G}$
    """
    math = kinetic_math(term)
    return escape_latex(term) if math is None else f"${math}$"


def kinetic_math(term: str) -> str | None:
    """A kinetic-diagram term (``m (a_G)_x``, ``I_G α``) as LaTeX math, or None when a word
    of it is not a name, a component of one, or Greek (with a power).

    >>> kinetic_math("I_G α"), kinetic_math("2 m")
    ('I_{G} \\\\, \\\\alpha', None)
    """
    parts = []
    for word in term.split():
        component = _COMPONENT.fullmatch(word)
        if _IDENTIFIER.fullmatch(word):
            parts.append(latex_name(word))
        elif component:
            parts.append(f"({latex_name(component[1])})_{{{component[2]}}}")
        elif _greek(word.rstrip("²")):
            power = "^{2}" if word.endswith("²") else ""
            parts.append(safe_math(word.rstrip("²")).strip() + power)
        else:
            return None
    return r" \, ".join(parts) if parts else None


def _greek(word: str) -> bool:
    return all(char in _GREEK for char in word)


def _force_label(force: ForceRow) -> str:
    """The force's name as math (spec names) or escaped text (anything else)."""
    if _IDENTIFIER.fullmatch(force.name):
        return _name(force.name)
    return escape_latex(force.name) or "?"


# ---- assumptions


def _assumptions_section(assumptions: Sequence[Assumption]) -> list[str]:
    """The "Assumptions" subsection: each assumption made to solve, and whether it held."""
    if not assumptions:
        return []
    items = [f"\\item[{_status_mark(a.status)}] {_assumption_text(a)}" for a in assumptions]
    return ["\n".join(["\\subsection*{Assumptions}", r"\begin{itemize}", *items,
                       r"\end{itemize}"])]  # fmt: skip


def _assumption_text(assumption: Assumption) -> str:
    detail = pretty_unit(assumption.detail)
    detail = f": {caption_latex(detail)}" if detail.strip() else ""
    status = {PASSED: "holds", FAILED: "\\textbf{fails}", NOT_RUN: "not decided"}[assumption.status]
    return f"\\textbf{{{caption_latex(assumption.name) or '?'}}} ({status}){detail}"
