  // ---- page styles, once per document -----------------------------------------------
  var CSS = [
    ".screwkit-viewer{font:14px/1.4 system-ui,sans-serif;color:inherit;max-width:100%;",
    "margin:.5em 0}",
    ".screwkit-stage{position:relative;width:100%;background:#f7f8fa;",
    "border:1px solid #d8dce2;",
    "border-radius:6px;overflow:hidden;box-sizing:border-box}",
    ".screwkit-stage canvas{display:block;width:100%;height:100%;touch-action:pan-y;",
    "cursor:grab;outline:none}",
    ".screwkit-stage canvas:focus-visible{box-shadow:inset 0 0 0 3px #2b6cb0}",
    ".screwkit-labels{position:absolute;inset:0;pointer-events:none;overflow:hidden}",
    ".screwkit-labels span{position:absolute;transform:translate(-50%,-50%);",
    "font:600 12px/1 ",
    "system-ui,sans-serif;background:rgba(255,255,255,.88);color:#1a1a1a;",
    "border:1px solid #8a94a3;",
    "border-radius:9px;padding:2px 5px;white-space:nowrap}",
    ".screwkit-labels span.screwkit-bad{background:#fde2e1;border-color:#c53030;",
    "color:#9b2c2c}",
    ".screwkit-buttons{position:absolute;top:6px;right:6px;display:flex;gap:4px}",
    ".screwkit-buttons button{width:32px;height:32px;",
    "font:600 17px/1 system-ui,sans-serif;",
    "border:1px solid #9aa3ad;border-radius:5px;background:rgba(255,255,255,.92);",
    "color:#222;",
    "cursor:pointer;padding:0}",
    ".screwkit-caption{margin:.35em 0;font-variant-numeric:tabular-nums;",
    "min-height:2.8em}",
    ".screwkit-controls{display:grid;",
    "grid-template-columns:max-content minmax(5rem,1fr) ",
    "max-content max-content;gap:.15em .6em;align-items:center;max-width:40rem}",
    ".screwkit-controls label{font-weight:600;white-space:nowrap}",
    ".screwkit-controls input[type=range]{width:100%;min-width:0;margin:0;height:26px}",
    ".screwkit-controls output{text-align:right;font-variant-numeric:tabular-nums;",
    "font-family:ui-monospace,monospace;display:inline-block}",
    ".screwkit-controls .screwkit-unit{opacity:.75}",
    ".screwkit-controls .screwkit-play{grid-column:1/-1;justify-self:start;",
    "min-width:7em;min-height:32px;font:600 14px/1 system-ui,sans-serif;",
    "border:1px solid #9aa3ad;border-radius:5px;background:#fff;color:#222;",
    "cursor:pointer}",
    ".screwkit-frame img{max-width:100%;height:auto}",
    ".screwkit-note{padding:1em;opacity:.8}"
  ].join("");

  function addStyle() {
    if (document.getElementById("screwkit-viewer-style")) return;
    var style = document.createElement("style");
    style.id = "screwkit-viewer-style";
    style.textContent = CSS;
    (document.head || document.documentElement).appendChild(style);
  }

  function el(tag, attrs, parent) {
    var node = document.createElement(tag);
    Object.keys(attrs || {}).forEach(function (k) {
      node.setAttribute(k, attrs[k]);
    });
    if (parent) parent.appendChild(node);
    return node;
  }

