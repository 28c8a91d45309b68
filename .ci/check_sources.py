"""Check that every chapter has one source and that its code fits on a page.

Each chapter is a MyST Markdown notebook notebooks/NAME.md (what people edit) paired
with notebooks/NAME.ipynb (generated from it by `make notebooks`, stored with outputs).
Fails unless:
  - every .ipynb has its .md and every .md its .ipynb;
  - the .ipynb's cells equal the .md's: same cell types, sources and tags, in the same
    order;
  - no code line of a chapter is longer than 88 characters;
  - no code cell carries an nbval comment (nbval's cell tags do that job, unseen by
    readers);
  - every chapter with code opens with the cell that installs screwkit where it is
    missing (`if importlib.util.find_spec("screwkit") is None: %pip install ...`);
  - no printed output line of a stored notebook (streams, plain text shown as text) is
    longer than 88 characters, the page column's width in code characters;
  - no chapter's code (its code cells and the code blocks of its prose, such as the
    solutions) imports or uses a private name of screwkit: `screwkit._x`, `sk._x`, or
    `m._x` for a module m imported from screwkit (`parallel._parallel_search`);
  - no chapter's source contains a symbol that book/notation.md's section "One symbol
    per concept" lists as not used in this course (its tables' last column);
  - no chapter calls a library function for a result before it derives it once without
    that function (the table and its allow-list are in .ci/derive_first.py);
and, with --built DIR (the HTML book, e.g. _build/html), unless:
  - no page contains the text "NBVAL";
  - no code line of a code cell (its <pre> block) is longer than 88 characters.

Usage: python .ci/check_sources.py [--notebooks notebooks] [--built _build/html]
"""

import argparse
import ast
import glob
import os
import re
import sys
from html.parser import HTMLParser

import jupytext
import nbformat

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import derive_first  # noqa: E402  (a module of this folder)

MAX_LINE = 88
INSTALL_TEST = 'importlib.util.find_spec("screwkit") is None'
# what a page shows as text, not as HTML, an image or math
_RICH = (
    "text/html",
    "text/latex",
    "text/markdown",
    "image/png",
    "image/svg+xml",
    "image/jpeg",
)


def _inputs(cell):
    """What must agree between a notebook and its source: type, source and tags."""
    return cell.cell_type, cell.source, list(cell.metadata.get("tags", []))


def _compare(source_path, notebook_path):
    source, notebook = jupytext.read(source_path), nbformat.read(notebook_path, 4)
    problems = []
    for i, (want, got) in enumerate(zip(source.cells, notebook.cells)):
        (want_type, want_source, want_tags), (got_type, got_source, got_tags) = (
            _inputs(want),
            _inputs(got),
        )
        where = f"{notebook_path}: cell {i}"
        if want_type != got_type:
            problems.append(
                f"{where} is a {got_type} cell, {source_path} has a {want_type} cell"
            )
        elif want_source != got_source:
            problems.append(f"{where} ({got_type}): source differs from {source_path}")
        elif want_tags != got_tags:
            problems.append(f"{where}: tags {got_tags}, {source_path} has {want_tags}")
    if len(source.cells) != len(notebook.cells):
        problems.append(
            f"{notebook_path} has {len(notebook.cells)} cells, "
            f"{source_path} has {len(source.cells)}"
        )
    return problems


def _code_lines(source_path):
    """Long lines and nbval comments in the code cells of one MyST source."""
    text_lines = open(source_path, encoding="utf-8").read().splitlines()
    problems = []
    for i, cell in enumerate(jupytext.read(source_path).cells):
        if cell.cell_type != "code":
            continue
        for line in cell.source.splitlines():
            where = f"{source_path}:{_line_number(text_lines, line)}: cell {i}"
            if len(line) > MAX_LINE:
                problems.append(
                    f"{where}: code line of {len(line)} characters (at most {MAX_LINE})"
                )
            if "NBVAL" in line:
                problems.append(f"{where}: nbval comment; use the cell tag instead")
    return problems


def _installs_screwkit(source_path):
    """A problem unless the first code cell installs screwkit where it is missing."""
    code = [
        cell for cell in jupytext.read(source_path).cells if cell.cell_type == "code"
    ]
    if not code or (
        INSTALL_TEST in code[0].source and "%pip install" in code[0].source
    ):
        return []
    return [
        f"{source_path}: the first code cell does not install screwkit where it is "
        "missing (on Colab); copy the first code cell of another chapter "
        f"(`if {INSTALL_TEST}:` then `%pip install ...`)"
    ]


