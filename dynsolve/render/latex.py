"""Render a :class:`~dynsolve.results.Solution` as a standalone LaTeX document for pdflatex.

The document needs only Debian's ``texlive-latex-base`` and ``texlive-latex-recommended``
(article, amsmath, amssymb, booktabs, geometry). It is pure ASCII and uses
the default OT1 encoding, so the Computer Modern Type 1 fonts are used and no font has to be
generated. Plain text goes through :func:`escape_latex`; the LaTeX fragments of the solution
(``latex``, ``latex_name``, ``latex_value``, ``formula_latex``, ``value_latex``) go through
:func:`safe_math`.
"""

from __future__ import annotations

import itertools
import re
import unicodedata
from collections.abc import Callable, Iterable, Iterator, Sequence
from pathlib import PurePath

from dynsolve.format import and_list, lines_phrase, pretty_unit
from dynsolve.names import latex_name
from dynsolve.results import (
    AnswerRow,
    Check,
    EquationRow,
    Formula,
    GivenRow,
    KeyComparison,
    Solution,
    Step,
)

PREAMBLE = r"""\documentclass[11pt]{article}
\usepackage[a4paper,margin=2.5cm]{geometry}
\usepackage{amsmath}
\usepackage{amssymb}
\usepackage{booktabs}
\allowdisplaybreaks
\renewcommand{\arraystretch}{1.25}
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.6ex}"""

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


def safe_math(fragment: str) -> str:
    """A LaTeX math fragment made pure ASCII and safe to put between math delimiters.

    Non-ASCII characters become math commands (or ``\\text{...}``), stray ``%``, ``#`` and
    ``$`` are escaped and line breaks become spaces; the LaTeX itself is trusted.

    >>> print(safe_math("T r = I_{O} α·2 — % x"))
    T r = I_{O}  \\alpha \\cdot 2 \\text{---} \\% x
    """
    fragment = _MATH_UNSAFE.sub(r"\\\1", fragment)
    pieces: list[Piece] = []
    for char in fragment:
        if char.isascii():
            pieces.append(("raw", char if char.isprintable() else " "))
        else:
            pieces.extend(_char_pieces(char))
    return "".join(_math_group(kind, list(run)) for kind, run in _runs(pieces, _math_kind))


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


def render_latex(solution: Solution) -> str:
    """The solution as a standalone LaTeX document (article class) for pdflatex.

    >>> from dynsolve.results import AnswerRow, Solution
    >>> answer = AnswerRow("T", 105.86, "N", "106 N", "14715/139", "106\\\\,\\\\mathrm{N}", "")
    >>> doc = render_latex(Solution("d.dyn", "Drum & block", "Hibbeler 17.11", "SI",
    ...                             "equations", (), (), (), (answer,), (), (), "solved"))
    >>> doc.splitlines()[0], doc.splitlines()[-1]
    ('\\\\documentclass[11pt]{article}', '\\\\end{document}')
    >>> "\\\\section*{Drum \\\\& block}" in doc, "$106\\\\,\\\\mathrm{N}$" in doc
    (True, True)
    """
    body = [
        _title(solution),
        _givens_section(solution.givens),
        _equations_section(solution.equations),
        _solution_section(solution.steps),
        _answers_section(solution.answers, solution.key),
        _checks_section(solution.checks),
    ]
    return "\n\n".join([PREAMBLE, r"\begin{document}", *body, r"\end{document}"]) + "\n"


def _math(fragment: str) -> str:
    """Inline math, or nothing for an empty fragment."""
    fragment = safe_math(fragment).strip()
    return f"${fragment}$" if fragment else ""


def _name(name: str) -> str:
    return _math(latex_name(name))


def _title(solution: Solution) -> str:
    title = escape_latex(solution.title.strip() or PurePath(solution.file).name or "Problem")
    lines = [f"\\section*{{{title}}}"]
    if solution.source.strip():
        lines.append(f"{{\\large\\itshape {escape_latex(solution.source)}\\par}}")
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


def _givens_section(givens: Sequence[GivenRow]) -> str:
    if not givens:
        return "\\subsection*{Given}\nNo givens."
    header = ["Symbol", "Value", "SI value", "Description"]
    rows = [_given_cells(g) for g in givens]
    return "\\subsection*{Given}\n" + _table(r"@{}lllp{0.4\linewidth}@{}", header, rows)


