"""Check the built book as a reader's browser sees it, with no network.

Serves the HTML build on 127.0.0.1 and loads every page of the build under book/ and
notebooks/ (by rule, not by list: a new chapter cannot slip by; and every file of
_toc.yml must be one of them) in headless Chromium (every host but 127.0.0.1
unresolvable). Fails unless:
  - math is typeset by the bundled MathJax (mjx-container elements, no MathJax errors)
    on every page that has math;
  - every chapter page (notebooks/) shows at least one figure whose file is in the
    build, and its first code cell installs screwkit where it is missing
    (Colab, a bare hub);
  - every image has an alt text that says what it shows (not its file's path, not a
    placeholder such as "precomputed figure");
  - no page links to a missing file or anchor of the book;
  - no page asked for anything off this machine (Chromium's net log lists every
    request);
  - every slider or drop-down of every in-page interactive figure (screwkit.viewer),
    when moved, changes the drawing, and no page logs a JavaScript error
    (Playwright driving the system Chromium); the redraw time of each move is printed
    (goal: under 50 ms);
  - no page holds a widget placeholder (a widget view with no fallback: blank in the
    book);
  - every trajectory viewer (screwkit.viewer.trajectory_viewer) plays: a click on its
    play button moves the arms (its time, readout and drawing change), and every
    chapter whose code calls it shows one;
  - every chapter says what the student will learn ("What you will learn") and ends with
    a "Summary";
  - no link (a launch button above all) points to a placeholder host such as
    hub.example.edu;
  - every file a page asks the server for exists (MathJax fonts and extensions
    included);
  - at 390, 800 and 1280 px (a phone, tapped; a tablet; a laptop): one search control in
    sight, and the table-of-contents and page-outline buttons open their sidebars
    (Escape closes them), with no tooltip left on screen after; a search finds pages;
  - at 1280 px, by rule over every element of the article: nothing wider than the
    content column, no code cell, output or table that scrolls sideways
    (the code font fits 88 characters), no figure image wider than the column; at every
    width the page itself never scrolls sideways and equations and tables stay in the
    column (in their own scrolling box);
  - at every width no formula (display or in the text) or table is clipped: one wider
    than its paragraph or the column scrolls in a box of its own (math_is_not_clipped);
  - axe-core (from the npm registry, fetched at check time) finds no critical or serious
    violation on any page, in the light and in the dark theme, with every answer box
    answered (its verdict's contrast checked);
  - every page weighs at most 2.5 MB cold (its HTML and all it loads, empty cache);
  - the whole book stays under 20 MB.
Keeps a screenshot of the first chapter in _build/.

Each check is a rule: a function named for what must hold, whose docstring says what it
checks, registered in ``RULES`` (run in its order, which is the report's). A "book"
rule runs once, a "page" rule on every page (the built HTML, the DOM after its scripts
ran, the requests it made). The JavaScript the rules run in the page is in
``.ci/site_check_js/``; every browser starts through ``.ci/harness.py``.

Usage: python .ci/site_check.py _build/html
"""

import functools
import http.server
import itertools
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
from collections.abc import Callable
from dataclasses import dataclass, field
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urljoin, urlsplit

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:  # loaded from elsewhere (the tests of its rules)
    sys.path.insert(0, str(HERE))
import harness  # noqa: E402 (.ci/harness.py: the fenced system Chromium)

SCRIPTS = HERE / "site_check_js"


def script(name):
    """The JavaScript function ``site_check_js/NAME.js`` (its text), for
    ``page.evaluate``."""
    return (SCRIPTS / f"{name}.js").read_text(encoding="utf-8")


class PageParser(HTMLParser):
    """Collects ids, links, images and MathJax elements of one HTML document."""

    def __init__(self):
        super().__init__()
        self.ids, self.links, self.images, self.alts = set(), [], [], []
        self.math_containers = self.math_errors = self.math_sources = 0

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if "id" in attrs:
            self.ids.add(attrs["id"])
        if tag == "a" and attrs.get("name"):
            self.ids.add(attrs["name"])
        if tag == "a" and attrs.get("href"):
            self.links.append(attrs["href"])
        if tag == "img" and attrs.get("src"):
            self.images.append(attrs["src"])
            self.alts.append((attrs["src"], attrs.get("alt")))
        if tag == "mjx-container":
            self.math_containers += 1
        if tag == "mjx-merror":
            self.math_errors += 1
        classes = (attrs.get("class") or "").split()
        if tag in ("span", "div") and "math" in classes:
            self.math_sources += 1


def parse(html):
    parser = PageParser()
    parser.feed(html)
    return parser


