"""The CI check of .ci/check_sources.py: chapter sources and notebooks agree, code fits
a page."""

import importlib.util
import pathlib

import jupytext
import nbformat
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location(
    "check_sources", ROOT / ".ci" / "check_sources.py"
)
check_sources = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(check_sources)

SOURCE = """\
---
jupytext:
  formats: ipynb,md:myst
  text_representation:
    extension: .md
    format_name: myst
kernelspec:
  display_name: Python 3
  language: python
  name: python3
---

# A chapter

Some prose.

```{code-cell} ipython3
:tags: [hide-input]

import importlib.util

if importlib.util.find_spec("screwkit") is None:
    %pip install --quiet screwkit
```

```{code-cell} ipython3
x = 1 + 1
print(x)
```

```{code-cell} ipython3
:tags: [nbval-ignore-output]

print("a timing")
```
"""


@pytest.fixture
def chapter(tmp_path):
    """A folder with one chapter: its MyST source and the notebook made from it."""
    (tmp_path / "chapter.md").write_text(SOURCE)
    jupytext.write(jupytext.read(tmp_path / "chapter.md"), tmp_path / "chapter.ipynb")
    return tmp_path


def edit_notebook(folder, change):
    path = folder / "chapter.ipynb"
    notebook = nbformat.read(path, 4)
    change(notebook)
    nbformat.write(notebook, path)


def test_a_notebook_made_from_its_source_passes(chapter):
    assert check_sources.check_notebooks(str(chapter)) == []


def test_a_changed_cell_source_is_named_with_file_and_cell(chapter):
    def change(notebook):
        notebook.cells[2].source = "x = 1 + 2\nprint(x)"

    edit_notebook(chapter, change)
    problems = check_sources.check_notebooks(str(chapter))
    assert len(problems) == 1
    assert "chapter.ipynb: cell 2 (code): source differs from" in problems[0]
    assert "chapter.md" in problems[0]


def test_a_changed_tag_and_cell_type_and_count_are_caught(chapter):
    def change(notebook):
        notebook.cells[3].metadata["tags"] = []
        notebook.cells[2].cell_type = "markdown"
        notebook.cells.append(nbformat.v4.new_markdown_cell("extra"))

    edit_notebook(chapter, change)
    problems = "\n".join(check_sources.check_notebooks(str(chapter)))
    assert "cell 2 is a markdown cell" in problems
    assert "cell 3: tags []" in problems and "nbval-ignore-output" in problems
    assert "chapter.ipynb has 5 cells" in problems and "has 4" in problems


def test_a_notebook_without_source_and_a_source_without_notebook(tmp_path, chapter):
    (chapter / "chapter.md").rename(chapter / "other.md")
    problems = check_sources.check_notebooks(str(chapter))
    assert any("chapter.ipynb has no MyST source" in p for p in problems)
    assert any("other.md has no notebook" in p for p in problems)


def test_a_long_code_line_and_an_nbval_comment_are_caught(chapter):
    long_line = (
        "y = [" + ", ".join(["1000"] * 16) + "]"
    )  # 5 + 16 * 6 - 2 + 1 = 100 chars
    assert len(long_line) == 100
    source = SOURCE.replace("x = 1 + 1", long_line).replace(
        'print("a timing")', '# NBVAL_IGNORE_OUTPUT\nprint("a timing")'
    )
    (chapter / "chapter.md").write_text(source)
    jupytext.write(jupytext.read(chapter / "chapter.md"), chapter / "chapter.ipynb")
    problems = check_sources.check_notebooks(str(chapter))
    assert len(problems) == 2
    line = source.splitlines().index(long_line) + 1
    assert f"chapter.md:{line}: cell 2: code line of 100 characters" in problems[0]
    assert "cell 3: nbval comment" in problems[1]


def test_a_line_of_exactly_88_characters_passes(chapter):
    line = "z = " + "1" * 84
    assert len(line) == 88
    (chapter / "chapter.md").write_text(SOURCE.replace("x = 1 + 1", line))
    jupytext.write(jupytext.read(chapter / "chapter.md"), chapter / "chapter.ipynb")
    assert check_sources.check_notebooks(str(chapter)) == []


