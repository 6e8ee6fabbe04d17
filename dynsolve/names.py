"""How spec names are displayed: Greek letters and subscripts, as text and as LaTeX.

>>> pretty("mu_s"), pretty("alpha"), pretty("theta2"), pretty("a_G")
('μ_s', 'α', 'θ2', 'a_G')
>>> latex_name("k_G"), latex_name("omega_CD"), latex_name("theta_ddot")
('k_{G}', '\\\\omega_{CD}', '\\\\ddot{\\\\theta}')
"""

from __future__ import annotations

import re
from functools import lru_cache

GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "zeta": "ζ",
    "eta": "η", "theta": "θ", "iota": "ι", "kappa": "κ", "lambda_": "λ", "lam": "λ", "mu": "μ",
    "nu": "ν", "xi": "ξ", "rho": "ρ", "sigma": "σ", "tau": "τ", "phi": "φ", "chi": "χ",
    "psi": "ψ", "omega": "ω", "Gamma": "Γ", "Delta": "Δ", "Theta": "Θ", "Lambda": "Λ",
    "Xi": "Ξ", "Pi": "Π", "Sigma": "Σ", "Phi": "Φ", "Psi": "Ψ", "Omega": "Ω",
}  # fmt: skip
_LATEX_GREEK = {name: "\\" + name.rstrip("_") for name in GREEK}
_LATEX_GREEK.update({"lam": "\\lambda", "lambda_": "\\lambda"})
_ACCENTS = {"dot": "\\dot", "ddot": "\\ddot", "hat": "\\hat", "bar": "\\bar"}
_TRAILING_DIGITS = re.compile(r"^([A-Za-z]+?)(\d+)$")


@lru_cache(maxsize=8192)  # a scene's few hundred names, asked for by every row they are in
def pretty(name: str) -> str:
    """The name with Greek words replaced by letters (``omega_CD`` → ``ω_CD``)."""
    head, *rest = name.split("_")
    match = _TRAILING_DIGITS.match(head)
    digits = ""
    if match and match.group(1) in GREEK:
        head, digits = match.group(1), match.group(2)
    head = GREEK.get(head, head)
    return "_".join([head + digits, *(GREEK.get(part, part) for part in rest)])


@lru_cache(maxsize=8192)
def latex_name(name: str) -> str:
    """The name as LaTeX math: ``k_G`` → ``k_{G}``, ``theta_dot`` → ``\\dot{\\theta}``."""
    head, *rest = name.split("_")
    accent = ""
    if rest and rest[-1] in _ACCENTS:
        accent = _ACCENTS[rest.pop()]
    match = _TRAILING_DIGITS.match(head)
    if match and not rest:
        head, rest = match.group(1), [match.group(2)]
    body = _LATEX_GREEK.get(head, head if len(head) == 1 else f"\\mathrm{{{head}}}")
    if accent:
        body = f"{accent}{{{body}}}"
    if rest:
        subscript = ",".join(_LATEX_GREEK.get(part, part) for part in rest)
        body = f"{body}_{{{subscript}}}"
    return body
