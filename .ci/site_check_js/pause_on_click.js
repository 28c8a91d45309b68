// A second click on a playing trajectory viewer's button, in one task of the page so
// that no animation frame runs between reading its state and clicking: a player that
// reached its end by itself while the browser was busy is started again first (play at
// the end starts from the beginning). Returns whether it is still playing after the click.
(id) => {
    const root = document.getElementById(id);
    const button = root.querySelector("button.screwkit-play");
    if (root.dataset.playing !== "1") button.click();
    button.click();
    return root.dataset.playing === "1";
}
