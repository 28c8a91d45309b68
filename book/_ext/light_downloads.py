"""Light downloads: the notebooks the download button offers, ready to run.

Each chapter's page offers its notebook (``_sources/notebooks/NAME.ipynb``). The copy
offered carries the chapter's text and code and no outputs, as the QuantEcon lectures'
downloads do: the page shows every output, and the notebook writes them anew when it
is run (Run All), the same outputs, as ``make test`` (strict nbval) checks. Stored
outputs in a download would mostly not work anyway: a downloaded notebook is untrusted,
and Jupyter runs no script of its stored outputs (the 3D viewers, the answer boxes,
the players of animations). The figures alone were some 4 MB of the book's copies.

The notebooks of the repository keep their outputs: the launch buttons (Binder, Colab,
a hub) open those, and ``make test`` checks them. This keeps the book under its size
limit (``.ci/site_check.py``).
"""

import json
import os


def light_notebook(notebook):
    """``notebook`` (a dict of nbformat) without its code cells' outputs and execution
    counts; changed in place and returned."""
    for cell in notebook.get("cells", []):
        if cell.get("cell_type") == "code":
            cell["outputs"] = []
            cell["execution_count"] = None
    notebook.get("metadata", {}).pop("widgets", None)  # the live widgets' state
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
