"""Tiny helper for the chapter sources in this folder: md("...") and code("...") cells.

Each chapter source (tools/chapters/NAME.py) writes notebooks/NAME.ipynb without outputs;
then `python tools/execute_notebooks.py notebooks/NAME.ipynb` stores the outputs.
"""
import textwrap

import nbformat

KERNEL = {"kernelspec": {"display_name": "Python 3 (ipykernel)", "language": "python", "name": "python3"},
          "language_info": {"name": "python", "version": "3.11.7"}}


def md(text):
    return nbformat.v4.new_markdown_cell(textwrap.dedent(text).strip())


def code(text):
    return nbformat.v4.new_code_cell(textwrap.dedent(text).strip())


def write(cells, path):
    notebook = nbformat.v4.new_notebook(cells=cells, metadata=KERNEL)
    nbformat.write(notebook, path)