def page(code, prose="A page."):
    """A built page in the shape Jupyter Book gives a code cell."""
    return (
        f"<html><body><p>{prose}</p>"
        '<div class="cell docutils container">'
        '<div class="cell_input docutils container">'
        '<div class="highlight-ipython3 notranslate"><div class="highlight"><pre>'
        f"{code}</pre></div></div></div>"
        '<div class="cell_output docutils container">'
        '<div class="output stream highlight-myst-ansi'
        ' notranslate"><div class="highlight"><pre><span></span>' + "9" * 120 + "</pre>"
        "</div></div></div></div></body></html>"
    )


def test_built_pages_with_nbval_text_or_long_code_lines_fail(tmp_path):
    (tmp_path / "notebooks").mkdir()
    short = (
        '<span class="n">x</span> <span class="o">=</span> <span class="mi">1</span>'
    )
    (tmp_path / "notebooks" / "good.html").write_text(page(short))
    (tmp_path / "notebooks" / "plumbing.html").write_text(
        page("<span># NBVAL_IGNORE_OUTPUT</span>\nx = 1")
    )
    long_code = (
        "x = [" + ", ".join(["&quot;ab&quot;"] * 20) + "]"
    )  # 5 + 20 * 6 - 2 + 1 = 124
    (tmp_path / "notebooks" / "wide.html").write_text(page("y = 2\n" + long_code))
    problems = check_sources.check_built(str(tmp_path))
    assert len(problems) == 2, problems
    assert "plumbing.html: contains the text NBVAL" in problems[0]
    assert "wide.html: code cell 0: line of 124 characters" in problems[1]


def test_long_outputs_and_the_word_nbval_in_lower_case_are_not_code(tmp_path):
    (tmp_path / "intro.html").write_text(page("x = 1", prose="run by nbval in CI"))
    assert check_sources.check_built(str(tmp_path)) == []


def test_an_empty_build_folder_is_reported(tmp_path):
    assert "has no HTML pages" in check_sources.check_built(str(tmp_path))[0]


def _write(folder, source):
    (folder / "chapter.md").write_text(source)
    jupytext.write(jupytext.read(folder / "chapter.md"), folder / "chapter.ipynb")


def test_a_chapter_whose_first_code_cell_does_not_install_screwkit_is_named(chapter):
    start = SOURCE.index("```{code-cell} ipython3\n:tags: [hide-input]")
    end = SOURCE.index("```{code-cell} ipython3\nx = 1 + 1")
    install = SOURCE[start:end]
    _write(chapter, SOURCE.replace(install, ""))  # no install cell at all
    problems = check_sources.check_notebooks(str(chapter))
    assert len(problems) == 1, problems
    assert "chapter.md: the first code cell does not install screwkit" in problems[0]
    moved = SOURCE.replace(install, "").replace(
        "Some prose.\n", "Some prose.\n\n" + install
    )
    _write(
        chapter,
        moved.replace(
            'print("a timing")\n```\n', 'print("a timing")\n```\n\n' + install
        ),
    )
    assert check_sources.check_notebooks(str(chapter)) == []  # first again: passes
    late = SOURCE.replace(install, "") + "\n" + install  # present, but not first
    _write(chapter, late)
    assert "does not install screwkit" in check_sources.check_notebooks(str(chapter))[0]


def test_a_chapter_without_code_needs_no_install_cell(tmp_path):
    _write(tmp_path, SOURCE[: SOURCE.index("```{code-cell}")])
    assert check_sources.check_notebooks(str(tmp_path)) == []


def test_a_printed_output_line_wider_than_the_column_is_named(chapter):
    def change(notebook):
        notebook.cells[2].outputs = [
            nbformat.v4.new_output("stream", text="ok\n" + "9" * 89)
        ]
        notebook.cells[3].outputs = [
            nbformat.v4.new_output(
                "execute_result", data={"text/plain": "8" * 89}, execution_count=1
            )
        ]
        notebook.cells[3].outputs.append(
            nbformat.v4.new_output(  # HTML is shown instead
                "display_data", data={"text/plain": "7" * 120, "text/html": "<b>x</b>"}
            )
        )

    edit_notebook(chapter, change)
    problems = check_sources.check_notebooks(str(chapter))
    assert len(problems) == 2, problems
    assert (
        "chapter.ipynb: cell 2: output line of 89 characters (at most 88)"
        in problems[0]
    )
    assert "chapter.ipynb: cell 3: output line of 89 characters" in problems[1]


