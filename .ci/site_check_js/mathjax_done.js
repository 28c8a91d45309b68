// Resolves when MathJax (if the page loads it) has typeset the page. Its loader
// fetches its components only after the page's own scripts have run (a viewer's
// three.js, say), which can come after a quiet half second: "networkidle" alone may
// miss them.
() => window.MathJax && MathJax.startup && MathJax.startup.promise
    ? MathJax.startup.promise.then(() => true) : false
