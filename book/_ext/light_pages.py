"""Light pages: what every page of the book loads, cut to what it uses.

pydata-sphinx-theme puts Font Awesome on every page twice: as web fonts with their CSS
classes (``fa-solid-900.woff2`` and friends, from its stylesheet), which draw every icon
of the book, and as a 1.49 MB script, ``fontawesome.js``, which redraws the same icons
as SVG. When the build finishes, the script's tag is taken out of every page and the
script out of the build: the icons stay, drawn by the fonts. So are the tags of Sphinx's
search scripts and its index (0.13 MB), which the theme puts on every page for a
search-as-you-type that is off: the search page loads them itself.

The fonts themselves are cut to the glyphs the book shows (fontTools, which Matplotlib
already installs): every ``fa-NAME`` class written in a page or a script of the build,
and every icon the theme's stylesheet draws by code point (admonitions, the back-to-top
arrow, ...). The subsets are written as WOFF under new names and the stylesheet pointed
at them; the full fonts are removed, and so are the stylesheet's rules for the icons not
shown. 274 kB of fonts become 8 kB, and the theme's stylesheet loses some 100 kB.

Images inside HTML outputs (the frames of ``sk.plotting.animation_html`` and of the
stepped figures of ``sk.viewer``) are PNG data in the notebook, so that it needs no
file; in the book each becomes a file of ``_images/`` (named by its hash), which the
browser fetches only when the frame is shown, and caches. The redundancy chapter's
animation was 1.7 MB of HTML.

screwkit's own scripts travel inside the HTML outputs of a notebook, so that a notebook
needs no file and no network: three.js (deflated, 230 kB) and the viewers' script (the
files of ``screwkit/static/viewer/`` joined, 50 kB) with the first viewer of a page, the
answer boxes' script (12 kB) with the first box. In the book each becomes a file of
``_static/screwkit/`` named by its hash, loaded by a ``<script src>`` at the same place
(so it runs in the same order), which the browser fetches once for the whole book and
caches. A page's second copy of the same script (a stepped figure and a 3D viewer both
carry the viewers' script) is dropped: the first copy has defined ``window.screwkit``,
and every figure mounts itself with the call that follows it. The notebooks' ipywidgets
state (a live widget's model, 118 kB on the mobility page) is left out of the pages too
(taken out of the page's scripts in Sphinx's ``html-page-context``): the book loads no
widget script that would read it.

The figures (PNG files of ``_images/``) are written with a palette when they have at
most 256 colours (lossless), and otherwise quantised to 256 colours (median cut, no
dithering, as the stepped figures already are) when that changes no pixel by more than
``MAX_MEAN_ERROR`` on average; matplotlib's RGBA output of a white figure is three to
four times larger. A figure with transparency, or one that would not shrink, is kept.

The code of a cell tagged ``hide-input`` (a figure's drawing code, folded under the
figure) is shown without syntax colours: Pygments wraps every name and operator in a
span of its own, and the folded drawing code was a sixth of the largest chapters' HTML
(90 kB of the PUMA's inverse kinematics). A reader who unfolds it reads the same code in
plain monospace.

Syntax colours that are no colour: Pygments' stylesheet gives names, punctuation and
white space (``n``, ``p``, ``w``) the very colour it gives the whole code block, in the
light and in the dark theme, yet every such token is a span of its own. When the build
finishes, the spans of each class whose only rule, in both themes, is the block's own
colour are taken out of every page (their text stays): nothing changes on screen, and
the PUMA's inverse kinematics loses some 170 kB of HTML.

Alt texts: a code cell's ``mystnb: image: alt:`` metadata is myst-nb's alt text for the
cell's image outputs; the same text is given here to the images of the cell's HTML
outputs whose alt text says nothing (a stepped figure's "precomputed figure", an
animation's alt made from its axes), so that every figure of a chapter is described in
the chapter's words.
"""

import base64
import glob
import hashlib
import html
import io
import os
import posixpath
import re

from docutils import nodes
from fontTools import subset
from fontTools.ttLib import TTFont

