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
  - axe-core (from the npm registry, fetched at check time) finds no critical or serious
    violation on any page;
  - every page weighs at most 2.5 MB cold (its HTML and all it loads, empty cache);
  - the whole book stays under 20 MB.
Keeps a screenshot of the first chapter in _build/.

Usage: python .ci/site_check.py _build/html
"""

import functools
import http.server
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
from html.parser import HTMLParser
from urllib.parse import unquote, urljoin, urlsplit

CHROMIUM_FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
    "--disable-quic",
    "--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1",
]


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


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        if shutil.which(name):
            return shutil.which(name)
    sys.exit("site check: no Chromium found (apt-get install chromium)")


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
        if code >= 400 and not self.path.endswith("/favicon.ico"):
            QuietHandler.missing.add(f"{code} {self.path}")
        super().send_error(code, message, explain)


def chromium(browser, url, profile, *extra):
    command = [
        browser,
        *CHROMIUM_FLAGS,
        f"--user-data-dir={profile}",
        "--virtual-time-budget=20000",
        *extra,
        url,
    ]
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


def check_links(root, page, parser, cache):
    problems = []
    base = "/" + page
    for href in parser.links + parser.images:
        parts = urlsplit(href)
        if parts.scheme or href.startswith("//") or href.startswith("mailto:"):
            continue
        target = urlsplit(urljoin(base, href))
        path = unquote(target.path).lstrip("/") or "index.html"
        file = os.path.join(root, path)
        if os.path.isdir(file):
            file = os.path.join(file, "index.html")
        if not os.path.isfile(file):
            problems.append(f"{page}: broken link {href}")
            continue
        if target.fragment and file.endswith(".html"):
            if file not in cache:
                with open(file, encoding="utf-8") as f:
                    cache[file] = parse(f.read()).ids
            if unquote(target.fragment) not in cache[file]:
                problems.append(f"{page}: link {href} points to a missing anchor")
    return problems


BOOK_LIMIT_MB = 20
REDRAW_GOAL_MS = 50
# What a chapter must show, as a heading or an admonition's title
# (the text of one element).
CHAPTER_SHAPE = {
    "What you will learn": re.compile(r">\s*What you will learn\s*<"),
    "Summary": re.compile(r"<h[2-6][^>]*>\s*Summary\s*<"),
}
PLACEHOLDER_HOSTS = ("example.",)  # example.com, hub.example.edu, ...


def check_chapter_shape(page, html):
    """A chapter page must say what the student will learn and end with a summary."""
    if not page.startswith("notebooks/"):
        return []
    return [
        f'{page}: a chapter without "{words}"'
        for words, pattern in CHAPTER_SHAPE.items()
        if not pattern.search(html)
    ]


# An alt text that names a file, or says nothing of what the image shows.
PATH_LIKE = re.compile(
    r"(^|/)[\w.-]+\.(png|jpe?g|gif|svg|webp)$|^_images/|^data:", re.I
)
PLACEHOLDER_ALTS = {"", "image", "figure", "precomputed figure", "png", "output"}


def check_alt_texts(page, parser):
    """Every image of a page says what it shows: an alt text that is not its file's
    path, nor a placeholder (decorations, such as a launch button's logo, name what they
    are)."""
    problems = []
    for src, alt in parser.alts:
        text = (alt or "").strip()
        if alt is None or text.lower() in PLACEHOLDER_ALTS or PATH_LIKE.search(text):
            problems.append(
                f"{page}: image {src[:60]} has the alt text {alt!r}, not what it shows"
            )
    return problems


# The first code cell of every chapter installs screwkit where it is missing
# (Colab, a bare JupyterHub), as the book's first chapter does.
INSTALLS_SCREWKIT = re.compile(r'find_spec\(\s*"screwkit"\s*\)[\s\S]*pip install')


def check_first_cell(root, page):
    """A chapter's first code cell installs screwkit where it is missing."""
    source = os.path.join(root, "_sources", os.path.splitext(page)[0] + ".ipynb")
    if not page.startswith("notebooks/"):
        return []
    if not os.path.exists(source):
        return [f"{page}: no notebook source in the build (_sources)"]
    with open(source, encoding="utf-8") as f:
        cells = [c for c in json.load(f)["cells"] if c["cell_type"] == "code"]
    if not cells or not INSTALLS_SCREWKIT.search("".join(cells[0]["source"])):
        return [
            f"{page}: the first code cell does not install screwkit where it is "
            "missing (copy the first code cell of another chapter)"
        ]
    return []


