"""Execute notebooks top to bottom and store their outputs (what nbval compares against).

Usage: python tools/execute_notebooks.py [notebooks/NAME.ipynb ...]   (default: all)
Run it (or `make notebooks`) after changing a chapter or screwkit, then review the diff.
"""
import glob
import os
import sys

import nbformat
from nbclient import NotebookClient


def execute(path):
    notebook = nbformat.read(path, as_version=4)
    client = NotebookClient(
        notebook,
        timeout=600,
        kernel_name="python3",
        resources={"metadata": {"path": os.path.dirname(path)}},
    )
    client.execute()
    # Widgets need a live kernel: the stored notebook keeps no widget state, the book shows figures.
    notebook.metadata.pop("widgets", None)
    nbformat.write(notebook, path)


if __name__ == "__main__":
    for path in sys.argv[1:] or sorted(glob.glob("notebooks/*.ipynb")):
        print(f"executing {path}", flush=True)
        execute(path)