# The theme's templates write these tags themselves (the macro head_js_preload, the
# block extrahead of its layout.html), not through Sphinx's script_files: no Sphinx
# event sees them, so they are taken out of the written pages.
SCRIPT_TAG = re.compile(
    r'\s*<script defer src="[^"]*_static/scripts/fontawesome\.js[^"]*"></script>'
)
# pydata-sphinx-theme loads Sphinx's search on every page for its search-as-you-type,
# which is off unless the theme option search_as_you_type is set: then only search.html
# needs it.
SEARCH_TAGS = re.compile(
    r'\s*<script src="[^"]*(?:_static/searchtools\.js|_static/language_data\.js'
    r'|searchindex\.js)"></script>'
)
FONTS = "vendor/fontawesome/webfonts"
# .fa-bars:before,.fa-navicon:before{content:"\f0c9"}
ICON_RULE = re.compile(
    r'((?:\.fa-[\w-]+:{1,2}before,?)+)\{content:"\\?([0-9a-f]{1,5})"\}'
)
ICON_CLASS = re.compile(r"\bfa-([a-z0-9-]+)")
CODE_POINT = re.compile(r'"\\(f[0-9a-f]{3}|e[0-9a-f]{3})"')
FONT_FACE = re.compile(
    r"url\(\.\./vendor/fontawesome/webfonts/(fa-[\w-]+)\.(woff2|ttf)\)"
    r' format\("(woff2|truetype)"\)'
)

# myst-nb's script of a notebook's ipywidgets state (read only by the widget scripts)
WIDGET_STATE = "application/vnd.jupyter.widget-state+json"


def no_widget_state(app, pagename, templatename, context, doctree):
    """Leave the notebook's ipywidgets state out of the page's scripts when the book
    loads no widget script (``nb_ipywidgets_js`` empty): myst-nb adds it to
    ``script_files`` in its own ``html-page-context`` handler, which runs first."""
    scripts = context.get("script_files")
    if scripts and not getattr(app.config, "nb_ipywidgets_js", None):
        scripts[:] = [
            script
            for script in scripts
            if (getattr(script, "attributes", None) or {}).get("type") != WIDGET_STATE
        ]


def drop_script(outdir, search_everywhere=False):
    """Take the theme's Font Awesome script (and, unless search_everywhere, Sphinx's
    search scripts but on search.html) out of every written page; delete the script."""
    for page in glob.glob(os.path.join(outdir, "**", "*.html"), recursive=True):
        with open(page, encoding="utf-8") as f:
            html = f.read()
        lighter = SCRIPT_TAG.sub("", html)
        if not search_everywhere and os.path.basename(page) != "search.html":
            lighter = SEARCH_TAGS.sub("", lighter)
        if lighter != html:
            with open(page, "w", encoding="utf-8") as f:
                f.write(lighter)
    script = os.path.join(outdir, "_static", "scripts", "fontawesome.js")
    if os.path.exists(script):
        os.remove(script)


def used_code_points(outdir, css):
    """The code points of the icons the book can show."""
    classes = set()
    for pattern in ("**/*.html", "_static/**/*.js"):
        for path in glob.glob(os.path.join(outdir, pattern), recursive=True):
            with open(path, encoding="utf-8", errors="replace") as f:
                classes.update(ICON_CLASS.findall(f.read()))
    points = set()
    for selectors, point in ICON_RULE.findall(css):
        if any(name in classes for name in re.findall(r"\.fa-([\w-]+):", selectors)):
            points.add(int(point, 16))
    without_icon_rules = ICON_RULE.sub("", css)  # the theme's own uses of the font
    points.update(int(point, 16) for point in CODE_POINT.findall(without_icon_rules))
    return points


def subset_fonts(outdir):
    static = os.path.join(outdir, "_static")
    stylesheet = os.path.join(static, "styles", "pydata-sphinx-theme.css")
    if not os.path.exists(stylesheet):
        return
    with open(stylesheet, encoding="utf-8") as f:
        css = f.read()
    points = used_code_points(outdir, css)
    fonts = os.path.join(static, FONTS)
    for name in {m[0] for m in FONT_FACE.findall(css)}:
        source = os.path.join(fonts, f"{name}.ttf")  # not the .woff2: that needs brotli
        if not os.path.exists(source):
            continue
        font = TTFont(source)
        options = subset.Options()
        options.flavor = "woff"  # WOFF2 would need the brotli package
        options.layout_features = ["*"]
        subsetter = subset.Subsetter(options)
        subsetter.populate(unicodes=points & set(font.getBestCmap()))
        subsetter.subset(font)
        buffer = io.BytesIO()
        font.save(buffer)
        with open(os.path.join(fonts, f"{name}-book.woff"), "wb") as f:
            f.write(buffer.getvalue())
        for extension in ("woff2", "ttf"):
            if os.path.exists(os.path.join(fonts, f"{name}.{extension}")):
                os.remove(os.path.join(fonts, f"{name}.{extension}"))
    # The stylesheet's rule for each of Font Awesome's ~1800 icon classes: kept only for
    # the
    # icons the book shows (the others would have no glyph in the subset fonts anyway).
    css = ICON_RULE.sub(
        lambda m: m.group(0) if int(m.group(2), 16) in points else "", css
    )
    css = re.sub(
        r"src:url\(\.\./vendor/fontawesome/webfonts/(fa-[\w-]+)\.woff2\) "
        r"format\(\"woff2\"\),"
        r"url\(\.\./vendor/fontawesome/webfonts/\1\.ttf\) format\(\"truetype\"\)",
        r'src:url(../vendor/fontawesome/webfonts/\1-book.woff) format("woff")',
        css,
    )
    with open(stylesheet, "w", encoding="utf-8") as f:
        f.write(css)


