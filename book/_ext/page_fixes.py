"""Two fixes to what every page's <head> carries, so that pages log no JavaScript error.

* The theme stack registers the inline setup scripts of sphinx-thebe and sphinx-togglebutton
  twice (``const THEBE_JS_URL`` declared twice is a SyntaxError in the browser): each
  page's scripts are kept once, in their first position.
* pydata-sphinx-theme reads the colour mode from ``html_context['default_mode']``, which
  nothing sets here, and logs "Got invalid theme mode" when it is empty: it is set to
  'light' unless the book's configuration chooses another.
"""


def _key(script):
    """What makes a script the same one: its file (None and '' alike: an inline body) and attributes."""
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


def setup(app):
    app.connect("config-inited", default_mode)
    app.connect("html-page-context", unique_scripts, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
