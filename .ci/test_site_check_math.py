"""The site check's rule on clipped math (site_check_js/clipped_math.js), on small
pages written here, in Chromium: it finds a formula or table that sticks out of its
paragraph with nothing to scroll it, and passes one that scrolls in a box of its own.
Run by `make site-check`; skipped without Chromium."""

import harness
import pytest
from site_check import CLIPPED_MATH

pytest.importorskip("pytest_playwright")
pytestmark = pytest.mark.skipif(
    harness.CHROMIUM is None, reason="needs Chromium (apt-get install chromium)"
)

WIDE = (
    "<mjx-container><span style='display:inline-block;width:{w}px'>x</span>"
    "</mjx-container>"
)


@pytest.fixture(scope="module")
def page(browser):
    """A phone-wide page of pytest-playwright's browser (the system Chromium)."""
    page = browser.new_page(viewport={"width": 390, "height": 800})
    yield page
    page.close()


def clipped(page, body):
    page.set_content(
        "<html><body style='margin:0'><main style='width:300px;padding:10px'>"
        f"{body}</main></body></html>"
    )
    return page.evaluate(CLIPPED_MATH)


def test_an_inline_formula_wider_than_its_paragraph_is_clipped(page):
    found = clipped(page, f"<p>Text {WIDE.format(w=500)} more.</p>")
    assert [(kind, w, room) for kind, _, w, room in found] == [
        ("inline formula", 500, 300)
    ]


def test_one_cut_off_by_a_hidden_overflow_is_clipped_too(page):
    body = "<p><span style='overflow:hidden;display:inline-flex;max-width:100%'>"
    body += f"{WIDE.format(w=500)}</span></p>"
    assert len(clipped(page, body)) == 1


def test_a_formula_in_a_box_that_scrolls_is_not_clipped(page):
    body = "<p><span style='overflow-x:auto;display:inline-flex;max-width:100%'>"
    body += f"{WIDE.format(w=500)}</span></p>"
    assert clipped(page, body) == []


def test_an_inline_box_cannot_scroll(page):
    # overflow on an inline element does nothing: the formula still runs out
    body = f"<p><span style='overflow-x:auto'>{WIDE.format(w=500)}</span></p>"
    assert len(clipped(page, body)) == 1


def test_a_formula_that_fits_and_a_wide_table_in_a_scrolling_box_pass(page):
    body = f"<p>{WIDE.format(w=200)}</p><div style='overflow-x:auto'>"
    body += "<table style='width:600px'><tr><td>a</td></tr></table></div>"
    assert clipped(page, body) == []
    assert len(clipped(page, "<table style='width:600px'><tr><td>a</td></tr></table>"))