DATA_IMAGE = re.compile(r"data:image/(png|jpeg|gif);base64,([A-Za-z0-9+/=]{2000,})")
# An alt text that says nothing (a stepped figure's, an animation's data-alt="auto"),
# inside HTML or inside the JSON string of a viewer's model (quotes escaped).
BLAND_ALT = re.compile(
    r'alt=(\\?")(precomputed figure)\1'
    r'|alt=(\\?")([^"\\]*)\3(\s+[^>]*?data-alt=\3auto\3)'
)


def cell_alt(cell):
    image = (cell.get("cell_metadata") or {}).get("mystnb", {}).get("image", {})
    return image.get("alt") if isinstance(image, dict) else None


def plain_folded_code(app, doctree, docname):
    """The code of cells tagged hide-input without syntax colours (see above)."""
    for cell in doctree.findall(nodes.container):
        if "tag_hide-input" in cell.get("classes", []):
            for block in cell.findall(nodes.literal_block):
                block["language"] = "none"


def replace_raw(node, text):
    node.replace_self(nodes.raw("", text, format="html"))


def describe_html_images(app, doctree, docname):
    """The cell's alt text for the bland alt texts of its HTML outputs (see above)."""
    for cell in doctree.findall(nodes.container):
        alt = cell.get("nb_element") == "cell_code" and cell_alt(cell)
        if not alt:
            continue
        text = html.escape(" ".join(alt.split()), quote=True)

        def described(m, text=text):
            if m.group(2):
                return f"alt={m.group(1)}{text}{m.group(1)}"
            return f"alt={m.group(3)}{text}{m.group(3)}{m.group(5)}"

        for raw in list(cell.findall(nodes.raw)):
            new = BLAND_ALT.sub(described, raw.astext())
            if new != raw.astext():
                replace_raw(raw, new)


def images_to_files(app, doctree, docname):
    """PNG data inside HTML outputs become files of _images/ (see above)."""
    if app.builder.format != "html":
        return
    folder = os.path.join(app.outdir, "_images")
    prefix = posixpath.relpath("_images", posixpath.dirname(docname) or ".")

    def to_file(match):
        data = base64.b64decode(match.group(2))
        name = f"{hashlib.sha256(data).hexdigest()}.{match.group(1)}"
        os.makedirs(folder, exist_ok=True)
        path = os.path.join(folder, name)
        if not os.path.exists(path):
            with open(path, "wb") as f:
                f.write(data)
        return f"{prefix}/{name}"

    for raw in list(doctree.findall(nodes.raw)):
        if "html" in raw.get("format", "") and "data:image/" in raw.astext():
            new = DATA_IMAGE.sub(to_file, raw.astext())
            if new != raw.astext():
                replace_raw(raw, new)


# screwkit's scripts inside HTML outputs, each as screwkit writes it: three.js
# (viewer.library_script), the viewers' script (viewer.viewer_script, which begins with
# header.js's comment), exercises.js
SCREWKIT_SCRIPT = re.compile(
    r"<script>\n((?:if\(!window\.THREE\)\{\(function\(\)\{var module="
    r"|/\* screwkit viewer: |// screwkit's self-checking answer boxes).*?)</script>\n?",
    re.S,
)
SCRIPTS = "_static/screwkit"


def scripts_to_files(app, doctree, docname):
    """screwkit's inline scripts become files of _static/screwkit/ (see above)."""
    if app.builder.format != "html":
        return
    folder = os.path.join(app.outdir, *SCRIPTS.split("/"))
    prefix = posixpath.relpath(SCRIPTS, posixpath.dirname(docname) or ".")
    seen = set()

    def to_file(match):
        body = match.group(1)
        digest = hashlib.sha256(body.encode("utf-8")).hexdigest()[:16]
        if digest in seen:
            return ""
        seen.add(digest)
        name = f"{digest}.js"
        os.makedirs(folder, exist_ok=True)
        path = os.path.join(folder, name)
        if not os.path.exists(path):
            with open(path, "w", encoding="utf-8") as f:
                f.write(body)
        return f'<script src="{prefix}/{name}"></script>\n'

    for raw in list(doctree.findall(nodes.raw)):
        if "html" in raw.get("format", "") and "<script>" in raw.astext():
            new = SCREWKIT_SCRIPT.sub(to_file, raw.astext())
            if new != raw.astext():
                replace_raw(raw, new)