def test_an_output_line_of_exactly_88_characters_passes(chapter):
    edit_notebook(
        chapter,
        lambda nb: nb.cells[2].outputs.append(
            nbformat.v4.new_output("stream", text="9" * 88 + "\n")
        ),
    )
    assert check_sources.check_notebooks(str(chapter)) == []


def test_the_repository_chapters_pass(capsys):
    assert check_sources.main(["--notebooks", str(ROOT / "notebooks")]) == 0
    assert "agree" in capsys.readouterr().out


@pytest.mark.parametrize(
    "code, private",
    [
        ("from screwkit._parallel_plot import draw_planar", "screwkit._parallel_plot"),
        ("import screwkit._checks as checks", "screwkit._checks"),
        ("from screwkit import _numeric", "screwkit._numeric"),
        ("import screwkit as sk\nsk._numeric.snap(1.0)", "sk._numeric"),
        (
            "from screwkit import parallel\n"
            "parallel._parallel_search.rpr_sextic(None, (1, 1, 1))",
            "parallel._parallel_search",
        ),
        ("import screwkit.parallel as par\npar._search", "par._search"),
    ],
)
def test_a_chapter_using_a_private_name_of_screwkit_is_named(chapter, code, private):
    source = SOURCE.replace("x = 1 + 1\n", code + "\nx = 1 + 1\n")
    _write(chapter, source)
    problems = check_sources.check_notebooks(str(chapter))
    assert len(problems) == 1, problems
    assert f"uses the private `{private}`" in problems[0]
    line = code.splitlines()[-1]
    assert problems[0].startswith(
        f"{chapter / 'chapter.md'}:{source.splitlines().index(line) + 1}:"
    )


def test_a_private_name_in_a_solution_block_of_the_prose_is_named(chapter):
    solution = (
        ":::{admonition} Solution\n:class: dropdown\n```python\n"
        "poses = parallel._parallel_search.rpr_sextic(rpr, rho)\n```\n:::\n"
    )
    source = SOURCE.replace(
        "x = 1 + 1\n", "from screwkit import parallel\nx = 1 + 1\n"
    ).replace("Some prose.\n", "Some prose.\n\n" + solution)
    _write(chapter, source)
    problems = check_sources.check_notebooks(str(chapter))
    assert [p.split(": ", 1)[1] for p in problems] == [
        "uses the private `parallel._parallel_search`; a chapter imports and uses "
        "only screwkit's public names"
    ]


def test_public_names_dunders_and_other_packages_privates_pass(chapter):
    code = (
        "import numpy as np\nimport screwkit as sk\n"
        "from screwkit.parallel.plotting import draw_spatial\n"
        "print(sk.__version__, sk.parallel.rpr_sextic, np._NoValue)\n"
        "values = {}\nvalues._private = 1\n"
    )
    _write(chapter, SOURCE.replace("x = 1 + 1\n", code + "x = 1 + 1\n"))
    assert check_sources.check_notebooks(str(chapter)) == []


def test_the_notation_page_lists_the_alternatives_it_does_not_use():
    alternatives = check_sources.notation_alternatives()
    # three ways of writing a joint screw, the DH link transform as A: one symbol per
    # concept (book/notation.md)
    for symbol in (r"\xi", r"\$", r"{}^{i-1}A_i", r"\operatorname{Ad}"):
        assert symbol in alternatives
    assert alternatives[r"\xi"].startswith("screw")