def serve(root):
    handler = functools.partial(QuietHandler, directory=root)
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    """Serves the book silently, remembering every request it could not answer."""

    missing = set()

    def log_message(self, *args):
        pass

    def send_error(self, code, message=None, explain=None):
        # the book declares its icon (_config.yml: _static/favicon.svg), and a 404 on
        # that counts; a page without one (the checks' own test pages) makes the browser
        # ask for /favicon.ico, which is no error of the page
        if code >= 400 and not self.path.endswith("/favicon.ico"):
            QuietHandler.missing.add(f"{code} {self.path}")
        super().send_error(code, message, explain)


def dump_dom(url, profile, *extra):
    """Chromium (headless, fenced) on ``url`` without Playwright; its stdout."""
    command = harness.command(
        f"--user-data-dir={profile}", "--virtual-time-budget=20000", *extra, url
    )
    result = subprocess.run(command, capture_output=True, text=True, timeout=180)
    if result.returncode != 0:
        raise RuntimeError(f"chromium failed on {url}: {result.stderr[-2000:]}")
    return result.stdout


def toc_pages(root):
    pages = []
    for folder in ("book", "notebooks"):
        directory = os.path.join(root, folder)
        if os.path.isdir(directory):
            pages += sorted(
                os.path.join(folder, f)
                for f in os.listdir(directory)
                if f.endswith(".html")
            )
    return pages


def outside_requests(netlog_path, origin):
    """URLs off this machine that the page itself asked for, from Chromium's net log.

    Requests the page makes carry the page's origin as initiator; the browser's own
    background requests (update checks and the like, unresolvable here) carry none.
    """
    with open(netlog_path) as f:
        text = f.read()
    try:
        log = json.loads(text)
    except json.JSONDecodeError:  # Chromium may leave the closing brackets off
        log = json.loads(text.rstrip().rstrip(",") + "]}")
    start_job = log["constants"]["logEventTypes"]["URL_REQUEST_START_JOB"]
    urls = set()
    for event in log.get("events", []):
        params = event.get("params") or {}
        if event.get("type") != start_job or params.get("initiator") != origin.rstrip(
            "/"
        ):
            continue
        if urlsplit(params.get("url", "")).hostname not in ("127.0.0.1", "localhost"):
            urls.add(params["url"])
    return urls


@dataclass
class Site:
    """What every rule may read of the book being checked."""

    root: str  # the HTML build, absolute
    origin: str  # where it is served: http://127.0.0.1:PORT/
    pages: list  # every page under book/ and notebooks/ (paths from root)
    tmp: str  # a scratch folder (Chromium's profile and net log)
    anchors: dict = field(default_factory=dict)  # file -> its ids, read once


@dataclass
class Page:
    """One page as the page rules see it."""

    name: str  # its path from the build's root (notebooks/puma_fk.html)
    html: str  # as built
    static: PageParser  # of the built HTML
    dom: PageParser  # of the DOM once its scripts ran (Chromium's --dump-dom)
    leaks: set  # URLs off this machine that the page asked for
    figures: list  # the sources of its images of _images/ (cell outputs)


def built_page(name, html, figures=()):
    """The page ``name`` as built, without a browser (its DOM is its HTML, it asked for
    nothing): what the rules that read only the build see."""
    static = parse(html)
    return Page(name, html, static, static, set(), list(figures))


def load_page(site, name):
    """The page ``name`` built, and loaded in a fenced Chromium with its net log."""
    with open(os.path.join(site.root, name), encoding="utf-8") as f:
        html = f.read()
    netlog = os.path.join(site.tmp, "netlog.json")
    dom = parse(
        dump_dom(
            site.origin + name,
            os.path.join(site.tmp, "profile"),
            "--dump-dom",
            f"--log-net-log={netlog}",
        )
    )
    return Page(
        name=name,
        html=html,
        static=parse(html),
        dom=dom,
        leaks=outside_requests(netlog, site.origin),
        figures=[src for src in dom.images if "_images/" in src],
    )


BOOK_LIMIT_MB = 20
REDRAW_GOAL_MS = 50
# What a chapter must show, as a heading or an admonition's title
# (the text of one element).
CHAPTER_SHAPE = {
    "What you will learn": re.compile(r">\s*What you will learn\s*<"),
    "Summary": re.compile(r"<h[2-6][^>]*>\s*Summary\s*<"),
}
PLACEHOLDER_HOSTS = ("example.",)  # example.com, hub.example.edu, ...


# ---- Rules on the book as built: its files, links, sources and what the pages say.


def toc_is_built(site, toc="_toc.yml"):
    """Every file of the table of contents is a page of the build
    (none left out of the checks)."""
    toc = os.path.join(os.path.dirname(os.path.dirname(site.root)), toc)
    if not os.path.exists(toc):
        return []
    with open(toc, encoding="utf-8") as f:
        files = re.findall(r"^\s*-?\s*(?:file|root):\s*(\S+)", f.read(), re.M)
    return [
        f"{name}: in _toc.yml but not built ({name}.html missing)"
        for name in files
        if not os.path.exists(os.path.join(site.root, name + ".html"))
    ]


