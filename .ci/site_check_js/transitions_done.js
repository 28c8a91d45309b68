// Resolves when every finite animation of the page (a theme switch's colour
// transitions) has finished, or after 5 s; endless ones (a spinner) are not waited for.
() => Promise.race([
    Promise.all(document.getAnimations()
        .filter(a => a.effect && a.effect.getComputedTiming().endTime !== Infinity)
        .map(a => a.finished.catch(() => null))),
    new Promise(done => setTimeout(done, 5000)),
]).then(() => true)
