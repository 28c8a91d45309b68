"""The book's own checks: the site check's page rules and the bibliography's labels."""

import base64
import importlib.util
import json
import pathlib

import pytest
from pybtex.database import parse_string

ROOT = pathlib.Path(__file__).resolve().parents[2]


def load(path, name):
    spec = importlib.util.spec_from_file_location(name, ROOT / path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


site_check = load(".ci/site_check.py", "site_check")
bibliography_style = load("book/_ext/bibliography_style.py", "bibliography_style")


def chapter_shape(name, html):
    """The site check's rule on a chapter's shape, for the page ``name`` built as
    ``html``."""
    return site_check.chapter_has_its_shape(None, site_check.built_page(name, html))


CHAPTER = """<h1>A chapter</h1>
<div class="admonition tip"><p class="admonition-title">What you will learn</p></div>
<h2>Summary<a class="headerlink" href="#summary">#</a></h2>"""


def test_a_chapter_with_both_blocks_passes():
    assert chapter_shape("notebooks/a.html", CHAPTER) == []


def test_a_chapter_without_summary_fails():
    html = CHAPTER.replace("<h2>Summary", "<h2>Speed")
    assert chapter_shape("notebooks/a.html", html) == [
        'notebooks/a.html: a chapter without "Summary"'
    ]


def test_the_word_summary_in_prose_is_not_a_summary():
    html = CHAPTER.replace("<h2>Summary", "<h2>Speed") + "<p>In Summary, nothing.</p>"
    assert len(chapter_shape("notebooks/a.html", html)) == 1


def test_a_chapter_without_outcomes_fails_and_front_matter_is_exempt():
    html = CHAPTER.replace("What you will learn", "Overview")
    assert len(chapter_shape("notebooks/a.html", html)) == 1
    assert chapter_shape("book/intro.html", html) == []


def test_placeholder_launch_url_fails():
    page = site_check.built_page(
        "notebooks/a.html",
        '<a href="https://hub.example.edu/hub/user-redirect/git-pull?repo=x">'
        "JupyterHub</a>"
        '<a href="https://mybinder.org/v2/gh/screwkit/x/main">Binder</a>',
    )
    problems = site_check.no_placeholder_links(None, page)
    assert len(problems) == 1 and "hub.example.edu" in problems[0]


BIB = r"""
@article{three, author = {Surriani, Atikah and Arrofiq, Muhammad and Fahmizal},
  year = {2018}}
@book{two, author = {Lynch, Kevin M. and Park, Frank C.}, year = {2017}}
@book{one, author = {Craig, John J.}, year = {2005}}
@misc{anonymous, title = {A study}, shorthand = {CX210L study 2021}, year = {2021}}
@misc{undated, author = {Adriyan}}
@misc{nobody, title = {Nothing to go by}}
"""


@pytest.mark.parametrize(
    "key, label",
    [
        ("three", "Surriani et al. 2018"),
        ("two", "Lynch and Park 2017"),
        ("one", "Craig 2005"),
        ("anonymous", "CX210L study 2021"),
        ("undated", "Adriyan n.d."),
    ],
)
def test_author_year_labels(key, label):
    entry = parse_string(BIB, "bibtex").entries[key]
    assert bibliography_style.author_year_label(entry) == label


def test_an_entry_without_author_or_shorthand_is_refused():
    entry = parse_string(BIB, "bibtex").entries["nobody"]
    with pytest.raises(ValueError, match="'nobody' has no author, editor or shorthand"):
        bibliography_style.author_year_label(entry)


def test_the_four_source_papers_are_marked_and_labelled():
    entries = parse_string((ROOT / "book/references.bib").read_text(), "bibtex").entries
    sources = {
        key for key, e in entries.items() if e.fields.get("keywords") == "source"
    }
    assert len(sources) == 4
    labels = {bibliography_style.author_year_label(entries[key]) for key in sources}
    assert labels == {
        "Adriyan 2020",
        "Surriani et al. 2018",
        "CX210L study 2021",
        "Redundancy thesis n.d.",
    }
    text = (ROOT / "book/references.bib").read_text().lower()
    assert "seed" not in text and "2021, 2021" not in text


BOOK_COLUMN_PX = 688  # the book's content column at 1280 px (pydata-sphinx-theme)


def stored_figures():
    """(notebook, cell number, PNG bytes) of every figure stored in the chapter
    notebooks."""
    for path in sorted((ROOT / "notebooks").glob("*.ipynb")):
        cells = json.loads(path.read_text())["cells"]
        for k, cell in enumerate(cells):
            for output in cell.get("outputs", []):
                if "image/png" in output.get("data", {}):
                    yield path.name, k, base64.b64decode(output["data"]["image/png"])


def test_every_stored_figure_fits_the_book_column():
    # myst-nb shows a PNG at its natural size (one pixel a CSS pixel): wider than the
    # column, the browser shrinks it and its text with it. The width is bytes 16-19 of
    # the PNG header.
    figures = list(stored_figures())
    assert len(figures) >= 9  # every chapter shows at least one
    wide = [
        (name, k, int.from_bytes(png[16:20], "big"))
        for name, k, png in figures
        if int.from_bytes(png[16:20], "big") > BOOK_COLUMN_PX
    ]
    assert wide == []


def test_no_stored_figure_is_a_thumbnail():
    # A formula rendered as a tiny PNG (SymPy's LaTeX image) is blurry: show it as
    # MathJax.
    small = [
        (name, k)
        for name, k, png in stored_figures()
        if int.from_bytes(png[16:20], "big") < 100
    ]
    assert small == []


def mechanism_problems(root, name, figures):
    """The site check's rule on a mobility chapter's drawings, for the page ``name`` of
    a build at ``root`` showing ``figures``."""
    site = site_check.Site(root=str(root), origin="", pages=[name], tmp="")
    page = site_check.built_page(name, "", figures)
    return site_check.mechanisms_are_drawn(site, page)


def test_a_mobility_chapter_must_draw_every_mechanism(tmp_path):
    source = tmp_path / "_sources" / "notebooks" / "m.ipynb"
    source.parent.mkdir(parents=True)
    code = [
        "for build in (sk.robots.pm_3prrr, sk.robots.pm_6ups):\n",
        "    print(sk.mobility(build()).type)",
    ]
    source.write_text(json.dumps({"cells": [{"cell_type": "code", "source": code}]}))
    one, two = ["_images/a.png"], ["_images/a.png", "_images/b.png"]
    assert (
        "2 mechanisms analysed"
        in (mechanism_problems(tmp_path, "notebooks/m.html", one)[0])
    )
    assert mechanism_problems(tmp_path, "notebooks/m.html", two) == []
    # a chapter that builds mechanisms without analysing their mobility is not of that
    # kind
    source.write_text(
        json.dumps(
            {"cells": [{"cell_type": "code", "source": ["sk.robots.pm_3prrr()"]}]}
        )
    )
    assert mechanism_problems(tmp_path, "notebooks/m.html", []) == []
