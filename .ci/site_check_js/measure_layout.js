// By rule, every element of the article: the content column; elements that stick
// out of it (not inside a box that clips or scrolls them); boxes that scroll
// sideways, by kind; images meant to be shown wider than the column; and whether the
// page itself scrolls sideways.
() => {
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
            .trim().split("\n")[0].slice(0, 50);
        return `${e.tagName.toLowerCase()}${e.className && typeof e.className === "string"
            ? "." + e.className.trim().split(/\s+/)[0] : ""} ${JSON.stringify(text)}`;
    };
    // the benchmark tables (book/benchmarks.md): preformatted, wider than the column
    const kind = e => e.closest("pre.sk-bench") ? "wide table"
        : e.closest(".cell_input") ? "code"
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
}
