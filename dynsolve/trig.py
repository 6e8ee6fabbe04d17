"""Trigonometric polynomials of a scene's angles in a canonical form (sin² + cos² = 1).

The scene's vectors are written with the sines and cosines of its angles (a tilted axis
(sin θ, cos θ, 0)); products of them (I_G = R J Rᵀ, ω × H_G, r × m a_G) hold powers
sin³θ, sin θ cos²θ that ``sin² + cos² = 1`` reduces. Written as a polynomial in
s = sin u and c = cos u, the remainder of its division by s² + c² − 1 (in s) is
A(c) + s B(c), one form for each function of u: two forms equal as functions have the
same remainder (the ideal of s² + c² − 1 is prime and {1, s} a basis over the functions
of c), so a form is identically 0 exactly when its remainder expands to 0 (so too the
remainder in c, A(s) + c B(s)).

>>> import sympy
>>> u, a = sympy.symbols("u a")
>>> pythagoras(a * sympy.sin(u) ** 3 + a * sympy.sin(u) * sympy.cos(u) ** 2)
a*sin(u)
>>> pythagoras(sympy.sin(2 * u) / 2 - sympy.sin(u) * sympy.cos(u))
0
>>> pythagoras(a * sympy.cos(u) ** 2 - a), shortest(a * sympy.sin(u) ** 2)
(-a*sin(u)**2, a*sin(u)**2)
>>> vanishes(sympy.sin(u) ** 3 + sympy.sin(u) * sympy.cos(u) ** 2 - sympy.sin(u))
True
"""

from __future__ import annotations

import sympy

from dynsolve.numbers import printed_size, surely_nonzero, tidy


def pythagoras(expr: sympy.Expr) -> sympy.Expr:
    """``expr`` reduced with sin²u + cos²u = 1 for each angle u until only one of sin u
    and cos u is left squared or higher (the one that leaves the shorter form; sin 2u
    written 2 sin u cos u first), its common factors taken out; ``expr`` itself when it is
    not a polynomial in the sines and cosines."""
    expr = sympy.Integer(0) + expr
    reduced = reduced_form(expr)
    return expr if reduced is None else sympy.factor_terms(reduced)


def reduced_form(expr: sympy.Expr, sums: bool = True) -> sympy.Expr | None:
    """:func:`pythagoras`'s remainder, expanded; None when there is no sine or cosine or
    ``expr`` is not a polynomial in them. Without ``sums``, also None for a sine or cosine
    of a sum of angles (A sin(ω t + φ) keeps its phase rather than being expanded)."""
    if not expr.has(sympy.sin, sympy.cos):
        return None
    if not sums and any(f.args[0].is_Add for f in expr.atoms(sympy.sin, sympy.cos)):
        return None
    expanded = sympy.expand(sympy.expand_trig(expr))
    angles = sorted(
        {f.args[0] for f in expanded.atoms(sympy.sin, sympy.cos)}, key=sympy.default_sort_key
    )
    letters = {u: (sympy.Dummy("s"), sympy.Dummy("c")) for u in angles}
    for u, (s, c) in letters.items():
        expanded = expanded.xreplace({sympy.sin(u): s, sympy.cos(u): c})
    if expanded.has(sympy.sin, sympy.cos):  # a sine of a sum that expand_trig kept
        return None
    for s, c in letters.values():
        reduced = [_remainder(expanded, s, c), _remainder(expanded, c, s)]
        if None in reduced:  # a sine in a denominator or under a root
            return None
        expanded = min(reduced, key=printed_size)  # type: ignore[arg-type]
    back = {x: f(u) for u, (s, c) in letters.items() for x, f in ((s, sympy.sin), (c, sympy.cos))}
    return expanded.xreplace(back)


def _remainder(expanded: sympy.Expr, x: sympy.Symbol, y: sympy.Symbol) -> sympy.Expr | None:
    """The remainder of the polynomial ``expanded`` in x divided by x² + y² − 1 (x^k
    written x^(k mod 2) (1 − y²)^(k div 2)), expanded; None where x is not in it as a
    power with a natural exponent."""
    terms = []
    for term in sympy.Add.make_args(expanded):
        rest, k = term.as_coeff_exponent(x)
        if rest.has(x) or not (k.is_Integer and k >= 0):
            return None
        terms.append(rest * x ** (k % 2) * (1 - y**2) ** (k // 2))
    return sympy.expand(sympy.Add(*terms))


def shortest(expr: sympy.Expr) -> sympy.Expr:
    """The form of ``expr`` that prints shortest: as it is, with its common factors out, or
    as :func:`tidied` writes it (reduced by :func:`pythagoras`)."""
    expr = sympy.Integer(0) + expr
    forms = [expr, sympy.factor_terms(expr)]
    reduced = reduced_form(expr)
    if reduced is not None:
        forms += [sympy.factor_terms(reduced), sympy.factor_terms(_double_angles(reduced))]
    return min(forms, key=printed_size)


def tidied(expr: sympy.Expr) -> sympy.Expr:
    """``expr`` as a 3D scene shows it: with sines and cosines, reduced by :func:`pythagoras`,
    or that form with each sin u cos u written sin(2u)/2, whichever prints shorter (a
    canonical form that ``sympy.simplify`` hardly ever shortens, at a hundred times the
    cost); else :func:`~dynsolve.numbers.tidy`.

    >>> u, a, b = sympy.symbols("u a b")
    >>> tidied(a * sympy.sin(u) ** 2 * sympy.cos(u) + a * sympy.cos(u) ** 3 + b * sympy.sin(2 * u))
    a*cos(u) + b*sin(2*u)
    """
    expr = sympy.Integer(0) + expr
    reduced = reduced_form(expr)
    if reduced is None:
        return tidy(expr)
    forms = (sympy.factor_terms(reduced), sympy.factor_terms(_double_angles(reduced)))
    return min(forms, key=printed_size)


def _double_angles(expr: sympy.Expr) -> sympy.Expr:
    """``expr`` with sin u cos u written sin(2u)/2 in each product that holds both once."""

    def folded(term: sympy.Expr) -> sympy.Expr:
        powers = term.as_powers_dict()
        for u in {f.args[0] for f in term.args if isinstance(f, sympy.sin)}:
            if powers.get(sympy.sin(u)) == 1 and powers.get(sympy.cos(u)) == 1:
                term = term / (sympy.sin(u) * sympy.cos(u)) * sympy.sin(2 * u) / 2
        return term

    return expr.replace(lambda e: e.is_Mul, folded)


def vanishes(expr: sympy.Expr) -> bool:
    """Whether ``expr`` is identically 0: not when it is a number other than 0 at a sample
    point of its letters (to the digits sympy's ``evalf`` guarantees: no identity then);
    else when its reduced form (:func:`pythagoras`) expands to 0; else as
    ``sympy.simplify`` finds, the last resort."""
    expr = sympy.Integer(0) + expr
    if expr == 0:
        return True
    if surely_nonzero(expr):
        return False
    return sympy.expand(pythagoras(expr)) == 0 or sympy.simplify(expr) == 0