def check_toc_built(root, toc="_toc.yml"):
    """Every file of the table of contents is a page of the build
    (none left out of the checks)."""
    toc = os.path.join(os.path.dirname(os.path.dirname(root)), toc)
    if not os.path.exists(toc):
        return []
    with open(toc, encoding="utf-8") as f:
        files = re.findall(r"^\s*-?\s*(?:file|root):\s*(\S+)", f.read(), re.M)
    return [
        f"{name}: in _toc.yml but not built ({name}.html missing)"
        for name in files
        if not os.path.exists(os.path.join(root, name + ".html"))
    ]


# The parallel mechanisms of the catalogue (screwkit.robots): a chapter that analyses
# them with sk.mobility must draw each one.
MECHANISM_BUILDER = re.compile(r"robots\.(pm_\w+|planar_3rrr|spherical_3rrr)\b")


def check_mechanism_drawings(root, page, figures):
    """A chapter of the mobility kind (its code calls sk.mobility) must show at least as
    many figures as the catalogue mechanisms its code builds
    (read from the page's .ipynb source)."""
    source = os.path.join(root, "_sources", os.path.splitext(page)[0] + ".ipynb")
    if not page.startswith("notebooks/") or not os.path.exists(source):
        return []
    with open(source, encoding="utf-8") as f:
        cells = json.load(f)["cells"]
    code = "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "code")
    if "sk.mobility(" not in code:
        return []
    mechanisms = sorted(set(MECHANISM_BUILDER.findall(code)))
    if len(figures) < len(mechanisms):
        return [
            f"{page}: {len(mechanisms)} mechanisms analysed "
            f"({', '.join(mechanisms)}) but only {len(figures)} figures: "
            "draw each one (sk.plotting.draw_mechanism)"
        ]
    return []


def check_placeholder_links(page, parser):
    """Links (launch buttons among them) must not point to a placeholder such as
    hub.example.edu."""
    problems = []
    for href in parser.links:
        host = urlsplit(href).hostname or ""
        if any(marker in host for marker in PLACEHOLDER_HOSTS):
            problems.append(f"{page}: a link to the placeholder {host}: {href[:120]}")
    return problems


# ---- The book as a reader sees it: navigation, weight, accessibility and layout, at
# the widths of a phone (390 px), a tablet (800 px) and a laptop (1280 px), on every
# page (by rule: every page of the build under book/ and notebooks/, so a new chapter
# cannot slip by).

WIDTHS = (390, 800, 1280)
PAGE_LIMIT_MB = 2.5  # a page, cold (empty cache): the HTML and everything it loads
AXE_VERSION = "4.14.1"  # axe-core from the npm registry, fetched at check time
AXE_FAILING = ("critical", "serious")

# In the page: which search controls, sidebar buttons and sidebars a reader can see.
VISIBLE = """(selector) => [...document.querySelectorAll(selector)].filter(e => {
    const r = e.getBoundingClientRect(), s = getComputedStyle(e);
    return r.width > 0 && r.height > 0 && s.visibility !== "hidden" && r.right > 0
        && r.left < innerWidth && e.closest("[inert]") === null;
}).length"""
DIALOG_OPEN = (
    "(id) => { const d = document.getElementById(id); return !!(d && d.open); }"
)
TOOLTIPS = "() => [...document.querySelectorAll('.tooltip.show')].length"