MAX_MEAN_ERROR = 1.0  # of 255, per channel, over the figure


def smaller_png(original):
    """The PNG bytes `original` with a palette (see above), or None where that would
    change the figure (transparency, too large an error) or not shrink it."""
    import numpy as np
    from PIL import Image

    image = Image.open(io.BytesIO(original))
    if image.mode not in ("RGB", "RGBA"):
        return None
    pixels = np.asarray(image)
    if image.mode == "RGBA":
        if pixels[..., 3].min() < 255:
            return None  # transparency: kept as it is
        image = image.convert("RGB")
        pixels = pixels[..., :3]
    exact = image.getcolors(256) is not None
    palette = image.quantize(
        colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE
    )
    if not exact:
        error = np.abs(np.asarray(palette.convert("RGB"), dtype=float) - pixels).mean()
        if error > MAX_MEAN_ERROR:
            return None
    buffer = io.BytesIO()
    palette.save(buffer, format="png", optimize=True)
    smaller = buffer.getvalue()
    return smaller if len(smaller) < len(original) else None


def shrink_png(path):
    """Rewrite the PNG at `path` with a palette (see above); returns bytes saved."""
    with open(path, "rb") as f:
        original = f.read()
    smaller = smaller_png(original)
    if smaller is None:
        return 0
    with open(path, "wb") as f:
        f.write(smaller)
    return len(original) - len(smaller)


def shrink_images(outdir):
    return sum(
        shrink_png(path) for path in glob.glob(os.path.join(outdir, "_images", "*.png"))
    )


CODE_BLOCK = re.compile(r'<div class="highlight"><pre>.*?</pre>', re.S)


def plain_token_classes(pygments_css):
    """The token classes whose only rule, in every theme, is the code block's colour."""
    block = dict(
        re.findall(
            r'(html\[data-theme="\w+"\]) \.highlight \{[^}]*color: ([^;}\s]+)',
            pygments_css,
        )
    )
    rules = {}
    for theme, name, body in re.findall(
        r'(html\[data-theme="\w+"\]) \.highlight \.([\w-]+) \{([^}]*)\}', pygments_css
    ):
        rules.setdefault(name, {})[theme] = body.strip()
    return sorted(
        name
        for name, by_theme in rules.items()
        if block
        and by_theme.keys() == block.keys()
        and all(by_theme[t] == f"color: {block[t]}" for t in block)
    )


def unwrap_plain_tokens(outdir):
    """Take the spans of plain_token_classes out of every page; returns bytes saved."""
    css = os.path.join(outdir, "_static", "pygments.css")
    if not os.path.exists(css):
        return 0
    with open(css, encoding="utf-8") as f:
        classes = plain_token_classes(f.read())
    if not classes:
        return 0
    names = "|".join(classes)
    span = re.compile(rf'<span class="(?:{names})">([^<]*)</span>')
    saved = 0
    for path in glob.glob(os.path.join(outdir, "**", "*.html"), recursive=True):
        with open(path, encoding="utf-8") as f:
            text = f.read()
        lighter = CODE_BLOCK.sub(lambda block: span.sub(r"\1", block[0]), text)
        if len(lighter) < len(text):
            saved += len(text) - len(lighter)
            with open(path, "w", encoding="utf-8") as f:
                f.write(lighter)
    return saved


def lighten(app, exception):
    if exception is None and app.builder.format == "html":
        options = app.config.html_theme_options or {}
        drop_script(
            app.outdir, search_everywhere=bool(options.get("search_as_you_type"))
        )
        subset_fonts(app.outdir)
        shrink_images(app.outdir)
        unwrap_plain_tokens(app.outdir)


def setup(app):
    app.connect("doctree-resolved", plain_folded_code)
    app.connect("doctree-resolved", describe_html_images)
    app.connect("doctree-resolved", images_to_files)
    app.connect("doctree-resolved", scripts_to_files)
    app.connect("html-page-context", no_widget_state, priority=900)
    # after the theme's own build-finished handlers (priority 500), which write the
    # themed pygments.css that unwrap_plain_tokens reads
    app.connect("build-finished", lighten, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