def _output_lines(notebook_path):
    """Printed output lines of a stored notebook wider than the page column."""
    problems = []
    for i, cell in enumerate(nbformat.read(notebook_path, 4).cells):
        for output in cell.get("outputs", []) if cell.cell_type == "code" else []:
            data = output.get("data", {})
            if output.output_type == "stream":
                text = output.get("text", "")
            elif output.output_type == "error":
                text = f"{output.get('ename', '')}: {output.get('evalue', '')}"
            elif not any(kind in data for kind in _RICH):
                text = data.get("text/plain", "")
            else:
                continue
            for line in text.splitlines():
                if len(line) > MAX_LINE:
                    problems.append(
                        f"{notebook_path}: cell {i}: output line of {len(line)} "
                        f"characters (at most {MAX_LINE}): {line[:40]}..."
                    )
    return problems


_FENCED = re.compile(r"^```[^\n]*\n(.*?)^```", re.DOTALL | re.MULTILINE)


def _code_blocks(source_path):
    """The code of a chapter: its code cells and the fenced blocks of its prose."""
    blocks = []
    for cell in jupytext.read(source_path).cells:
        if cell.cell_type == "code":
            blocks.append(cell.source)
        else:
            blocks += _FENCED.findall(cell.source)
    return blocks


def _private(name):
    """Whether an identifier is private (_x), not a dunder (__version__)."""
    return name.startswith("_") and not name.startswith("__")


def _private_uses(source_path):
    """Problems where a chapter's code imports or uses a private name of screwkit."""
    text_lines = open(source_path, encoding="utf-8").read().splitlines()
    trees = []
    for block in _code_blocks(source_path):
        lines = block.splitlines()
        python = "\n".join("" if ln.lstrip()[:1] in "%!" else ln for ln in lines)
        try:
            trees.append((ast.parse(python), lines))
        except SyntaxError:  # an example that is not Python: nothing to check
            continue
    screwkit = {"screwkit", "sk"}  # names that hold screwkit or one of its modules
    found = []
    for tree, lines in trees:
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                for alias in node.names:
                    if alias.name.split(".")[0] == "screwkit":
                        screwkit.add(alias.asname or "screwkit")
                        found += [(node, lines, alias.name)] * any(
                            _private(p) for p in alias.name.split(".")
                        )
            elif isinstance(node, ast.ImportFrom) and not node.level:
                module = node.module or ""
                if module.split(".")[0] != "screwkit":
                    continue
                if any(_private(p) for p in module.split(".")):
                    found.append((node, lines, module))
                for alias in node.names:
                    screwkit.add(alias.asname or alias.name)
                    if _private(alias.name):
                        found.append((node, lines, f"{module}.{alias.name}"))
    for tree, lines in trees:
        for node in ast.walk(tree):
            if isinstance(node, ast.Attribute) and _private(node.attr):
                root = node.value
                while isinstance(root, ast.Attribute):
                    root = root.value
                if isinstance(root, ast.Name) and root.id in screwkit:
                    found.append((node, lines, ast.unparse(node)))
    problems = []
    for node, lines, name in found:
        line = lines[node.lineno - 1]
        problems.append(
            f"{source_path}:{_line_number(text_lines, line)}: uses the private "
            f"`{name}`; a chapter imports and uses only screwkit's public names"
        )
    return problems


def _line_number(text_lines, line):
    """The 1-based number of `line` in the file (its first occurrence), or '?'."""
    for number, text in enumerate(text_lines, start=1):
        if text == line:
            return number
    return "?"


NOTATION_PAGE = os.path.join(os.path.dirname(__file__), "..", "book", "notation.md")


def notation_alternatives(page=NOTATION_PAGE):
    """The symbols the notation page lists as not used, as {symbol: concept}.

    They are the code spans of the last column of the tables that follow the heading
    "## One symbol per concept" (the second table, concept and the symbols not used,
    kept apart so that each table fits a phone): the page is the one place the list is
    kept.
    """
    with open(page, encoding="utf-8") as handle:
        text = handle.read()
    start = text.index("## One symbol per concept")
    end = text.find("\n## ", start + 1)
    alternatives = {}
    for line in text[start : end if end > 0 else None].splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 2 or set(cells[0]) <= set("-") or cells[0] == "concept":
            continue
        for symbol in re.findall(r"`([^`]+)`", cells[-1]):
            alternatives[symbol] = cells[0]
    return alternatives