def links_resolve(site, page):
    """Every link and image of the page points to a file of the build, and every
    link's anchor to an id of its page."""
    problems = []
    base = "/" + page.name
    for href in page.static.links + page.static.images:
        parts = urlsplit(href)
        if parts.scheme or href.startswith("//") or href.startswith("mailto:"):
            continue
        target = urlsplit(urljoin(base, href))
        path = unquote(target.path).lstrip("/") or "index.html"
        file = os.path.join(site.root, path)
        if os.path.isdir(file):
            file = os.path.join(file, "index.html")
        if not os.path.isfile(file):
            problems.append(f"{page.name}: broken link {href}")
            continue
        if target.fragment and file.endswith(".html"):
            if file not in site.anchors:
                with open(file, encoding="utf-8") as f:
                    site.anchors[file] = parse(f.read()).ids
            if unquote(target.fragment) not in site.anchors[file]:
                problems.append(f"{page.name}: link {href} points to a missing anchor")
    return problems


def no_placeholder_links(site, page):
    """Links (launch buttons among them) must not point to a placeholder such as
    hub.example.edu."""
    problems = []
    for href in page.static.links:
        host = urlsplit(href).hostname or ""
        if any(marker in host for marker in PLACEHOLDER_HOSTS):
            problems.append(
                f"{page.name}: a link to the placeholder {host}: {href[:120]}"
            )
    return problems


# An alt text that names a file, or says nothing of what the image shows.
PATH_LIKE = re.compile(
    r"(^|/)[\w.-]+\.(png|jpe?g|gif|svg|webp)$|^_images/|^data:", re.I
)
PLACEHOLDER_ALTS = {"", "image", "figure", "precomputed figure", "png", "output"}


def alt_texts_say_what_they_show(site, page):
    """Every image of a page says what it shows: an alt text that is not its file's
    path, nor a placeholder (decorations, such as a launch button's logo, name what they
    are)."""
    problems = []
    for src, alt in page.static.alts:
        text = (alt or "").strip()
        if alt is None or text.lower() in PLACEHOLDER_ALTS or PATH_LIKE.search(text):
            problems.append(
                f"{page.name}: image {src[:60]} has the alt text {alt!r}, "
                "not what it shows"
            )
    return problems


def chapter_code(site, page):
    """The code cells of a chapter page (from the build's .ipynb source), or None."""
    source = os.path.join(
        site.root, "_sources", os.path.splitext(page.name)[0] + ".ipynb"
    )
    if not page.name.startswith("notebooks/") or not os.path.exists(source):
        return None
    with open(source, encoding="utf-8") as f:
        cells = json.load(f)["cells"]
    return ["".join(c["source"]) for c in cells if c["cell_type"] == "code"]


# The first code cell of every chapter installs screwkit where it is missing
# (Colab, a bare JupyterHub), as the book's first chapter does.
INSTALLS_SCREWKIT = re.compile(r'find_spec\(\s*"screwkit"\s*\)[\s\S]*pip install')


def first_cell_installs_screwkit(site, page):
    """A chapter's first code cell installs screwkit where it is missing."""
    if not page.name.startswith("notebooks/"):
        return []
    cells = chapter_code(site, page)
    if cells is None:
        return [f"{page.name}: no notebook source in the build (_sources)"]
    if not cells or not INSTALLS_SCREWKIT.search(cells[0]):
        return [
            f"{page.name}: the first code cell does not install screwkit where it is "
            "missing (copy the first code cell of another chapter)"
        ]
    return []


def chapter_has_its_shape(site, page):
    """A chapter page must say what the student will learn and end with a summary."""
    if not page.name.startswith("notebooks/"):
        return []
    return [
        f'{page.name}: a chapter without "{words}"'
        for words, pattern in CHAPTER_SHAPE.items()
        if not pattern.search(page.html)
    ]


def nothing_leaves_the_machine(site, page):
    """The page asked for nothing off this machine (Chromium's net log lists every
    request)."""
    return [
        f"{page.name}: request left the machine: {url}" for url in sorted(page.leaks)
    ]


def math_is_typeset(site, page):
    """A page with math has it typeset by the bundled MathJax, without MathJax
    errors."""
    problems = []
    if page.static.math_sources and not page.dom.math_containers:
        problems.append(f"{page.name}: has math but MathJax typeset none of it")
    if page.dom.math_errors:
        problems.append(f"{page.name}: MathJax reported {page.dom.math_errors} errors")
    return problems


def chapter_shows_a_figure(site, page):
    """Every chapter page shows at least one figure whose file is in the build."""
    if page.name.startswith("notebooks/") and not page.figures:
        return [f"{page.name}: a chapter page without a figure (no cell output image)"]
    return []


