// Switches the page to the dark theme as its colour-mode button does
// (pydata-sphinx-theme keeps the choice in localStorage "mode" and sets data-theme and
// data-mode on <html>); returns the theme now shown.
(mode) => {
    localStorage.setItem("mode", mode);
    localStorage.setItem("theme", mode);
    document.documentElement.dataset.mode = mode;
    document.documentElement.dataset.theme = mode;
    return document.documentElement.dataset.theme;
}
