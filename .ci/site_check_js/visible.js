// How many elements matching `selector` a reader can see (in the viewport, not
// hidden, not inert): search controls, sidebar buttons, sidebar links.
(selector) => [...document.querySelectorAll(selector)].filter(e => {
    const r = e.getBoundingClientRect(), s = getComputedStyle(e);
    return r.width > 0 && r.height > 0 && s.visibility !== "hidden" && r.right > 0
        && r.left < innerWidth && e.closest("[inert]") === null;
}).length
