"""Textbook notation for exact kinematics: cos(q1) -> c1, sin(q2 + q3) -> s23."""

import numbers

import sympy as sp

from ._checks import describe

__all__ = ["textbook"]


def textbook(expr, q_symbols=None, collect=True):
    """``expr`` in textbook notation: cos(q1) -> c1, sin(q2 + q3) -> s23.

    Parameters
    ----------
    expr : SymPy expression or matrix
        E.g. ``chain.fk_symbolic()``; a matrix is converted entry by entry.
    q_symbols : list of sympy.Symbol, optional
        The joint symbols; by default the free symbols whose names start with "q".
    collect : bool, optional
        Group sums by c1/s1 first, then by the next angles, which gives nested forms
        like c1 (c23 (...) - s23 (...)) - s1 (...).

    Returns
    -------
    SymPy expression or matrix
        ``expr`` with c1, s23, ... symbols in place of the cosines and sines.

    Examples
    --------
    >>> q1, q2, q3 = sp.symbols("q1 q2 q3")
    >>> textbook(sp.cos(q1) * sp.cos(q2 + q3) + sp.sin(q2))
    c1*c_{23} + s2
    """
    if isinstance(expr, sp.MatrixBase):
        return expr.applyfunc(lambda e: textbook(e, q_symbols, collect))
    if isinstance(expr, (str, bytes)) or not isinstance(
        expr, (sp.Basic, numbers.Number)
    ):
        raise TypeError(
            f"expr must be a SymPy expression or matrix (e.g. chain.fk_symbolic()), "
            f"got {describe(expr)}"
        )
    expr = sp.sympify(expr)
    if q_symbols is not None and (
        isinstance(q_symbols, (str, sp.Basic))
        or not isinstance(q_symbols, (list, tuple))
        or not all(isinstance(q, sp.Symbol) for q in q_symbols)
    ):
        raise TypeError(
            f"q_symbols must be a list of SymPy symbols (e.g. chain.q_symbols), "
            f"got {describe(q_symbols)}"
        )
    q_symbols = q_symbols or sorted(
        (s for s in expr.free_symbols if str(s).startswith("q")), key=str
    )
    index = {q: str(q)[1:] for q in q_symbols}
    replacements, order = {}, []
    for function, letter in ((sp.cos, "c"), (sp.sin, "s")):
        for call in expr.atoms(function):
            argument = call.args[0]
            terms = argument.args if isinstance(argument, sp.Add) else (argument,)
            if all(t in index for t in terms):
                label = "".join(sorted((index[t] for t in terms), key=int))
                symbol = sp.Symbol(
                    f"{letter}_{{{label}}}" if len(label) > 1 else f"{letter}{label}"
                )
                replacements[call] = symbol
                order.append((label, letter, symbol))
    result = expr.xreplace(replacements)
    if collect and order:
        order.sort(key=lambda item: (len(item[0]), item[0], item[1]))
        result = _nested_collect(sp.expand(result), [symbol for _, _, symbol in order])
    return result


def _nested_collect(expr, symbols):
    """Collect by the first symbol pair (c_k, s_k) present, then recurse into the
    coefficients."""
    present = [s for s in symbols if expr.has(s)]
    if not present or not isinstance(expr, sp.Add):
        return expr
    lead = str(present[0])[1:]
    group = [s for s in present if str(s)[1:] == lead]
    rest = [s for s in present if s not in group]
    collected = sp.collect(expr, group, evaluate=False)
    if len(collected) == 1 and sp.S.One in collected:
        return _nested_collect(expr, rest)
    return sp.Add(
        *[_nested_collect(coeff, rest) * key for key, coeff in collected.items()]
    )
