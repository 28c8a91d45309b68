// Move control k of figure `id` to another value of its grid; returns [changed?,
// milliseconds, label]. A figure's drawing is its canvas pixels or its frame's HTML.
([id, k]) => {
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
}