# The parallel mechanisms of the catalogue (screwkit.robots): a chapter that analyses
# them with sk.mobility must draw each one.
MECHANISM_BUILDER = re.compile(r"robots\.(pm_\w+|planar_3rrr|spherical_3rrr)\b")


def mechanisms_are_drawn(site, page):
    """A chapter of the mobility kind (its code calls sk.mobility) must show at least as
    many figures as the catalogue mechanisms its code builds
    (read from the page's .ipynb source)."""
    cells = chapter_code(site, page)
    if cells is None:
        return []
    code = "\n".join(cells)
    if "sk.mobility(" not in code:
        return []
    mechanisms = sorted(set(MECHANISM_BUILDER.findall(code)))
    if len(page.figures) < len(mechanisms):
        return [
            f"{page.name}: {len(mechanisms)} mechanisms analysed "
            f"({', '.join(mechanisms)}) but only {len(page.figures)} figures: "
            "draw each one (sk.plotting.draw_mechanism)"
        ]
    return []


def first_chapter_screenshot(site):
    """Keeps a screenshot of the first chapter in _build/ for review (fails only if
    Chromium cannot draw it)."""
    shot_page = next(
        (p for p in site.pages if p.startswith("notebooks/")), site.pages[0]
    )
    shot = os.path.join(os.path.dirname(site.root), "screenshot.png")
    dump_dom(
        site.origin + shot_page,
        os.path.join(site.tmp, "profile"),
        f"--screenshot={shot}",
        "--window-size=1280,1600",
        "--hide-scrollbars",
    )
    print(f"screenshot of {shot_page}: {shot}")
    return []


# ---- Rules on the in-page figures: every control of every figure, moved.

MOVE_CONTROL = script("move_control")


def interactive_figures_respond(site):
    """Every slider or drop-down of every in-page figure (screwkit.viewer), when moved,
    changes the drawing; no page logs a JavaScript error or holds a widget placeholder
    (blank in the book). Prints each page's redraw times (goal: under 50 ms)."""
    problems = []
    with harness.launch() as chromium:
        for page_name in site.pages:
            page = chromium.new_page()
            errors = harness.collect_errors(
                page, ignore=lambda url: url.endswith("/favicon.ico")
            )
            page.goto(site.origin + page_name, wait_until="load")
            problems += no_widget_placeholders(page, page_name)
            found, times, figures = figures_respond(page, page_name)
            problems += found
            problems += [f"{page_name}: JavaScript error: {e}" for e in errors]
            if times:
                print(
                    f"{page_name}: {len(figures)} interactive figures, "
                    f"{len(times)} controls moved, "
                    f"redraw median {sorted(times)[len(times) // 2]:.1f} ms, "
                    f"max {max(times):.1f} ms (goal {REDRAW_GOAL_MS} ms)"
                )
            page.close()
    return problems


def no_widget_placeholders(page, page_name):
    """No widget view without a fallback (blank in the book)."""
    placeholders = page.locator(
        "script[type='application/vnd.jupyter.widget-view+json']"
    ).count()
    if placeholders:
        return [f"{page_name}: {placeholders} widget placeholders (blank in the book)"]
    return []


def figures_respond(page, page_name):
    """Every figure was drawn, and each of its controls, moved, changes the drawing.

    Returns the problems, the redraw times (ms) and the figures' ids."""
    problems = []
    figures = page.eval_on_selector_all("div.screwkit-viewer", "d => d.map(e => e.id)")
    times = []
    for figure in figures:
        if not page.evaluate(
            "id => document.getElementById(id).dataset.mounted", figure
        ):
            problems.append(f"{page_name}: figure {figure} was never drawn")
            continue
        count = page.locator(
            f"[id='{figure}'] input[type=range], [id='{figure}'] select"
        ).count()
        for k in range(count):
            changed, elapsed, label = page.evaluate(MOVE_CONTROL, [figure, k])
            times.append(elapsed)
            if not changed:
                problems.append(
                    f"{page_name}: moving {label} of {figure} changed nothing"
                )
    return problems, times, figures


# ---- Rule on the trajectory viewers (screwkit.viewer.trajectory_viewer): play moves
# the arms.

TRAJECTORY_STATE = script("trajectory_state")
PAUSE_ON_CLICK = script("pause_on_click")
PLAYED_S = 0.3  # the animation time play must reach, from where it started (s)


def trajectories_play(site):
    """On every page with a trajectory viewer, and every chapter whose code calls
    ``trajectory_viewer(``: each viewer has a play button, and a click on it moves the
    arms: its time (the root's data-time) advances by PLAYED_S, its readout and its
    drawing change, and a second click pauses it. Prints what each viewer played."""
    with harness.launch() as chromium:
        return trajectories_play_in(chromium, site)