def check_navigation(page, page_name, width):
    """One search; the table-of-contents and page-outline buttons open their
    sidebars."""
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
                page.wait_for_timeout(400)
                closed = page.evaluate(VISIBLE, links) == 0
                press(buttons[0])
                page.wait_for_timeout(400)
                if not closed or not page.evaluate(VISIBLE, links):
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
        page.wait_for_timeout(400)
        dialog = f"pst-{side}-sidebar-modal"
        if not page.evaluate(DIALOG_OPEN, dialog) or not page.evaluate(
            VISIBLE, f"#{dialog} a"
        ):
            problems.append(
                f"{where}: the {side} sidebar button does not open the sidebar"
            )
        page.keyboard.press("Escape")
        page.wait_for_timeout(300)
        if page.evaluate(DIALOG_OPEN, dialog):
            problems.append(f"{where}: Escape does not close the {side} sidebar")
    if width >= 600:  # the mouse leaves the buttons, as a reader's does
        page.mouse.move(width // 2, 600)
    page.wait_for_timeout(700)  # longer than the tooltips' show delay
    if page.evaluate(TOOLTIPS):
        problems.append(
            f"{where}: a tooltip stays on screen after the buttons were used"
        )
    return problems


# In the page (by rule, every element of the article): the content column; elements that
# stick out of it (not inside a box that clips or scrolls them); boxes that scroll
# sideways, by kind; images meant to be shown wider than the column; and whether the
# page itself scrolls sideways.
MEASURE_LAYOUT = """() => {
    const article = document.querySelector("article.bd-article") || document.querySelector("main");
    const style = getComputedStyle(article), box = article.getBoundingClientRect();
    const left = box.left + parseFloat(style.paddingLeft);
    const right = box.right - parseFloat(style.paddingRight);
    const clips = e => getComputedStyle(e).overflowX !== "visible";
    const inside = e => { for (let a = e.parentElement; a && a !== article; a = a.parentElement)
                              if (clips(a)) return true;
                          return false; };
    const name = e => {
        const text = (e.innerText || e.getAttribute("alt") || e.getAttribute("src") || "")
            .trim().split("\\n")[0].slice(0, 50);
        return `${e.tagName.toLowerCase()}${e.className && typeof e.className === "string"
            ? "." + e.className.trim().split(/\\s+/)[0] : ""} ${JSON.stringify(text)}`;
    };
    const kind = e => e.closest(".cell_input") ? "code"
        : e.closest("mjx-container, div.math, span.math") ? "equation"
        : e.closest("table, .pst-scrollable-table-container") || e.querySelector("table") ? "table"
        : e.closest(".cell_output") ? "output"
        : e.closest("div.highlight") ? "code block" : "other";
    const out = [], scrolling = [];
    for (const e of article.querySelectorAll("*")) {
        const r = e.getBoundingClientRect(), s = getComputedStyle(e);
        if (r.width === 0 || r.height === 0 || s.position === "fixed") continue;
        if ((r.right > right + 1 || r.left < left - 1) && !inside(e)) {
            const p = e.parentElement.getBoundingClientRect();
            if (!(p.right > right + 1 || p.left < left - 1))
                out.push([kind(e), name(e), Math.round(r.width)]);
        }
        // A box (not an inline element, whose clientWidth is 0) with more inside than it shows:
        // scrolled sideways, or clipped. What is inside is measured by its elements' boxes,
        // leaving out MathJax's copy for screen readers (mjx-assistive-mml), which is clipped
        // on purpose and would count in scrollWidth.
        if (s.display === "inline" || !clips(e) || e.scrollWidth <= e.clientWidth + 1
            || e.closest("mjx-assistive-mml")) continue;
        const edge = e.getBoundingClientRect().left + e.clientLeft + e.clientWidth - e.scrollLeft;
        let widest = edge;
        for (const d of e.querySelectorAll("*")) {
            if (d.closest("mjx-assistive-mml")) continue;
            const dr = d.getBoundingClientRect();
            if (dr.width > 0) widest = Math.max(widest, dr.right);
        }
        const hidden = Math.round(widest - edge);
        if (hidden <= 3) continue;  // an italic letter's overhang
        if (s.overflowX === "hidden") out.push([kind(e), `clipped (${hidden} px) ${name(e)}`,
                                                Math.round(r.width) + hidden]);
        else scrolling.push([kind(e), name(e), e.clientWidth + hidden, e.clientWidth]);
    }
    const images = [...article.querySelectorAll("img")].map(img => {
        const intended = img.getAttribute("width") ? parseFloat(img.getAttribute("width"))
                                                  : img.naturalWidth;
        return [img.getAttribute("src"), intended];
    }).filter(([src, width]) => width > right - left + 1);
    const page = document.documentElement.scrollWidth > innerWidth + 1;
    return {column: Math.round(right - left), out, scrolling, images, page};
}"""  # noqa: E501 (JavaScript: its lines are the string's text)


def check_layout(page, page_name, width):
    """At 1280 px nothing wider than the column, and no code cell, output or table that
    scrolls sideways (an equation too long for any column, or a code block of the prose,
    may: they are listed); at every width the page itself never scrolls sideways, and
    equations and tables stay in the column (scrolling inside their own box)."""
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
        if width >= 1280 and kind in ("equation", "code block"):
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


AXE_RUN = """async () => {
    const result = await axe.run(document, {resultTypes: ["violations"]});
    return result.violations.map(v => [v.id, v.impact, v.nodes.length,
        v.nodes.slice(0, 2).map(n => n.target.join(" ")).join(", ")]);
}"""


def check_accessibility(page, page_name, axe):
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


def check_search(chromium, url, word="screw"):
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


# In the page: resolves when MathJax (if the page loads it) has typeset the page. Its
# loader fetches its components only after the page's own scripts have run (a viewer's
# three.js, say), which can come after a quiet half second: "networkidle" alone may miss
# them.
MATHJAX_DONE = """() => window.MathJax && MathJax.startup && MathJax.startup.promise
    ? MathJax.startup.promise.then(() => true) : false"""


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


def check_reader(browser, origin, pages, cache):
    """Every page at every width: navigation, layout and (at 1280 px) axe; and its cold
    weight."""
    from playwright.sync_api import sync_playwright

    axe = axe_source(cache)
    problems, notes, layout_counts, axe_counts, weights = [], [], {}, {}, {}
    flags = [f for f in CHROMIUM_FLAGS if f != "--headless"]
    with sync_playwright() as p:
        chromium = p.chromium.launch(executable_path=browser, args=flags)
        for width in WIDTHS:
            phone = width < 600
            context = chromium.new_context(
                viewport={"width": width, "height": 900},
                has_touch=phone,
                is_mobile=phone,
            )
            for page_name in pages:
                page = context.new_page()
                page.goto(origin + page_name, wait_until="load")
                page.wait_for_timeout(500)  # MathJax typesets after load
                found, counts, noted = check_layout(page, page_name, width)
                problems += found
                notes += noted
                for kind, count in counts.items():
                    layout_counts[(width, kind)] = (
                        layout_counts.get((width, kind), 0) + count
                    )
                problems += check_navigation(page, page_name, width)
                if width == 1280:
                    page.reload(wait_until="load")
                    page.wait_for_timeout(500)
                    found, counts = check_accessibility(page, page_name, axe)
                    problems += found
                    axe_counts[page_name] = counts
                page.close()
            context.close()
        for page_name in pages:
            weights[page_name] = cold_weight(chromium, origin + page_name)
        problems += check_search(chromium, origin + pages[0])
        chromium.close()
    for width in WIDTHS:
        kinds = {
            kind: n for (w, kind), n in sorted(layout_counts.items()) if w == width
        }
        print(f"at {width} px, boxes that scroll sideways (by kind): {kinds or 'none'}")
    for note in notes:
        print("  " + note)
    print(
        "axe-core",
        AXE_VERSION,
        "violations (elements) by impact, and cold page weight:",
    )
    for page_name in pages:
        counts = ", ".join(
            f"{k} {v}" for k, v in sorted(axe_counts.get(page_name, {}).items())
        )
        print(
            f"  {page_name}: {weights[page_name] / 1e6:.2f} MB; axe: {counts or 'none'}"
        )
        if weights[page_name] > PAGE_LIMIT_MB * 1e6:
            problems.append(
                f"{page_name}: {weights[page_name] / 1e6:.2f} MB cold, over the "
                f"{PAGE_LIMIT_MB} MB limit"
            )
    return problems


# In the page: move control k of figure `id` to another value of its grid, return
# [changed?, milliseconds, label]. A figure's drawing is its canvas pixels or its
# frame's HTML.
MOVE_CONTROL = """([id, k]) => {
    const root = document.getElementById(id);
    const drawing = () => [...root.querySelectorAll("canvas")].map(c => c.toDataURL()).join()
        + [...root.querySelectorAll(".screwkit-frame")].map(f => f.innerHTML).join();
    const control = root.querySelectorAll("input[type=range], select")[k];
    const before = drawing();
    let label = control.getAttribute("aria-label");
    if (control.tagName === "SELECT") {
        control.selectedIndex = (control.selectedIndex + 1) % control.options.length;
    } else {
        const [low, high, step] = [+control.min, +control.max, +control.step];
        const count = Math.round((high - low) / step);
        const here = Math.round((+control.value - low) / step);
        control.value = String(low + step * ((here + Math.max(1, Math.round(count / 3))) % (count + 1)));
    }
    const start = performance.now();
    control.dispatchEvent(new Event(control.tagName === "SELECT" ? "change" : "input"));
    const elapsed = performance.now() - start;
    return [drawing() !== before, elapsed, label];
}"""  # noqa: E501 (JavaScript: its lines are the string's text)


def check_interactive(browser, origin, pages):
    """Move every control of every in-page figure; the drawing must change, without JS
    errors."""
    from playwright.sync_api import sync_playwright

    problems = []
    flags = [f for f in CHROMIUM_FLAGS if f != "--headless"]
    with sync_playwright() as p:
        chromium = p.chromium.launch(executable_path=browser, args=flags)
        for page_name in pages:
            page = chromium.new_page()
            errors = []
            page.on("pageerror", lambda error: errors.append(str(error)))
            page.on(
                "console",
                lambda m: (
                    m.type == "error"
                    and not m.location.get("url", "").endswith("/favicon.ico")
                    and errors.append(m.text)
                ),
            )
            page.goto(origin + page_name, wait_until="load")
            placeholders = page.locator(
                "script[type='application/vnd.jupyter.widget-view+json']"
            ).count()
            if placeholders:
                problems.append(
                    f"{page_name}: {placeholders} widget placeholders "
                    "(blank in the book)"
                )
            figures = page.eval_on_selector_all(
                "div.screwkit-viewer", "d => d.map(e => e.id)"
            )
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
            problems += [f"{page_name}: JavaScript error: {e}" for e in errors]
            if times:
                print(
                    f"{page_name}: {len(figures)} interactive figures, "
                    f"{len(times)} controls moved, "
                    f"redraw median {sorted(times)[len(times) // 2]:.1f} ms, "
                    f"max {max(times):.1f} ms (goal {REDRAW_GOAL_MS} ms)"
                )
            page.close()
        chromium.close()
    return problems


def main(root):
    root = os.path.abspath(root)
    pages = toc_pages(root)
    if not pages:
        sys.exit(
            f"site check: no pages under {root}/book or {root}/notebooks; "
            "build the book first"
        )
    browser = find_chromium()
    server = serve(root)
    origin = f"http://127.0.0.1:{server.server_address[1]}/"
    problems, anchors = check_toc_built(root), {}
    with tempfile.TemporaryDirectory() as tmp:
        netlog = os.path.join(tmp, "netlog.json")
        for page in pages:
            with open(os.path.join(root, page), encoding="utf-8") as f:
                static = parse(f.read())
            problems += check_links(root, page, static, anchors)
            problems += check_placeholder_links(page, static)
            problems += check_alt_texts(page, static)
            problems += check_first_cell(root, page)
            with open(os.path.join(root, page), encoding="utf-8") as f:
                problems += check_chapter_shape(page, f.read())
            dom = parse(
                chromium(
                    browser,
                    origin + page,
                    os.path.join(tmp, "profile"),
                    "--dump-dom",
                    f"--log-net-log={netlog}",
                )
            )
            leaks = outside_requests(netlog, origin)
            problems += [
                f"{page}: request left the machine: {url}" for url in sorted(leaks)
            ]
            if static.math_sources and not dom.math_containers:
                problems.append(f"{page}: has math but MathJax typeset none of it")
            if dom.math_errors:
                problems.append(f"{page}: MathJax reported {dom.math_errors} errors")
            figures = [src for src in dom.images if "_images/" in src]
            if page.startswith("notebooks/") and not figures:
                problems.append(
                    f"{page}: a chapter page without a figure (no cell output image)"
                )
            problems += check_mechanism_drawings(root, page, figures)
            print(
                f"{page}: {dom.math_containers} math, {len(figures)} figures, "
                f"{len(static.links)} links, {len(leaks)} outside requests"
            )
        shot_page = next((p for p in pages if p.startswith("notebooks/")), pages[0])
        shot = os.path.join(os.path.dirname(root), "screenshot.png")
        chromium(
            browser,
            origin + shot_page,
            os.path.join(tmp, "profile"),
            f"--screenshot={shot}",
            "--window-size=1280,1600",
            "--hide-scrollbars",
        )
        print(f"screenshot of {shot_page}: {shot}")
        problems += check_interactive(browser, origin, pages)
        problems += check_reader(
            browser, origin, pages, os.path.join(os.path.dirname(root), ".site-check")
        )
    server.shutdown()
    problems += [
        f"the server had no answer for {request}"
        for request in sorted(QuietHandler.missing)
    ]
    size = sum(
        os.path.getsize(os.path.join(d, f)) for d, _, fs in os.walk(root) for f in fs
    )
    print(f"book size: {size / 1e6:.1f} MB (limit {BOOK_LIMIT_MB} MB)")
    if size > BOOK_LIMIT_MB * 1e6:
        problems.append(
            f"the book is {size / 1e6:.1f} MB, over the {BOOK_LIMIT_MB} MB limit"
        )
    if problems:
        print("\nsite check FAILED:")
        for problem in problems:
            print("  - " + problem)
        sys.exit(1)
    print(f"site check passed: {len(pages)} pages")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "_build/html")
