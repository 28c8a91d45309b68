"""Serve MathJax 3 from the book itself, so pages typeset math with no network.

The files come from the PyPI package ``sphinx-mathjax-offline`` (MathJax 3.2.2),
installed by requirements.txt. Only what the pages load is copied into
``_build/html/_static/mathjax`` when the build finishes (``mathjax_path`` in
``_config.yml`` points there): the loader ``startup.js`` and the components that
``mathjax3_config`` asks it for (the core, TeX input, CHTML output and its font data,
and the assistive MathML that screen readers read), the CHTML fonts, and the TeX
extensions its autoloader fetches when a page uses a macro outside the base set
(``\\boldsymbol``, ``\\color``, ...). That is about 2 MB of the package's 24 MB; a page
loads 0.76 MB of it, where the combined ``tex-chtml.js`` was 1.16 MB (it also carries
the right-click menu, 0.43 MB, which the book does without). They are deliberately not
in a top-level ``_static/`` folder, whose every ``.js`` Jupyter Book would add to every
page.
"""

import importlib.util
import os
import shutil

from sphinx.errors import ExtensionError
from sphinx.util.fileutil import copy_asset

PACKAGE = "sphinx-mathjax-offline"
# What MathJax's loader fetches (the `loader.load` of mathjax3_config).
COMPONENTS = ("input/tex", "output/chtml", "a11y/assistive-mml")
# Paths relative to the package's static/mathjax folder: a file or a whole folder.
SHIPPED = (
    "startup.js",
    "core.js",
    os.path.join("input", "tex.js"),
    os.path.join("output", "chtml.js"),
    os.path.join("output", "chtml", "fonts", "tex.js"),
    os.path.join("a11y", "assistive-mml.js"),
    os.path.join("output", "chtml", "fonts", "woff-v2"),
    os.path.join("input", "tex", "extensions"),
)


def mathjax_source():
    spec = importlib.util.find_spec(PACKAGE)
    if spec is None or not spec.submodule_search_locations:
        raise ExtensionError(
            f"the package {PACKAGE} is missing: run `pip install -r requirements.txt`"
        )
    folder = os.path.join(list(spec.submodule_search_locations)[0], "static", "mathjax")
    missing = [
        path for path in SHIPPED if not os.path.exists(os.path.join(folder, path))
    ]
    if missing:
        raise ExtensionError(f"{PACKAGE} has no {', '.join(missing)} under {folder}")
    return folder


def copy_mathjax(app, exception):
    if exception is None and app.builder.format == "html":
        source, target = (
            mathjax_source(),
            os.path.join(app.outdir, "_static", "mathjax"),
        )
        for path in SHIPPED:
            destination = os.path.join(target, path)
            if os.path.isdir(os.path.join(source, path)):
                copy_asset(os.path.join(source, path), destination)
            else:
                copy_asset(os.path.join(source, path), os.path.dirname(destination))


def drop_unloaded_files(app, exception):
    """Remove from the build what no page loads: the themes' source maps (``*.map``,
    read only by a browser's developer tools) and pydata-sphinx-theme's translation
    catalogues (``_static/locales``, used when Sphinx writes the pages, never by the
    browser): 4 MB."""
    if exception is not None or app.builder.format != "html":
        return
    static = os.path.join(app.outdir, "_static")
    shutil.rmtree(os.path.join(static, "locales"), ignore_errors=True)
    for folder, _, files in os.walk(static):
        for name in files:
            if name.endswith(".map"):
                os.remove(os.path.join(folder, name))


def check_config(app, config):
    if config.mathjax_path != "mathjax/startup.js":
        raise ExtensionError(
            "mathjax_path must be 'mathjax/startup.js' (the bundled copy), "
            f"got {config.mathjax_path!r}"
        )
    mathjax = config.mathjax3_config if isinstance(config.mathjax3_config, dict) else {}
    config.mathjax3_config = mathjax
    mathjax.setdefault("loader", {}).setdefault("load", list(COMPONENTS))
    mathjax_source()


def setup(app):
    app.connect("config-inited", check_config)
    app.connect("build-finished", copy_mathjax)
    app.connect("build-finished", drop_unloaded_files)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
