// What a trajectory viewer (screwkit.viewer.trajectory_viewer) shows at this moment:
// [time drawn (its root's data-time), playing?, caption, canvas pixels].
(id) => {
    const root = document.getElementById(id);
    const canvas = root.querySelector("canvas");
    return [
        +root.dataset.time,
        root.dataset.playing === "1",
        root.querySelector(".screwkit-caption").textContent,
        canvas ? canvas.toDataURL() : "",
    ];
}
