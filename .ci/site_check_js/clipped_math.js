// Formulas and tables clipped where they stand: every MathJax formula (display or in
// the text) and every table of the article whose box sticks out of its block container
// or of the content column, with no box around it (itself included) that scrolls
// sideways: its end runs out of the paragraph (overflow visible) or is cut off
// (overflow hidden), and the reader cannot scroll to it. An inline element's overflow
// does nothing, so only a box that is not inline counts as one that scrolls.
// Returns [kind, text, width, room] for each: its width and the room it has, in px.
() => {
    const article = document.querySelector("article.bd-article") || document.querySelector("main");
    if (!article) return [];
    const scrolls = e => {
        const s = getComputedStyle(e);
        return (s.overflowX === "auto" || s.overflowX === "scroll") && s.display !== "inline";
    };
    const blockOf = e => {
        for (let a = e.parentElement; a && a !== article; a = a.parentElement) {
            const d = getComputedStyle(a).display;
            if (!d.startsWith("inline") && d !== "contents") return a;
        }
        return article;
    };
    const contentBox = e => {
        const r = e.getBoundingClientRect(), s = getComputedStyle(e);
        return {left: r.left + parseFloat(s.paddingLeft) + parseFloat(s.borderLeftWidth),
                right: r.right - parseFloat(s.paddingRight) - parseFloat(s.borderRightWidth)};
    };
    const column = contentBox(article);
    const found = [];
    for (const e of article.querySelectorAll("mjx-container, table")) {
        if (e.closest("mjx-assistive-mml") || e.parentElement.closest("mjx-container")) continue;
        const r = e.getBoundingClientRect();
        if (r.width === 0 || r.height === 0) continue;
        let scrolled = false;
        for (let a = e; a && a !== article; a = a.parentElement) {
            if (scrolls(a)) { scrolled = true; break; }
        }
        if (scrolled) continue;  // whether that box fits the column is layout_fits' check
        const room = contentBox(blockOf(e));
        const left = Math.max(room.left, column.left), right = Math.min(room.right, column.right);
        if (r.right > right + 2 || r.left < left - 2) {
            const math = e.tagName === "MJX-CONTAINER";
            const text = ((math && e.querySelector("mjx-assistive-mml")) || e).textContent;
            found.push([math ? (e.getAttribute("display") === "true" ? "display formula"
                                                                     : "inline formula")
                             : "table",
                        text.replace(/\s+/g, " ").trim().slice(0, 40),
                        Math.round(r.width), Math.round(right - left)]);
        }
    }
    return found;
}