@pytest.mark.parametrize(
    "line, symbol",
    [
        (r"The joint screw $\xi_1 = (\omega_1; v_1)$.", r"\xi"),
        (r"$$ {}^{i-1}A_i = R_z(\theta_i) $$", r"{}^{i-1}A_i"),
        (r"twists $\$_i$ of the joints", r"\$"),
    ],
)
def test_a_chapter_writing_an_unused_symbol_is_named(chapter, line, symbol):
    path = chapter / "chapter.md"
    path.write_text(path.read_text().replace("Some prose.", line))
    jupytext.write(jupytext.read(path), chapter / "chapter.ipynb")
    problems = check_sources.check_notebooks(str(chapter))
    assert len(problems) == 1, problems
    assert f"chapter.md:15: writes {symbol} for the" in problems[0]
    assert "book/notation.md" in problems[0]


# Derive, then call: .ci/derive_first.py, run by check_notebooks.
_spec = importlib.util.spec_from_file_location(
    "derive_first", ROOT / ".ci" / "derive_first.py"
)
derive_first = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(derive_first)

ROW = ("chapter", "lib.f", r"lib\.f\(", r"def my_f\(", None)
DERIVE = "def my_f(x):\n    return 2 * x\n"
CALL = "print(lib.f(3))\n"


def myst(*cells, prose=""):
    """A chapter text: a heading, then one code cell per source, then `prose`."""
    body = "".join(f"```{{code-cell}} ipython3\n{cell}```\n\n" for cell in cells)
    return "# A chapter\n\n" + body + prose


def line_of(text, code):
    """The 1-based line of the first line of `code` in `text`, found by hand."""
    return text.splitlines().index(code.splitlines()[0]) + 1


def run(texts, table=(ROW,), allowed=None, order=("early", "chapter", "late")):
    return derive_first.check(texts, list(order), list(table), allowed or {})


def test_the_repository_chapters_derive_before_they_call():
    assert derive_first.check_chapters(str(ROOT / "notebooks")) == []
    chapters = derive_first.toc_chapters()
    for chapter, _name, _, _, derived_in in derive_first.DERIVED_FIRST:
        assert chapter in chapters and (derived_in is None or derived_in in chapters)
    for key, reason in derive_first.ALLOWED_EARLY.items():
        assert key in {row[:2] for row in derive_first.DERIVED_FIRST}
        assert len(reason) > 20


def test_a_call_before_the_derivation_is_named_with_its_line():
    text = myst(CALL, DERIVE)
    problems = run({"chapter": text})
    assert len(problems) == 1, problems
    assert problems[0].startswith(f"notebooks/chapter.md:{line_of(text, CALL)}: ")
    assert "calls lib.f before the chapter derives it" in problems[0]
    assert f"notebooks/chapter.md:{line_of(text, DERIVE)}" in problems[0]


def test_a_call_after_the_derivation_passes_in_the_next_cell_or_the_same_one():
    assert run({"chapter": myst(DERIVE, CALL)}) == []
    assert run({"chapter": myst(DERIVE + CALL)}) == []
    assert len(run({"chapter": myst(CALL + DERIVE)})) == 1


def test_a_derivation_only_in_a_solution_block_or_prose_does_not_count():
    solution = f"```python\n{DERIVE}```\n"
    problems = run({"chapter": myst(CALL, prose=solution)})
    assert len(problems) == 1 and "has no code matching" in problems[0]


def test_a_derivation_in_an_earlier_chapter_counts_and_in_a_later_one_does_not():
    def row(where):
        return [(*ROW[:4], where)]

    texts = {"early": myst(DERIVE), "chapter": myst(CALL), "late": myst(DERIVE)}
    assert run(texts, row("early")) == []
    assert len(run(texts, row("late"))) == 1
    assert len(run({"early": myst(CALL), "chapter": myst(CALL)}, row("early"))) == 1


def test_the_allow_list_excuses_an_early_call_and_reports_itself_when_stale():
    allowed = {("chapter", "lib.f"): "a figure helper drawn before the topic"}
    assert run({"chapter": myst(CALL, DERIVE)}, allowed=allowed) == []
    stale = run({"chapter": myst(DERIVE, CALL)}, allowed=allowed)
    assert (
        len(stale) == 1
        and "remove ('chapter', 'lib.f') from ALLOWED_EARLY" in (stale[0])
    )


def test_a_row_whose_call_the_chapter_no_longer_makes_is_reported():
    problems = run({"chapter": myst(DERIVE)})
    assert len(problems) == 1 and "no code cell calls lib.f" in problems[0]