def _given_cells(given: GivenRow) -> list[str]:
    value = escape_latex(given.written) if given.symbolic else _math(given.latex_value)
    return [_math(given.latex_name), value, escape_latex(given.si), escape_latex(given.description)]


# ---- equations


def _equations_section(equations: Sequence[EquationRow]) -> str:
    if not equations:
        return "\\subsection*{Equations}\nNo equations."
    return "\n\n".join(["\\subsection*{Equations}", *(_equation(e) for e in equations)])


def _equation(row: EquationRow) -> str:
    note = escape_latex(row.note)
    if row.constraint:
        note = "Constraint" + (f": {note}" if note else "")
    head = f"\\noindent\\textit{{{note}}}\\hfill{{\\small {_dimension(row)}}}"
    return "\n".join([
        head,
        r"\begin{equation*}",
        f"{safe_math(row.latex).strip() or '?'} \\tag*{{(line {row.line})}}",
        r"\end{equation*}",
    ])  # fmt: skip


_DIMENSION = re.compile(r"^(.*\S)\s+\[([^\[\]]*)\]$")


def _dimension(row: EquationRow) -> str:
    """``[force, N] ✓`` from ``force [N]``, or a marked mismatch."""
    match = _DIMENSION.match(row.dimension.strip())
    text = f"{match.group(1)}, {match.group(2)}" if match else row.dimension.strip()
    shown = f"{{[}}{escape_latex(text)}{{]}}" if text else ""
    if row.dimension_ok:
        return f"{shown}~$\\checkmark$"
    return f"\\textbf{{dimensions differ}} {shown}~$\\times$"


# ---- solution steps


def _solution_section(steps: Sequence[Step]) -> str:
    if not steps:
        return "\\subsection*{Solution}\nNo solve steps."
    return "\n\n".join(["\\subsection*{Solution}", *(_step(s) for s in steps)])


def _step(step: Step) -> str:
    names = and_list([_name(n) for n in step.unknowns])
    lead = f"\\paragraph{{Step {step.index}.}} {lines_phrase(step.lines, '--')} {names}"
    lines = [f"{lead} ({escape_latex(step.method)}):"]
    if step.results:
        rows = " \\\\\n".join(_result(r) for r in step.results)
        lines += [r"\begin{align*}", rows, r"\end{align*}"]
    lines += _discarded(step.discarded)
    if step.note.strip():
        lines.append(f"\\textit{{{escape_latex(step.note)}}}")
    return "\n".join(lines)


def _result(result: Formula) -> str:
    """``T &= \\frac{...}{...} = 106\\,\\mathrm{N}``; the value alone when no formula."""
    formula = safe_math(result.formula_latex).strip()
    value = safe_math(result.value_latex).strip()
    parts = [p for p in (formula, value) if p]
    if len(parts) == 2 and formula == value:
        parts = [formula]
    return f"{safe_math(latex_name(result.name))} &= " + " = ".join(parts or ["?"])


def _discarded(discarded: Sequence[str]) -> list[str]:
    if not discarded:
        return []
    items = [f"\\item {escape_latex(pretty_unit(d))}" for d in discarded]
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


def _answer_cells(answer: AnswerRow, key: KeyComparison | None, keyed: bool) -> list[str]:
    value = _math(answer.latex) or f"\\textit{{{escape_latex(answer.shown)}}}"
    cells = [_name(answer.name), value]
    if keyed:
        cells += [escape_latex(pretty_unit(key.expected)), _mark(key.passed)] if key else ["", ""]
    return cells


def _mark(passed: bool) -> str:
    return "$\\checkmark$" if passed else "$\\times$"


def _checks_section(checks: Sequence[Check]) -> str:
    if not checks:
        return "\\subsection*{Checks}\nNo checks."
    failed = sum(not c.passed for c in checks)
    verdict = f"All {len(checks)} checks passed."
    if failed:
        verdict = f"\\textbf{{{failed} of {len(checks)} checks failed.}}"
    items = [f"\\item[{_mark(c.passed)}] {_check_text(c)}" for c in checks]
    return "\n".join(["\\subsection*{Checks}", verdict, r"\begin{itemize}", *items,
                      r"\end{itemize}"])  # fmt: skip


def _check_text(check: Check) -> str:
    detail = f": {escape_latex(pretty_unit(check.detail))}" if check.detail.strip() else ""
    status = "" if check.passed else " (failed)"
    return f"\\textbf{{{escape_latex(check.name)}}}{status}{detail}"