def trajectories_play_in(chromium, site):
    """trajectories_play in a running browser (Playwright's): the problems."""
    problems = []
    for name in site.pages:
        with open(os.path.join(site.root, name), encoding="utf-8") as f:
            built = '"kind":"trajectory"' in f.read()
        code = chapter_code(site, built_page(name, "")) or []
        called = any("trajectory_viewer(" in cell for cell in code)
        if not (built or called):
            continue
        page = chromium.new_page()
        errors = harness.collect_errors(
            page, ignore=lambda url: url.endswith("/favicon.ico")
        )
        page.goto(site.origin + name, wait_until="load")
        players = page.eval_on_selector_all(
            "div.screwkit-viewer:has(button.screwkit-play)", "d => d.map(e => e.id)"
        )
        if called and not players:
            problems.append(
                f"{name}: its code calls trajectory_viewer but the page has no "
                "player (a viewer with a play button)"
            )
        for figure in players:
            problems += trajectory_plays(page, name, figure)
        problems += [f"{name}: JavaScript error: {e}" for e in errors]
        page.close()
    return problems


def trajectory_plays(page, page_name, figure):
    """A click on the viewer's play button moves its arms; another pauses them.

    The second click is made inside the page (PAUSE_ON_CLICK), so a busy machine that
    lets a short trajectory reach its end before the click cannot make it a play."""
    button = page.locator(f"[id='{figure}'] button.screwkit-play")
    button.scroll_into_view_if_needed()
    start, _, caption, drawing = page.evaluate(TRAJECTORY_STATE, figure)
    button.click()
    from playwright.sync_api import TimeoutError as Timeout

    try:
        page.wait_for_function(
            f"() => +document.getElementById('{figure}').dataset.time >= "
            f"{start + PLAYED_S}",
            timeout=10000,
        )
    except Timeout:  # the time did not advance
        time, *_ = page.evaluate(TRAJECTORY_STATE, figure)
        return [
            f"{page_name}: play on {figure} did not move it: its time went from "
            f"{start:g} s to {time:g} s in 10 s"
        ]
    time, _, text, pixels = page.evaluate(TRAJECTORY_STATE, figure)
    playing = page.evaluate(PAUSE_ON_CLICK, figure)
    problems = [
        f"{page_name}: play on {figure} {what}"
        for what, wrong in (
            ("left its readout as it was", text == caption),
            ("left its drawing as it was", pixels == drawing),
            ("did not pause on a second click", playing),
        )
        if wrong
    ]
    print(f"{page_name}: {figure} played from {start:g} s to {time:g} s")
    return problems


# ---- Rules on the book as a reader sees it: navigation, weight, accessibility and
# layout, at the widths of a phone (390 px), a tablet (800 px) and a laptop (1280 px),
# on every page.

WIDTHS = (390, 800, 1280)
PAGE_LIMIT_MB = 2.5  # a page, cold (empty cache): the HTML and everything it loads
AXE_VERSION = "4.14.1"  # axe-core from the npm registry, fetched at check time
AXE_FAILING = ("critical", "serious")
VISIBLE = script("visible")
DIALOG_OPEN = script("dialog_open")
TOOLTIPS = script("tooltips")
MEASURE_LAYOUT = script("measure_layout")
AXE_RUN = script("axe_run")
MATHJAX_DONE = script("mathjax_done")
CLIPPED_MATH = script("clipped_math")
DARK_THEME = script("dark_theme")
TRANSITIONS_DONE = script("transitions_done")
ANSWER_BOXES = script("answer_boxes_answered")


def becomes(page, script, arg, test, seconds=5):
    """Whether ``script`` (a function of ``arg``, run in the page) gives a value that
    passes ``test`` (JavaScript after the value, such as ``"=== 0"``) within
    ``seconds``: polled at every animation frame, so a sidebar's transition or a busy
    machine is waited for, not guessed by a fixed pause."""
    from playwright.sync_api import TimeoutError as Timeout

    try:
        page.wait_for_function(
            f"(arg) => ({script})(arg) {test}", arg=arg, timeout=seconds * 1000
        )
    except Timeout:
        return False
    return True