def _notation_uses(source_path, alternatives):
    """Problems where a chapter writes a symbol the notation page does not use."""
    with open(source_path, encoding="utf-8") as handle:
        text_lines = handle.read().splitlines()
    return [
        f"{source_path}:{number}: writes {symbol} for the {concept}; book/notation.md "
        "uses one symbol per concept"
        for number, line in enumerate(text_lines, 1)
        for symbol, concept in alternatives.items()
        if symbol in line
    ]


def check_notebooks(folder):
    """Problems of the chapter sources in `folder`, as sentences (empty: all good)."""
    sources = {os.path.splitext(p)[0] for p in glob.glob(os.path.join(folder, "*.md"))}
    notebooks = {
        os.path.splitext(p)[0] for p in glob.glob(os.path.join(folder, "*.ipynb"))
    }
    problems = [
        f"{name}.ipynb has no MyST source {name}.md"
        for name in sorted(notebooks - sources)
    ]
    problems += [
        f"{name}.md has no notebook {name}.ipynb (run `make notebooks`)"
        for name in sorted(sources - notebooks)
    ]
    alternatives = notation_alternatives()
    for name in sorted(sources):
        problems += _notation_uses(name + ".md", alternatives)
        if name in notebooks:
            problems += _compare(name + ".md", name + ".ipynb")
            problems += _output_lines(name + ".ipynb")
        problems += _code_lines(name + ".md")
        problems += _installs_screwkit(name + ".md")
        problems += _private_uses(name + ".md")
    problems += derive_first.check_chapters(folder)
    return problems


class _CodeCellParser(HTMLParser):
    """Collects the text of the <pre> blocks inside the code-cell inputs of one page."""

    def __init__(self):
        super().__init__()
        self.cells = []  # one text per <pre> of a cell input
        self._div_depth = 0  # open <div>s since entering a cell input (0: outside one)
        self._in_pre = False

    def handle_starttag(self, tag, attrs):
        if tag == "div":
            classes = (dict(attrs).get("class") or "").split()
            if self._div_depth:
                self._div_depth += 1
            elif "cell_input" in classes:
                self._div_depth = 1
        elif tag == "pre" and self._div_depth:
            self._in_pre = True
            self.cells.append("")

    def handle_endtag(self, tag):
        if tag == "div" and self._div_depth:
            self._div_depth -= 1
        elif tag == "pre":
            self._in_pre = False

    def handle_data(self, data):
        if self._in_pre:
            self.cells[-1] += data


def check_built(folder):
    """Problems of the HTML pages under `folder`, as sentences (empty: all good)."""
    problems = []
    pages = sorted(glob.glob(os.path.join(folder, "**", "*.html"), recursive=True))
    if not pages:
        return [f"{folder} has no HTML pages: build the book first (make book)"]
    for page in pages:
        html = open(page, encoding="utf-8").read()
        if "NBVAL" in html:
            problems.append(f"{page}: contains the text NBVAL (use nbval's cell tags)")
        parser = _CodeCellParser()
        parser.feed(html)
        for i, text in enumerate(parser.cells):
            for line in text.splitlines():
                if len(line) > MAX_LINE:
                    problems.append(
                        f"{page}: code cell {i}: line of {len(line)} characters "
                        f"(at most {MAX_LINE}): {line[:40]}..."
                    )
    return problems


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--notebooks", default="notebooks", help="folder of the chapters"
    )
    parser.add_argument("--built", help="also check the HTML book in this folder")
    args = parser.parse_args(argv)
    problems = check_notebooks(args.notebooks)
    if args.built:
        problems += check_built(args.built)
    for problem in problems:
        print(problem)
    if problems:
        print(
            f"check_sources: {len(problems)} problem(s); `make notebooks` rebuilds the "
            "notebooks from their .md sources"
        )
        return 1
    print(
        "check_sources: sources, notebooks"
        + (" and built pages" if args.built else "")
        + " agree"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
