// Answers every answer box of the page ("1", which is wrong or needs a unit in most),
// so that the verdicts are on screen for axe-core to check their contrast; returns how
// many boxes were answered.
() => {
    const boxes = [...document.querySelectorAll(".sk-answer-box")];
    for (const box of boxes) {
        const input = box.querySelector("input"), button = box.querySelector("button");
        if (!input || !button) continue;
        input.value = "1";
        button.click();
    }
    return boxes.length;
}
