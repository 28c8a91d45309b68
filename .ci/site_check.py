"""Check the built book as a reader's browser sees it, with no network.

Serves the HTML build on 127.0.0.1, loads every page of the table of contents in headless
Chromium (every host but 127.0.0.1 unresolvable), and fails unless:
  - math is typeset by the bundled MathJax (mjx-container elements, no MathJax errors)
    on every page that has math;
  - every chapter page (notebooks/) shows at least one figure whose file is in the build;
  - no page links to a missing file or anchor of the book;
  - no page asked for anything off this machine (Chromium's net log lists every request);
  - every slider or drop-down of every in-page interactive figure (screwkit.viewer), when
    moved, changes the drawing, and no page logs a JavaScript error (Playwright driving the
    system Chromium); the redraw time of each move is printed (goal: under 50 ms);
  - no page holds a widget placeholder (a widget view with no fallback: blank in the book);
  - every chapter says what the student will learn ("What you will learn") and ends with a
    "Summary";
  - no link (a launch button above all) points to a placeholder host such as hub.example.edu;
  - every file a page asks the server for exists (MathJax fonts and extensions included);
  - in Chromium at 1280 px, no figure image is wider than the content column (it would be shrunk
    and its text with it) and no code cell's output is wider than the column (clipped, or behind
    a scroll bar); the same is counted, not failed, at a phone's 390 px;
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
        self.ids, self.links, self.images = set(), [], []
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
    command = [browser, *CHROMIUM_FLAGS, f"--user-data-dir={profile}",
               "--virtual-time-budget=20000", *extra, url]
    result = subprocess.run(command, capture_output=True, text=True, timeout=180)
    if result.returncode != 0:
        raise RuntimeError(f"chromium failed on {url}: {result.stderr[-2000:]}")
    return result.stdout


def toc_pages(root):
    pages = []
    for folder in ("book", "notebooks"):
        directory = os.path.join(root, folder)
        if os.path.isdir(directory):
            pages += sorted(os.path.join(folder, f) for f in os.listdir(directory) if f.endswith(".html"))
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
        if event.get("type") != start_job or params.get("initiator") != origin.rstrip("/"):
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
# What a chapter must show, as a heading or an admonition's title (the text of one element).
CHAPTER_SHAPE = {
    "What you will learn": re.compile(r">\s*What you will learn\s*<"),
    "Summary": re.compile(r"<h[2-6][^>]*>\s*Summary\s*<"),
}
PLACEHOLDER_HOSTS = ("example.",)  # example.com, hub.example.edu, ...


def check_chapter_shape(page, html):
    """A chapter page must say what the student will learn and end with a summary."""
    if not page.startswith("notebooks/"):
        return []
    return [f"{page}: a chapter without \"{words}\"" for words, pattern in CHAPTER_SHAPE.items()
            if not pattern.search(html)]


# The parallel mechanisms of the catalogue (screwkit.robots): a chapter that analyses them with
# sk.mobility must draw each one.
MECHANISM_BUILDER = re.compile(r"robots\.(pm_\w+|planar_3rrr|spherical_3rrr)\b")


def check_mechanism_drawings(root, page, figures):
    """A chapter of the mobility kind (its code calls sk.mobility) must show at least as many
    figures as the catalogue mechanisms its code builds (read from the page's .ipynb source)."""
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
        return [f"{page}: {len(mechanisms)} mechanisms analysed ({', '.join(mechanisms)}) but only "
                f"{len(figures)} figures: draw each one (sk.plotting.draw_mechanism)"]
    return []


def check_placeholder_links(page, parser):
    """Links (launch buttons among them) must not point to a placeholder such as hub.example.edu."""
    problems = []
    for href in parser.links:
        host = urlsplit(href).hostname or ""
        if any(marker in host for marker in PLACEHOLDER_HOSTS):
            problems.append(f"{page}: a link to the placeholder {host}: {href[:120]}")
    return problems


# In the page: the content column's width, figures wider than it (as the image is meant to be
# shown: its width attribute, else its natural width) and code cell outputs wider than it.
MEASURE_LAYOUT = """() => {
    const article = document.querySelector("article.bd-article") || document.querySelector("main");
    const style = getComputedStyle(article);
    const column = article.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight);
    const figures = [...article.querySelectorAll("img")].map(img => {
        const intended = img.getAttribute("width") ? parseFloat(img.getAttribute("width"))
                                                  : img.naturalWidth;
        return [img.getAttribute("src"), intended];
    }).filter(([src, width]) => width > column + 1);
    const outputs = [...article.querySelectorAll("div.cell_output")].map((output, k) => {
        const parts = [output, ...output.querySelectorAll("pre, mjx-container, table, .output")];
        const widest = Math.max(...parts.map(e => Math.max(e.scrollWidth,
                                                           e.getBoundingClientRect().width)));
        const text = (output.innerText || "").trim().split("\\n")[0].slice(0, 60);
        return [k, Math.round(widest), text];
    }).filter(([k, width]) => width > column + 1);
    return [Math.round(column), figures, outputs];
}"""


def check_layout(browser, pages):
    """Figures and code cell outputs no wider than the content column, at 1280 px and 390 px."""
    from playwright.sync_api import sync_playwright

    problems = []
    flags = [f for f in CHROMIUM_FLAGS if f != "--headless"]
    with sync_playwright() as p:
        chromium = p.chromium.launch(executable_path=browser, args=flags)
        for width, fail in ((1280, True), (390, False)):
            context = chromium.new_context(viewport={"width": width, "height": 900})
            wide_figures = wide_outputs = 0
            for page_name, url in pages:
                page = context.new_page()
                page.goto(url, wait_until="load")
                page.wait_for_timeout(300)  # MathJax typesets after load
                column, figures, outputs = page.evaluate(MEASURE_LAYOUT)
                if fail:
                    problems += [f"{page_name}: figure {src[:80]} is {w:.0f} px wide, the "
                                 f"column {column} px" for src, w in figures]
                    problems += [f"{page_name}: code cell output {k + 1} is {w} px wide, the "
                                 f"column {column} px: {text!r}" for k, w, text in outputs]
                else:
                    wide_figures += len(figures)
                    wide_outputs += len(outputs)
                page.close()
            if not fail:
                print(f"at {width} px: {wide_figures} figures (shown shrunk) and {wide_outputs} "
                      "code outputs (scrolled sideways) wider than the column; not a failure")
            context.close()
        chromium.close()
    return problems

# In the page: move control k of figure `id` to another value of its grid, return
# [changed?, milliseconds, label]. A figure's drawing is its canvas pixels or its frame's HTML.
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
}"""


def check_interactive(browser, origin, pages):
    """Move every control of every in-page figure; the drawing must change, without JS errors."""
    from playwright.sync_api import sync_playwright

    problems = []
    flags = [f for f in CHROMIUM_FLAGS if f != "--headless"]
    with sync_playwright() as p:
        chromium = p.chromium.launch(executable_path=browser, args=flags)
        for page_name in pages:
            page = chromium.new_page()
            errors = []
            page.on("pageerror", lambda error: errors.append(str(error)))
            page.on("console", lambda m: m.type == "error" and not m.location.get("url", "")
                    .endswith("/favicon.ico") and errors.append(m.text))
            page.goto(origin + page_name, wait_until="load")
            placeholders = page.locator(
                "script[type='application/vnd.jupyter.widget-view+json']").count()
            if placeholders:
                problems.append(f"{page_name}: {placeholders} widget placeholders (blank in the book)")
            figures = page.eval_on_selector_all("div.screwkit-viewer", "d => d.map(e => e.id)")
            times = []
            for figure in figures:
                if not page.evaluate("id => document.getElementById(id).dataset.mounted", figure):
                    problems.append(f"{page_name}: figure {figure} was never drawn")
                    continue
                count = page.locator(f"[id='{figure}'] input[type=range], [id='{figure}'] select").count()
                for k in range(count):
                    changed, elapsed, label = page.evaluate(MOVE_CONTROL, [figure, k])
                    times.append(elapsed)
                    if not changed:
                        problems.append(f"{page_name}: moving {label} of {figure} changed nothing")
            problems += [f"{page_name}: JavaScript error: {e}" for e in errors]
            if times:
                print(f"{page_name}: {len(figures)} interactive figures, {len(times)} controls moved, "
                      f"redraw median {sorted(times)[len(times) // 2]:.1f} ms, "
                      f"max {max(times):.1f} ms (goal {REDRAW_GOAL_MS} ms)")
            page.close()
        chromium.close()
    return problems


def main(root):
    root = os.path.abspath(root)
    pages = toc_pages(root)
    if not pages:
        sys.exit(f"site check: no pages under {root}/book or {root}/notebooks; build the book first")
    browser = find_chromium()
    server = serve(root)
    origin = f"http://127.0.0.1:{server.server_address[1]}/"
    problems, anchors = [], {}
    with tempfile.TemporaryDirectory() as tmp:
        netlog = os.path.join(tmp, "netlog.json")
        for page in pages:
            with open(os.path.join(root, page), encoding="utf-8") as f:
                static = parse(f.read())
            problems += check_links(root, page, static, anchors)
            problems += check_placeholder_links(page, static)
            with open(os.path.join(root, page), encoding="utf-8") as f:
                problems += check_chapter_shape(page, f.read())
            dom = parse(chromium(browser, origin + page, os.path.join(tmp, "profile"),
                                 "--dump-dom", f"--log-net-log={netlog}"))
            leaks = outside_requests(netlog, origin)
            problems += [f"{page}: request left the machine: {url}" for url in sorted(leaks)]
            if static.math_sources and not dom.math_containers:
                problems.append(f"{page}: has math but MathJax typeset none of it")
            if dom.math_errors:
                problems.append(f"{page}: MathJax reported {dom.math_errors} errors")
            figures = [src for src in dom.images if "_images/" in src]
            if page.startswith("notebooks/") and not figures:
                problems.append(f"{page}: a chapter page without a figure (no cell output image)")
            problems += check_mechanism_drawings(root, page, figures)
            print(f"{page}: {dom.math_containers} math, {len(figures)} figures, "
                  f"{len(static.links)} links, {len(leaks)} outside requests")
        shot_page = next((p for p in pages if p.startswith("notebooks/")), pages[0])
        shot = os.path.join(os.path.dirname(root), "screenshot.png")
        chromium(browser, origin + shot_page, os.path.join(tmp, "profile"),
                 f"--screenshot={shot}", "--window-size=1280,1600", "--hide-scrollbars")
        print(f"screenshot of {shot_page}: {shot}")
        problems += check_interactive(browser, origin, pages)
        problems += check_layout(browser, [(page, origin + page) for page in pages])
    server.shutdown()
    problems += [f"the server had no answer for {request}" for request in sorted(QuietHandler.missing)]
    size = sum(os.path.getsize(os.path.join(d, f)) for d, _, fs in os.walk(root) for f in fs)
    print(f"book size: {size / 1e6:.1f} MB (limit {BOOK_LIMIT_MB} MB)")
    if size > BOOK_LIMIT_MB * 1e6:
        problems.append(f"the book is {size / 1e6:.1f} MB, over the {BOOK_LIMIT_MB} MB limit")
    if problems:
        print("\nsite check FAILED:")
        for problem in problems:
            print("  - " + problem)
        sys.exit(1)
    print(f"site check passed: {len(pages)} pages")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "_build/html")
