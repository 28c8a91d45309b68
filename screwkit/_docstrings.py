"""Docstrings that share a passage: the passage written once, filled in at import.

Where several functions take the same parameters or differ only by a word (the space,
body and geometric forms of one quantity), their docstrings hold a placeholder such as
``{rates}`` or ``{form}`` and the passage is written once, beside them:

>>> @fill(what="a pose", returns="Returns\\n-------\\nfloat\\n    Its size.")
... def size(T):
...     '''The size of {what}.
...
...     {returns}
...     '''
>>> import inspect
>>> print(inspect.cleandoc(size.__doc__))
The size of a pose.
<BLANKLINE>
Returns
-------
float
    Its size.
"""

import textwrap

__all__ = ["fill", "CHAIN", "CHAIN_Q"]

#: The Parameters section of a function of a chain (a Chain's method is such a
#: function: ``chain.fk(q)`` is ``fk(chain, q)``); ``{chain}`` in its docstring.
CHAIN = """Parameters
----------
chain : Chain
    The serial chain."""
#: The same with the chain's joint values, one configuration or a batch.
CHAIN_Q = (
    CHAIN
    + """
q : array-like, shape (n,) or (N, n)
    Joint values (rad or m)."""
)


def fill(**passages):
    """A decorator filling the ``{name}`` placeholders of a docstring.

    Parameters
    ----------
    **passages : str
        The text of each placeholder; a passage of several lines is indented as its
        placeholder is, so that a shared Parameters section reads as if written out.

    Returns
    -------
    callable
        The decorator: it sets ``function.__doc__`` and returns the function itself.
    """

    def decorate(function):
        if function.__doc__ is None:  # python -OO strips docstrings
            return function
        lines = []
        for line in function.__doc__.split("\n"):
            indent = line[: len(line) - len(line.lstrip())]
            for name, text in passages.items():
                block = textwrap.indent(text, indent).lstrip()
                line = line.replace("{" + name + "}", block)
            lines.append(line)
        function.__doc__ = "\n".join(lines)
        return function

    return decorate
