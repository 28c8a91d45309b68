"""Rebuild each chapter notebook from its MyST Markdown source, execute it, store its
outputs.

notebooks/NAME.md (jupytext's md:myst format) is what people edit; notebooks/NAME.ipynb
is generated from it, with the outputs nbval compares and Colab and Binder open. For
each chapter this script takes every cell (type, source, tags) from the .md, keeps the
.ipynb's cell ids where a cell is unchanged (so the diff shows only real changes),
clears every output, executes the notebook top to bottom and writes the .ipynb.

Usage: python tools/execute_notebooks.py [notebooks/NAME.md ...] (default: all chapters)
Run it (or `make notebooks`) after changing a chapter or screwkit, then review the diff.
"""

import glob
import os
import sys

import jupytext
import nbformat
from jupytext.combine import combine_inputs_with_outputs
from nbclient import NotebookClient


def sync(source_path):
    """The notebook of `source_path` (a .md): its cells, the old .ipynb's cell ids."""
    notebook = jupytext.read(source_path)
    notebook_path = os.path.splitext(source_path)[0] + ".ipynb"
    if os.path.exists(notebook_path):
        notebook = combine_inputs_with_outputs(
            notebook, nbformat.read(notebook_path, 4)
        )
    for cell in notebook.cells:
        cell.metadata.pop("execution", None)
        if cell.cell_type == "code":
            cell.outputs, cell.execution_count = [], None
    return notebook, notebook_path


def execute(source_path):
    notebook, notebook_path = sync(source_path)
    client = NotebookClient(
        notebook,
        timeout=600,
        kernel_name="python3",
        record_timing=False,
        resources={"metadata": {"path": os.path.dirname(notebook_path)}},
    )
    client.execute()
    # Widgets need a live kernel: the stored notebook keeps no widget state, the book
    # shows figures.
    notebook.metadata.pop("widgets", None)
    jupytext.write(notebook, notebook_path, fmt="ipynb")


if __name__ == "__main__":
    for path in sys.argv[1:] or sorted(glob.glob("notebooks/*.md")):
        if path.endswith(".ipynb"):
            path = path[: -len(".ipynb")] + ".md"
        print(f"executing {path}", flush=True)
        execute(path)
