"""Names a package loads on first use: the one helper behind screwkit's lazy imports.

In a package's ``__init__``::

    __getattr__, __dir__ = _lazy.attach(__name__, {"module": ("name", ...)}, globals())

``package.module`` then imports the submodule when it is first read, and
``package.name`` imports its module and reads the name, which stays in the package as an
ordinary attribute afterwards. A submodule listed with no names loads only as itself
(matplotlib, ipywidgets and scipy.optimize are imported by such modules, so importing
screwkit does not import them).
"""

import importlib


def attach(package, lazy, namespace):
    """The ``__getattr__`` and ``__dir__`` of a package whose names load on first use.

    Parameters
    ----------
    package : str
        The package's ``__name__``.
    lazy : dict of str to tuple of str
        Each submodule loaded on first use, and the names read from it.
    namespace : dict
        The package's ``globals()``: a name found is kept there.

    Returns
    -------
    tuple of callable
        ``(__getattr__, __dir__)`` for the package's module.
    """

    def __getattr__(name):
        if name in lazy:
            return importlib.import_module(f".{name}", package)
        for module, names in lazy.items():
            if name in names:
                value = getattr(importlib.import_module(f".{module}", package), name)
                namespace[name] = value  # found once, then an ordinary attribute
                return value
        raise AttributeError(f"module {package!r} has no attribute {name!r}")

    def __dir__():
        return sorted({*namespace, *namespace.get("__all__", ()), *lazy})

    return __getattr__, __dir__
