"""Light downloads: the notebooks the download button offers, without dead weight.

Each chapter's page offers its notebook (``_sources/notebooks/NAME.ipynb``) with its
stored outputs. Two things in them weigh much and show nothing more:

* screwkit's scripts inside HTML outputs (three.js, 230 kB, and the viewers' script with
  the first 3D viewer of a chapter; the answer boxes' script with the first box). A
  downloaded notebook is untrusted: Jupyter runs no script of its stored outputs, so
  the viewer shows its note ("Waiting for the 3D library ...") until its cell is run,
  which writes the output, scripts and all, anew. The copies keep the viewers' data
  and their note, and drop the scripts.
* figures as matplotlib writes them (RGBA PNG): they are given a palette as the book's
  own images are (``light_pages.smaller_png``: lossless up to 256 colours, else at most
  ``MAX_MEAN_ERROR`` per channel on average), the frames of an animation too.

The notebooks of the repository are not touched: the launch buttons (Binder, Colab, a
hub) open those, and ``make test`` checks them. This keeps the book under its size
limit (``.ci/site_check.py``), 22 MB before.
"""

import base64
import json
import os

from light_pages import DATA_IMAGE, SCREWKIT_SCRIPT, smaller_png


def _png(data):
    """Base64 PNG data, with a palette where that keeps the figure."""
    smaller = smaller_png(base64.b64decode(data))
    return base64.b64encode(smaller).decode("ascii") if smaller else data


def _image_uri(match):
    kind, data = match.groups()
    return f"data:image/{kind};base64,{_png(data) if kind == 'png' else data}"


def _text(value):
    return "".join(value) if isinstance(value, list) else value


def light_output(output):
    """A code cell's output (a dict of nbformat) without screwkit's inline scripts and
    with smaller PNG figures; changed in place."""
    data = output.get("data") or {}
    if "image/png" in data:
        data["image/png"] = _png(_text(data["image/png"]).replace("\n", ""))
    if "text/html" in data:
        html = SCREWKIT_SCRIPT.sub("", _text(data["text/html"]))
        data["text/html"] = DATA_IMAGE.sub(_image_uri, html)


def light_notebook(notebook):
    for cell in notebook.get("cells", []):
        for output in cell.get("outputs", []):
            light_output(output)
    return notebook


def light_sources(app, exception):
    if exception is not None or app.builder.format != "html":
        return
    for folder, _, files in os.walk(os.path.join(app.outdir, "_sources")):
        for name in files:
            if not name.endswith(".ipynb"):
                continue
            path = os.path.join(folder, name)
            with open(path, encoding="utf-8") as f:
                notebook = json.load(f)
            with open(path, "w", encoding="utf-8") as f:
                json.dump(light_notebook(notebook), f, indent=1, ensure_ascii=False)


def setup(app):
    app.connect("build-finished", light_sources)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
