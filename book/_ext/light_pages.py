"""Light pages: what every page of the book loads, cut to what it uses.

pydata-sphinx-theme puts Font Awesome on every page twice: as web fonts with their CSS
classes (``fa-solid-900.woff2`` and friends, from its stylesheet), which draw every icon of
the book, and as a 1.49 MB script, ``fontawesome.js``, which redraws the same icons as SVG.
When the build finishes, the script's tag is taken out of every page and the script out of
the build: the icons stay, drawn by the fonts.

The fonts themselves are cut to the glyphs the book shows (fontTools, which Matplotlib
already installs): every ``fa-NAME`` class written in a page or a script of the build, and
every icon the theme's stylesheet draws by code point (admonitions, the back-to-top arrow,
...). The subsets are written as WOFF under new names and the stylesheet pointed at them;
the full fonts are removed. 274 kB of fonts become a few kB.
"""
import glob
import io
import os
import re

from fontTools import subset
from fontTools.ttLib import TTFont

SCRIPT_TAG = re.compile(r'\s*<script defer src="[^"]*_static/scripts/fontawesome\.js[^"]*"></script>')
FONTS = "vendor/fontawesome/webfonts"
# .fa-bars:before,.fa-navicon:before{content:"\f0c9"}
ICON_RULE = re.compile(r'((?:\.fa-[\w-]+:{1,2}before,?)+)\{content:"\\?([0-9a-f]{1,5})"\}')
ICON_CLASS = re.compile(r"\bfa-([a-z0-9-]+)")
CODE_POINT = re.compile(r'"\\(f[0-9a-f]{3}|e[0-9a-f]{3})"')
FONT_FACE = re.compile(r"url\(\.\./vendor/fontawesome/webfonts/(fa-[\w-]+)\.(woff2|ttf)\)"
                       r' format\("(woff2|truetype)"\)')


def drop_script(outdir):
    for page in glob.glob(os.path.join(outdir, "**", "*.html"), recursive=True):
        with open(page, encoding="utf-8") as f:
            html = f.read()
        lighter = SCRIPT_TAG.sub("", html)
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
    css = re.sub(r"src:url\(\.\./vendor/fontawesome/webfonts/(fa-[\w-]+)\.woff2\) format\(\"woff2\"\),"
                 r"url\(\.\./vendor/fontawesome/webfonts/\1\.ttf\) format\(\"truetype\"\)",
                 r'src:url(../vendor/fontawesome/webfonts/\1-book.woff) format("woff")', css)
    with open(stylesheet, "w", encoding="utf-8") as f:
        f.write(css)


def lighten(app, exception):
    if exception is None and app.builder.format == "html":
        drop_script(app.outdir)
        subset_fonts(app.outdir)


def setup(app):
    app.connect("build-finished", lighten)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
