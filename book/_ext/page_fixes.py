"""Fixes to what every page carries: no JavaScript error, one search, working buttons.

* The theme stack registers the inline setup scripts of sphinx-thebe and
  sphinx-togglebutton twice (``const THEBE_JS_URL`` declared twice is a SyntaxError in
  the browser): each page's scripts are kept once, in their first position.
* pydata-sphinx-theme reads the colour mode from ``html_context['default_mode']``, which
  nothing sets here, and logs "Got invalid theme mode" when it is empty: it is set to
  'light' unless the book's configuration chooses another.
* pydata-sphinx-theme 0.17 gives every page a header bar of its own unless
  ``navbar_persistent`` is set: above 960 px it shows a second search field across the
  top, and below it its hidden sidebar buttons come first in the page, so the theme's
  scripts (which bind to the first ``.primary-toggle`` and ``.secondary-toggle``) bound
  the table-of-contents and page-outline buttons to those hidden copies: on a phone they
  did nothing. With ``navbar_persistent`` empty the bar is not written at all, and the
  buttons the reader sees are the ones the scripts bind.
* The book's own small stylesheet and script (``book/_static/site``): tooltips that do
  not stay behind after a tap, code and equations that fit the column (see their
  comments).
"""

import os

HERE = os.path.dirname(os.path.abspath(__file__))
STATIC = os.path.join(HERE, os.pardir, "_static", "site")


def _key(script):
    """The identity of a script: its file (None or '': inline) and its attributes."""
    attributes = getattr(script, "attributes", {}) or {}
    filename = getattr(script, "filename", script) or ""
    return str(filename), tuple(sorted((k, str(v)) for k, v in attributes.items()))


def unique_scripts(app, pagename, templatename, context, doctree):
    scripts = context.get("script_files")
    if scripts:
        seen, kept = set(), []
        for script in scripts:
            if _key(script) not in seen:
                seen.add(_key(script))
                kept.append(script)
        scripts[:] = kept


def default_mode(app, config):
    config.html_context.setdefault("default_mode", "light")


def no_header_bar(app, config):
    config.html_theme_options.setdefault("navbar_persistent", [])


def book_assets(app, config):
    config.html_static_path.append(os.path.normpath(STATIC))
    app.add_css_file("book.css")
    # Deferred scripts run in document order: this one before the theme's (which come
    # last).
    app.add_js_file("book.js", loading_method="defer")


def setup(app):
    app.connect("config-inited", default_mode)
    app.connect("config-inited", no_header_bar)
    app.connect("config-inited", book_assets)
    app.connect("html-page-context", unique_scripts, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
