/* Fixes to the theme's pages, run (deferred) before the theme's own scripts.
 *
 * Tooltips: Bootstrap shows a button's tooltip on hover and on focus. On a touch screen a tap
 * is both, and the tooltip stays over the button (or over its neighbour, the search button,
 * when a dialog hands the focus back), so touch screens get no tooltips (every button keeps its
 * aria-label); elsewhere a tooltip follows the mouse only, not the focus a click leaves.
 *
 * Names for screen readers: an icon inside a button or link is decoration (the button has
 * its label), so it is hidden from them: the theme button's icons carry titles ("Light",
 * "Dark", ...) that made its visible name differ from its label "Color mode". A code cell's
 * "Show code cell source" summary is named by that visible text, not by a different label.
 *
 * Landmarks: the primary sidebar (the book's title and its table of contents) is a region of
 * its own, so that no content of the page lies outside a landmark.
 *
 * The list of references: docutils writes it as role="list" whose items have the role
 * "doc-biblioentry" (deprecated, and not a list item for assistive technology), so a screen
 * reader was told of a list without items: each entry is a list item.
 *
 * Equations: a display equation at most a fifth wider than the column is set that much
 * smaller, so that it fits; a wider one (on a phone) scrolls in its own box, which then takes
 * the keyboard focus, so that it can be scrolled without a mouse. A formula in the text
 * scrolls in its box too (span.math, book.css); tables and outputs in theirs.
 *
 * Scroll cue: each of those boxes whose content is wider than it (more than 3 px: an italic
 * letter's overhang does not count) is marked .sk-scrolls, with .sk-more-left and
 * .sk-more-right saying on which side there is more (kept up to date as it scrolls); the
 * book's stylesheet fades that side. Every box that scrolls takes the keyboard focus.
 */
(function () {
  "use strict";
  const touch = window.matchMedia("(hover: none)").matches;
  document.querySelectorAll('[data-bs-toggle="tooltip"]').forEach((element) => {
    if (touch) {
      element.removeAttribute("data-bs-toggle");
    } else {
      element.setAttribute("data-bs-trigger", "hover");
    }
  });
  document.querySelectorAll("button i, a i, button span[class*='fa-'], a span[class*='fa-']")
    .forEach((icon) => icon.setAttribute("aria-hidden", "true"));
  document.querySelectorAll("details > summary[aria-label]").forEach((summary) => {
    if (summary.textContent.trim()) summary.removeAttribute("aria-label");
  });

  const sidebar = document.getElementById("pst-primary-sidebar");
  if (sidebar && !sidebar.hasAttribute("role")) {
    sidebar.setAttribute("role", "complementary");
    sidebar.setAttribute("aria-label", "The book's chapters");
  }
  document.querySelectorAll('[role="list"] > [role="doc-biblioentry"]').forEach((entry) => {
    entry.setAttribute("role", "listitem");
  });

  function fitEquations() {
    document.querySelectorAll('mjx-container[display="true"]').forEach((box) => {
      // MathJax scales each equation to the text by its own inline font-size: start from it.
      if (!("mathjaxSize" in box.dataset)) box.dataset.mathjaxSize = box.style.fontSize;
      box.style.fontSize = box.dataset.mathjaxSize;
      const ratio = box.clientWidth / box.scrollWidth;
      if (ratio < 1 && ratio >= 0.8) {
        const size = parseFloat(getComputedStyle(box).fontSize);
        box.style.fontSize = `${Math.floor(size * ratio * 100) / 100}px`;
      }
    });
    document.querySelectorAll(SCROLLERS).forEach(cueIfScrolling);
  }
  const SCROLLERS = 'mjx-container[display="true"], span.math, ' +
    "div.pst-scrollable-table-container, div.cell_output .output, pre.sk-bench";
  // How far the content of a box reaches past its right edge, in px, by its elements'
  // boxes (MathJax's copy for screen readers, clipped on purpose, left out); for a box
  // of plain text (a benchmark table), by its scroll width.
  function hiddenWidth(box) {
    if (box.scrollWidth <= box.clientWidth + 1) return 0;
    if (!box.firstElementChild) return box.scrollWidth - box.clientWidth;  // plain text
    const edge = box.getBoundingClientRect().left + box.clientLeft + box.clientWidth;
    let widest = edge - box.scrollLeft;
    box.querySelectorAll("*").forEach((element) => {
      if (element.closest("mjx-assistive-mml")) return;
      const right = element.getBoundingClientRect().right;
      if (right > widest) widest = right;
    });
    return widest + box.scrollLeft - edge;
  }
  function updateSides(box) {
    const more = box.scrollWidth - box.clientWidth;
    box.classList.toggle("sk-more-left", box.scrollLeft > 1);
    box.classList.toggle("sk-more-right", box.scrollLeft < more - 1);
  }
  function cueIfScrolling(box) {
    const scrolls = hiddenWidth(box) > 3;
    box.classList.toggle("sk-scrolls", scrolls);
    if (scrolls) {
      updateSides(box);
      if (!box.dataset.skCue) {
        box.dataset.skCue = "1";
        box.addEventListener("scroll", () => updateSides(box), { passive: true });
      }
    } else {
      box.classList.remove("sk-more-left", "sk-more-right");
    }
    // what scrolls (if only by a letter's overhang) takes the keyboard focus, so that
    // the arrow keys scroll it
    if (box.scrollWidth > box.clientWidth + 1) {
      box.setAttribute("tabindex", "0");
    } else {
      box.removeAttribute("tabindex");
    }
  }
  let timer = null;
  window.addEventListener("resize", () => {
    clearTimeout(timer);
    timer = setTimeout(fitEquations, 200);
  });
  window.addEventListener("load", () => {
    const startup = window.MathJax && window.MathJax.startup;
    if (startup && startup.promise) startup.promise.then(fitEquations);
    else fitEquations();  // a page without math: its tables and outputs
  });
})();