def navigation_works(page, page_name, width):
    """One search control in sight; the table-of-contents and page-outline buttons open
    their sidebars (Escape closes them), with no tooltip left on screen after."""
    problems = []
    where = f"{page_name} at {width} px"
    press = (
        (lambda locator: locator.tap())
        if width < 600
        else (lambda locator: locator.click())
    )
    searches = page.evaluate(VISIBLE, ".search-button, .search-button-field")
    if searches != 1:
        problems.append(f"{where}: {searches} search controls in sight (want one)")
    sidebars = (
        ("primary", "#pst-primary-sidebar .bd-docs-nav a", 992),
        (
            "secondary",
            "#pst-secondary-sidebar .page-toc a, #pst-secondary-sidebar nav a",
            1200,
        ),
    )
    for side, links, wide in sidebars:
        if page.locator(f"#pst-{side}-sidebar").count() == 0 or (
            side == "secondary" and page.locator(links).count() == 0
        ):
            continue  # a page without an outline has no outline button
        buttons = [b for b in page.locator(f".{side}-toggle").all() if b.is_visible()]
        in_sight = page.evaluate(VISIBLE, links)
        if width >= wide:
            if not in_sight:
                problems.append(f"{where}: the {side} sidebar is not in sight")
            if side == "primary" and buttons:  # its button closes and reopens it
                press(buttons[0])
                closed = becomes(page, VISIBLE, links, "=== 0")
                press(buttons[0])
                if not closed or not becomes(page, VISIBLE, links, "> 0"):
                    problems.append(
                        f"{where}: the {side} sidebar button does not close and "
                        "reopen the sidebar"
                    )
            continue
        if len(buttons) != 1:
            problems.append(
                f"{where}: {len(buttons)} {side} sidebar buttons in sight (want one)"
            )
            continue
        press(buttons[0])
        dialog = f"pst-{side}-sidebar-modal"
        if not becomes(page, DIALOG_OPEN, dialog, "=== true") or not becomes(
            page, VISIBLE, f"#{dialog} a", "> 0"
        ):
            problems.append(
                f"{where}: the {side} sidebar button does not open the sidebar"
            )
        page.keyboard.press("Escape")
        if not becomes(page, DIALOG_OPEN, dialog, "=== false"):
            problems.append(f"{where}: Escape does not close the {side} sidebar")
    if width >= 600:  # the mouse leaves the buttons, as a reader's does
        page.mouse.move(width // 2, 600)
    page.wait_for_timeout(700)  # longer than the tooltips' show delay
    if not becomes(page, TOOLTIPS, None, "=== 0"):
        problems.append(
            f"{where}: a tooltip stays on screen after the buttons were used"
        )
    return problems


def layout_fits(page, page_name, width):
    """At 1280 px nothing wider than the column, and no code cell, output or table that
    scrolls sideways (an equation too long for any column, a code block of the prose, or
    a benchmark table in 12 px text, may: they are listed); at every width the page
    itself never scrolls sideways, and equations and tables stay in the column
    (scrolling inside their own box)."""
    layout = page.evaluate(MEASURE_LAYOUT)
    where, column = f"{page_name} at {width} px", layout["column"]
    problems, counts, notes = [], {}, []
    if layout["page"]:
        problems.append(f"{where}: the page scrolls sideways")
    for kind, name, w in layout["out"]:
        if width >= 1280 or kind in ("equation", "table"):
            problems.append(
                f"{where}: {name} is {w} px wide, wider than the column ({column} px)"
            )
        else:
            key = "wider than the column: " + kind
            counts[key] = counts.get(key, 0) + 1
    for kind, name, full, shown in layout["scrolling"]:
        counts[kind] = counts.get(kind, 0) + 1
        if width >= 1280 and kind in ("equation", "code block", "wide table"):
            notes.append(
                f"{where}: {kind} {name} scrolls sideways ({full} px in {shown} px)"
            )
        elif width >= 1280:
            problems.append(
                f"{where}: {kind} {name} scrolls sideways ({full} px in {shown} px)"
            )
    if width >= 1280:
        problems += [
            f"{where}: figure {src[:80]} is {w:.0f} px wide, the column {column} px"
            for src, w in layout["images"]
        ]
    return problems, counts, notes


def math_is_not_clipped(page, page_name, width):
    """No formula (display or in the text) or table runs out of its paragraph or the
    column, or is cut off, without a box around it that scrolls sideways (on
    a phone, long inline formulas ran out of their paragraph with no way to scroll)."""
    page.evaluate(MATHJAX_DONE)
    clipped = page.evaluate(CLIPPED_MATH)
    return [
        f"{page_name} at {width} px: {kind} {text!r} is {w} px wide in {room} px, "
        "clipped (no box around it scrolls)"
        for kind, text, w, room in clipped
    ]


def axe_in_both_themes(page, page_name, axe):
    """axe-core (no_serious_accessibility_violations) in the light theme, then in the
    dark one, with every answer box answered so that its verdict is checked too."""
    page.evaluate(MATHJAX_DONE)
    page.evaluate(ANSWER_BOXES)
    problems, counts = no_serious_accessibility_violations(page, page_name, axe)
    if page.evaluate(DARK_THEME, "dark") != "dark":
        return problems + [f"{page_name}: the dark theme cannot be set"], counts, {}
    page.evaluate(TRANSITIONS_DONE)  # the theme's colours transition
    dark, dark_counts = no_serious_accessibility_violations(page, page_name, axe)
    page.evaluate(DARK_THEME, "light")  # the next page starts light
    return problems + [f"{p} (dark theme)" for p in dark], counts, dark_counts


def axe_source(cache):
    """axe-core's browser build, installed from the npm registry into `cache` once."""
    script = os.path.join(cache, "node_modules", "axe-core", "axe.min.js")
    if not os.path.exists(script):
        npm = shutil.which("npm")
        if npm is None:
            sys.exit(
                "site check: npm is needed to fetch axe-core (apt-get install npm)"
            )
        subprocess.run(
            [
                npm,
                "install",
                "--no-save",
                "--no-audit",
                "--no-fund",
                "--prefix",
                cache,
                f"axe-core@{AXE_VERSION}",
            ],
            check=True,
            capture_output=True,
            timeout=300,
        )
    return script


def no_serious_accessibility_violations(page, page_name, axe):
    """axe-core finds no critical or serious violation on the page."""
    page.add_script_tag(path=axe)
    violations = page.evaluate(AXE_RUN)
    counts = {}
    for _rule, impact, nodes, _ in violations:
        counts[impact] = counts.get(impact, 0) + nodes
    problems = [
        f"{page_name}: axe {impact} {rule} on {nodes} elements ({where})"
        for rule, impact, nodes, where in violations
        if impact in AXE_FAILING
    ]
    return problems, counts


def search_finds_pages(chromium, url, word="screw"):
    """The search button opens the search box, and a search finds pages
    (on search.html)."""
    page = chromium.new_page(viewport={"width": 1280, "height": 900})
    page.goto(url, wait_until="load")
    page.locator(".bd-header-article .search-button").click()
    box = page.locator("#pst-search-dialog input[name=q]")
    box.fill(word)
    box.press("Enter")
    page.wait_for_load_state("load")
    try:
        page.wait_for_selector("#search-results li, ul.search li", timeout=15000)
        found = page.locator("#search-results li, ul.search li").count()
    except Exception:  # Playwright's TimeoutError: no result came
        found = 0
    page.close()
    return [] if found else [f"searching for {word!r} from {url} found nothing"]


def settle(page, pending, quiet_ms=700, limit_ms=30000):
    """Wait until no request has been pending or started for `quiet_ms` (at most
    `limit_ms`). `pending` is a list of [started, finished] counts kept by the page's
    request events."""
    waited, last, still = 0, None, 0
    while waited < limit_ms:
        state = tuple(pending)
        still = still + 100 if state == last and state[0] == state[1] else 0
        if still >= quiet_ms:
            return
        last = state
        page.wait_for_timeout(100)
        waited += 100


def cold_weight(chromium, url):
    """Bytes a first visit downloads (empty cache): the page and all it loads, read to
    its end, once its math is typeset and nothing more is asked for."""
    context = chromium.new_context(viewport={"width": 1280, "height": 900})
    page = context.new_page()
    requests, pending = [], [0, 0]

    def started(_):
        pending[0] += 1

    def ended(request, done=True):
        pending[1] += 1
        if done:
            requests.append(request)

    page.on("request", started)
    page.on("requestfinished", ended)
    page.on("requestfailed", lambda request: ended(request, done=False))
    page.goto(url, wait_until="networkidle")
    page.evaluate(MATHJAX_DONE)
    page.evaluate("window.scrollTo(0, document.body.scrollHeight)")
    settle(page, pending)
    size = sum(request.sizes()["responseBodySize"] for request in list(requests))
    context.close()
    return size


def reader_sees_a_working_book(site):
    """Every page at every width: navigation, layout and no clipped math (see
    navigation_works, layout_fits, math_is_not_clipped), and at 1280 px axe-core in both
    themes; every page's cold weight at most
    PAGE_LIMIT_MB; a search finds pages. Prints the boxes that scroll sideways, the axe
    counts and each page's weight."""
    cache = os.path.join(os.path.dirname(site.root), ".site-check")
    axe = axe_source(cache)
    problems, notes, layout_counts, axe_counts, weights = [], [], {}, {}, {}
    clipped, dark_counts = {}, {}
    with harness.launch() as chromium:
        for width in WIDTHS:
            phone = width < 600
            context = chromium.new_context(
                viewport={"width": width, "height": 900},
                has_touch=phone,
                is_mobile=phone,
            )
            for page_name in site.pages:
                page = context.new_page()
                page.goto(site.origin + page_name, wait_until="load")
                page.evaluate(MATHJAX_DONE)  # MathJax typesets after load
                found, counts, noted = layout_fits(page, page_name, width)
                problems += found
                notes += noted
                for kind, count in counts.items():
                    layout_counts[(width, kind)] = (
                        layout_counts.get((width, kind), 0) + count
                    )
                found = math_is_not_clipped(page, page_name, width)
                problems += found
                clipped[width] = clipped.get(width, 0) + len(found)
                problems += navigation_works(page, page_name, width)
                if width == 1280:
                    page.reload(wait_until="load")
                    page.evaluate(MATHJAX_DONE)
                    found, counts, dark = axe_in_both_themes(page, page_name, axe)
                    problems += found
                    axe_counts[page_name], dark_counts[page_name] = counts, dark
                page.close()
            context.close()
        for page_name in site.pages:
            weights[page_name] = cold_weight(chromium, site.origin + page_name)
        problems += search_finds_pages(chromium, site.origin + site.pages[0])
    for width in WIDTHS:
        kinds = {
            kind: n for (w, kind), n in sorted(layout_counts.items()) if w == width
        }
        print(f"at {width} px, boxes that scroll sideways (by kind): {kinds or 'none'}")
        print(f"at {width} px, clipped formulas and tables: {clipped.get(width, 0)}")
    for note in notes:
        print("  " + note)
    print(
        "axe-core",
        AXE_VERSION,
        "violations (elements) by impact, and cold page weight:",
    )
    for page_name in site.pages:
        counts = ", ".join(
            f"{k} {v}" for k, v in sorted(axe_counts.get(page_name, {}).items())
        )
        dark = ", ".join(
            f"{k} {v}" for k, v in sorted(dark_counts.get(page_name, {}).items())
        )
        print(
            f"  {page_name}: {weights[page_name] / 1e6:.2f} MB; axe: {counts or 'none'}"
            f"; dark theme: {dark or 'none'}"
        )
        if weights[page_name] > PAGE_LIMIT_MB * 1e6:
            problems.append(
                f"{page_name}: {weights[page_name] / 1e6:.2f} MB cold, over the "
                f"{PAGE_LIMIT_MB} MB limit"
            )
    return problems


# ---- Rules on the whole, once every page was loaded.


def server_had_every_file(site):
    """Every file a page asked the server for exists (MathJax fonts and extensions
    included)."""
    return [
        f"the server had no answer for {request}"
        for request in sorted(QuietHandler.missing)
    ]


def book_within_its_limit(site):
    """The whole book stays under BOOK_LIMIT_MB; prints its size."""
    size = sum(
        os.path.getsize(os.path.join(d, f))
        for d, _, fs in os.walk(site.root)
        for f in fs
    )
    print(f"book size: {size / 1e6:.1f} MB (limit {BOOK_LIMIT_MB} MB)")
    if size > BOOK_LIMIT_MB * 1e6:
        return [f"the book is {size / 1e6:.1f} MB, over the {BOOK_LIMIT_MB} MB limit"]
    return []


@dataclass(frozen=True)
class Rule:
    """A check: ``scope`` "book" runs ``check(site)`` once, "page" runs
    ``check(site, page)`` on every page; each returns a list of problems (str)."""

    scope: str
    check: Callable


#: Every rule of the site check, in the order they run and report.
RULES = [
    Rule("book", toc_is_built),
    Rule("page", links_resolve),
    Rule("page", no_placeholder_links),
    Rule("page", alt_texts_say_what_they_show),
    Rule("page", first_cell_installs_screwkit),
    Rule("page", chapter_has_its_shape),
    Rule("page", nothing_leaves_the_machine),
    Rule("page", math_is_typeset),
    Rule("page", chapter_shows_a_figure),
    Rule("page", mechanisms_are_drawn),
    Rule("book", first_chapter_screenshot),
    Rule("book", interactive_figures_respond),
    Rule("book", trajectories_play),
    Rule("book", reader_sees_a_working_book),
    Rule("book", server_had_every_file),
    Rule("book", book_within_its_limit),
]


def run(site, rules):
    """Every rule in order (a run of page rules on each page in turn); the problems."""
    problems = []
    for scope, group in itertools.groupby(rules, key=lambda rule: rule.scope):
        group = list(group)
        if scope == "book":
            for rule in group:
                problems += rule.check(site)
            continue
        for name in site.pages:
            page = load_page(site, name)
            for rule in group:
                problems += rule.check(site, page)
            print(
                f"{name}: {page.dom.math_containers} math, {len(page.figures)} "
                f"figures, {len(page.static.links)} links, "
                f"{len(page.leaks)} outside requests"
            )
    return problems


def main(root):
    root = os.path.abspath(root)
    pages = toc_pages(root)
    if not pages:
        sys.exit(
            f"site check: no pages under {root}/book or {root}/notebooks; "
            "build the book first"
        )
    if harness.CHROMIUM is None:
        sys.exit("site check: no Chromium found (apt-get install chromium)")
    server = serve(root)
    origin = f"http://127.0.0.1:{server.server_address[1]}/"
    with tempfile.TemporaryDirectory() as tmp:
        problems = run(Site(root=root, origin=origin, pages=pages, tmp=tmp), RULES)
    server.shutdown()
    if problems:
        print("\nsite check FAILED:")
        for problem in problems:
            print("  - " + problem)
        sys.exit(1)
    print(f"site check passed: {len(pages)} pages")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "_build/html")
