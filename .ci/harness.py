"""The one way the project's checks start a browser: the system Chromium, fenced off
the network.

Every check that looks at a page (the site check, the viewers' browser test, the live
JupyterLab check, the answer boxes' test, the viewers' screenshots) starts Chromium
through this module, so that they all run the same browser with the same fence: every
host but 127.0.0.1 unresolvable, no background requests, no downloaded browser.
Playwright (``.ci/requirements.txt``) drives it; :func:`command` runs it without
Playwright (the site check's DOM dumps and net logs).

Scripts in ``.ci/`` import it as ``harness``; others put ``.ci`` on ``sys.path`` first.
"""

import contextlib
import shutil

#: The system Chromium (apt-get install chromium), or None.
CHROMIUM = next(
    (
        shutil.which(name)
        for name in ("chromium", "chromium-browser", "google-chrome")
        if shutil.which(name)
    ),
    None,
)

#: The fence: no requests of the browser's own, and no host resolves but 127.0.0.1.
FLAGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
    "--disable-quic",
    "--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1",
]


def executable():
    """The system Chromium's path.

    Returns
    -------
    str
        The path of the Chromium on PATH.

    Raises
    ------
    RuntimeError
        When no Chromium is installed.
    """
    if CHROMIUM is None:
        raise RuntimeError("no Chromium found on PATH (apt-get install chromium)")
    return CHROMIUM


@contextlib.contextmanager
def launch(**options):
    """The system Chromium, headless, fenced, driven by Playwright; closed after.

    Parameters
    ----------
    **options
        More keyword arguments of Playwright's ``chromium.launch`` (not
        ``executable_path`` or ``args``, which this module sets).

    Yields
    ------
    playwright.sync_api.Browser
    """
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=executable(), args=FLAGS, **options)
        try:
            yield browser
        finally:
            browser.close()


def collect_errors(page, ignore=lambda url: False):
    """Keep the page's uncaught exceptions and console errors in ``page.errors``.

    Parameters
    ----------
    page : playwright.sync_api.Page
    ignore : callable, optional
        ``ignore(url)`` is true for a console error's source URL that does not count
        (a missing favicon, say).

    Returns
    -------
    list of str
        ``page.errors``, filled as the page runs.
    """
    errors = []
    page.on("pageerror", lambda error: errors.append(str(error)))
    page.on(
        "console",
        lambda m: (
            m.type == "error"
            and not ignore(m.location.get("url", ""))
            and errors.append(m.text)
        ),
    )
    page.errors = errors
    return errors


def command(*arguments):
    """The command line of a headless, fenced Chromium run without Playwright.

    Parameters
    ----------
    *arguments : str
        Chromium's further flags and the URL (``--dump-dom``, ``--screenshot=...``).

    Returns
    -------
    list of str
        For ``subprocess.run``.
    """
    return [executable(), "--headless", *FLAGS, *arguments]
