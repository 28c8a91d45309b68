"""The book's own tools: the API page's plan, the light pages' rewrites, the site
check's rules."""

import base64
import importlib.util
import json
import pathlib
import sys
import types

# The book's extensions need these: a course test, not run with screwkit alone.
import docutils  # noqa: F401
import fontTools  # noqa: F401
import matplotlib
import sphinx  # noqa: F401

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402
from matplotlib import animation  # noqa: E402

import screwkit as sk  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]


def load(path, name):
    spec = importlib.util.spec_from_file_location(name, ROOT / path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


site_check = load(".ci/site_check.py", "site_check")
api_reference = load("book/_ext/api_reference.py", "api_reference")
light_pages = load("book/_ext/light_pages.py", "light_pages")


# ---- the API page: one entry for every public name, by rule
# ---------------------------------


def test_every_public_name_has_an_entry_and_one_full_description():
    sections = api_reference.plan(sk)
    targets = [target for _, _, entries in sections for _, target, _ in entries]
    expected = {
        f"screwkit.{name}"
        for name in sk.__all__
        if not isinstance(getattr(sk, name), types.ModuleType)
    }
    for module in api_reference.public_modules(sk):
        expected |= {
            f"{module.__name__}.{name}" for name in api_reference.public_names(module)
        }
    assert set(targets) == expected and len(targets) == len(set(targets))
    homes = [
        alias or target for _, _, entries in sections for _, target, alias in entries
    ]
    assert set(homes) <= set(targets)  # every alias points at an entry of the page


def test_an_object_is_described_where_it_is_defined():
    homes = api_reference.documented_homes(sk)
    assert homes["screwkit.Chain"] == "screwkit.chains.Chain"
    home = "screwkit.ik.subproblems.subproblem1"
    assert homes["screwkit.ik.subproblem1"] == home
    assert homes["screwkit.ik.subproblems.subproblem1"] == home


def test_a_long_constant_value_leaves_the_signature_for_a_wrapping_block():
    # ik.dispatch.STRUCTURES in the signature line made the API page 489 px wide on a
    # 390 px phone: its value goes below, one entry a line, in the order tried
    lines = api_reference.value_lines(sk.ik.dispatch.STRUCTURES)
    assert lines[0] == "   :no-value:"
    start = lines.index("   .. code-block:: text") + 2
    body = [line.strip() for line in lines[start:]]
    assert len(body) == len(sk.ik.dispatch.STRUCTURES)
    for line, name in zip(body, sk.ik.dispatch.STRUCTURES):
        assert line.lstrip("{").startswith(repr(name))
    assert api_reference.value_lines(sk.parallel.RPR_BASE) == []  # short: stays


def test_the_modules_are_found_on_disk():
    names = {module.__name__ for module in api_reference.public_modules(sk)}
    on_disk = set()
    for path in (ROOT / "screwkit").rglob("*.py"):  # a folder's __init__: the folder
        parts = path.relative_to(ROOT).with_suffix("").parts
        name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
        public = not any(part.startswith("_") for part in name.split("."))
        if public and name != "screwkit":
            on_disk.add(name)
    assert names == on_disk


def test_norms_in_docstrings_are_escaped_and_code_and_tables_kept():
    lines = [
        "lambda = |V|^2 / 2, ``a | b`` stays",
        "| a table | row |",
    ]
    api_reference.escape_norms(None, "function", "f", None, {}, lines)
    assert lines == [
        "lambda = \\|V\\|^2 / 2, ``a | b`` stays",
        "| a table | row |",
    ]


# ---- light pages: frames as files, the cell's alt text
# -------------------------------------


def test_bland_alt_texts_are_found_and_given_ones_kept():
    def sub(text):
        return light_pages.BLAND_ALT.sub(
            lambda m: (
                f"alt={m.group(1)}NEW{m.group(1)}"
                if m.group(2)
                else f"alt={m.group(3)}NEW{m.group(3)}{m.group(5)}"
            ),
            text,
        )

    assert sub('<img alt="precomputed figure" src="x">') == '<img alt="NEW" src="x">'
    assert (
        sub('["<img alt=\\"precomputed figure\\" src=\\"x\\">"]')
        == '["<img alt=\\"NEW\\" src=\\"x\\">"]'
    )
    assert (
        sub('<img src="d" alt="An animation." width="1" data-alt="auto">')
        == '<img src="d" alt="NEW" width="1" data-alt="auto">'
    )
    given = '<img src="d" alt="The arm." width="1" data-alt="given">'
    assert sub(given) == given


def a_movie(frames=4):
    fig, ax = plt.subplots(figsize=(2, 1.5), dpi=40)
    (line,) = ax.plot([0, 1], [0, 1], label="arm")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("w (m$^2$)")
    ax.legend()

    def update(k):
        line.set_data([0, 1], [0, k])
        return (line,)

    movie = animation.FuncAnimation(fig, update, frames=frames, interval=100)
    return fig, movie


def test_animation_player_is_deterministic_labelled_and_lazy():
    fig, movie = a_movie(4)
    first, second = sk.plotting.animation_html(movie), sk.plotting.animation_html(movie)
    plt.close(fig)
    assert first == second  # no random id: the same frames give the same output
    assert 'aria-label="Frame of the animation"' in first
    assert 'alt="An animation of 4 frames: w (m\u00b2) against t (s) (arm)."' in first
    assert first.count("data:image/png;base64,") == 4
    frames = json.loads(
        first.split('class="screwkit-animation-frames">')[1].split("</script>")[0]
    )
    assert len(frames) == 3  # the others: the first frame is the image itself
    png = base64.b64decode(frames[0].split(",", 1)[1])
    assert png[:8] == b"\x89PNG\r\n\x1a\n"


def test_animation_alt_and_label_are_checked():
    fig, movie = a_movie(2)
    given = sk.plotting.animation_html(movie, alt="The arm climbs.", label="Time step")
    with pytest.raises(TypeError, match="alt"):
        sk.plotting.animation_html(movie, alt="  ")
    plt.close(fig)
    assert 'alt="The arm climbs."' in given and 'data-alt="given"' in given
    assert 'aria-label="Time step"' in given


def fake_build(outdir):
    """What scripts_to_files reads of Sphinx's app: the builder's format, the outdir."""
    return types.SimpleNamespace(
        builder=types.SimpleNamespace(format="html"), outdir=str(outdir)
    )


def a_doctree(*fragments):
    from docutils import nodes
    from docutils.utils import new_document

    document = new_document("page")
    for fragment in fragments:
        document += nodes.raw("", fragment, format="html")
    return document


def test_screwkit_scripts_become_one_file_each_loaded_in_place(tmp_path):
    from screwkit import viewer

    puma = sk.robots.puma560()
    first = viewer.robot_viewer(puma).html(library=True)
    steps = viewer.stepped_figure(str, "k", "1/s", values=viewer.grid(0, 1, 0.5))
    box = sk.exercises.answer_box("puma_fk", 2, script=True)._repr_html_()
    doctree = a_doctree(first, steps.html(), box)
    light_pages.scripts_to_files(fake_build(tmp_path), doctree, "notebooks/puma_fk")
    pages = [raw.astext() for raw in doctree.findall(lambda n: n.tagname == "raw")]
    folder = tmp_path / "_static" / "screwkit"
    files = {path.read_text(encoding="utf-8"): path.name for path in folder.iterdir()}
    # three scripts, each written once, byte for byte as screwkit inlines it
    assert set(files) == {
        viewer.library_script() + "\n",
        viewer.viewer_script(),
        sk.exercises.exercises_script(),
    }
    src = '<script src="../_static/screwkit/{}"></script>'.format
    assert src(files[viewer.library_script() + "\n"]) in pages[0]
    assert pages[0].index(src(files[viewer.viewer_script()])) < pages[0].index(
        "window.screwkit.mount("
    )  # viewer.js still runs before the figure's mount call
    assert "<script>\n" + viewer.viewer_script() not in "".join(pages)
    assert "screwkit viewer:" not in pages[1]  # the page's second copy is dropped
    assert 'type="application/json"' in pages[1]  # the stepped figure itself stays
    assert src(files[sk.exercises.exercises_script()]) in pages[2]


def test_the_widget_state_is_left_out_when_the_book_loads_no_widget_script():
    from sphinx.builders.html._assets import _JavaScript

    # as myst-nb adds them to the page's scripts (app.add_js_file in html-page-context)
    state = _JavaScript(
        None, type="application/vnd.jupyter.widget-state+json", body='{"state": {}}'
    )
    script = _JavaScript("_static/book.js", defer="defer")
    for widget_scripts, kept in (({"w.js": {}}, [script, state]), ({}, [script])):
        config = types.SimpleNamespace(nb_ipywidgets_js=widget_scripts)
        context = {"script_files": [script, state]}
        light_pages.no_widget_state(
            types.SimpleNamespace(config=config),
            "notebooks/a",
            "page.html",
            context,
            None,
        )
        assert context["script_files"] == kept


def test_figures_are_written_with_a_palette_only_when_that_keeps_them(tmp_path):
    import numpy as np
    from PIL import Image

    # a plot of 5 colours: written losslessly; a matplotlib figure (a viridis field, a
    # line, antialiased text: thousands of colours): quantised within the mean-error
    # bound; one with transparency: left alone
    flat = np.full((120, 200, 4), 255, np.uint8)
    for k, colour in enumerate(
        [(31, 119, 180), (255, 127, 14), (44, 160, 44), (0,) * 3]
    ):
        flat[20 + 20 * k : 30 + 20 * k, 10:190, :3] = colour
    clear = flat.copy()
    clear[:10, :10, 3] = 0
    for name, pixels in (("flat", flat), ("clear", clear)):
        Image.fromarray(pixels, "RGBA").save(tmp_path / f"{name}.png")
    fig, ax = plt.subplots(figsize=(4, 3), dpi=80)
    x = np.linspace(0, 3, 200)
    ax.pcolormesh(x, x, np.sin(x[:, None]) * np.cos(x[None, :]), cmap="viridis")
    ax.plot(x, 1.5 + np.sin(3 * x), color="red")
    ax.set_title("|det J| (m$^3$)")
    fig.savefig(tmp_path / "plot.png")
    plt.close(fig)
    plot = np.asarray(Image.open(tmp_path / "plot.png").convert("RGB"), dtype=float)
    assert Image.open(tmp_path / "plot.png").getcolors(256) is None  # > 256 colours
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    assert light_pages.shrink_png(str(tmp_path / "flat.png")) > 0
    assert light_pages.shrink_png(str(tmp_path / "plot.png")) > 0
    assert light_pages.shrink_png(str(tmp_path / "clear.png")) == 0
    assert (tmp_path / "clear.png").read_bytes() == before["clear.png"]
    flat_after = np.asarray(Image.open(tmp_path / "flat.png").convert("RGB"))
    assert (flat_after == flat[..., :3]).all()
    plot_after = np.asarray(Image.open(tmp_path / "plot.png").convert("RGB"))
    assert np.abs(plot_after - plot).mean() <= light_pages.MAX_MEAN_ERROR
    assert len((tmp_path / "plot.png").read_bytes()) < len(before["plot.png"]) / 2


# ---- the site check's static rules
# ----------------------------------------------------------


@pytest.mark.parametrize(
    "alt",
    [
        None,
        "",
        "precomputed figure",
        "../_images/ab12.png",
        "figure.png",
        "data:image/png;base64,AAAA",
    ],
)
def test_an_alt_text_that_says_nothing_fails(alt):
    attribute = "" if alt is None else f' alt="{alt}"'
    page = site_check.built_page(
        "notebooks/a.html", f'<img src="../_images/a.png"{attribute}>'
    )
    assert len(site_check.alt_texts_say_what_they_show(None, page)) == 1


def test_an_alt_text_that_describes_passes():
    page = site_check.built_page(
        "notebooks/a.html", '<img src="../_images/a.png" alt="The PUMA 560 at q = 0.">'
    )
    assert site_check.alt_texts_say_what_they_show(None, page) == []


def first_cell_problems(root, name):
    """The site check's rule on the first cell, for the page ``name`` of a build at
    ``root``."""
    site = site_check.Site(root=str(root), origin="", pages=[name], tmp="")
    page = site_check.built_page(name, "")
    return site_check.first_cell_installs_screwkit(site, page)


def write_notebook(root, page, first_source):
    path = pathlib.Path(root, "_sources", page.replace(".html", ".ipynb"))
    path.parent.mkdir(parents=True)
    cells = [
        {"cell_type": "markdown", "source": ["# A chapter"]},
        {"cell_type": "code", "source": first_source},
    ]
    path.write_text(json.dumps({"cells": cells}))


def test_a_chapter_whose_first_cell_installs_screwkit_passes(tmp_path):
    write_notebook(
        tmp_path,
        "notebooks/a.html",
        [
            'if importlib.util.find_spec("screwkit") is None:\n',
            '    %pip install --quiet "git+https://github.com/screwkit/x"',
        ],
    )
    assert first_cell_problems(tmp_path, "notebooks/a.html") == []


def test_a_chapter_without_the_install_cell_fails(tmp_path):
    write_notebook(tmp_path, "notebooks/a.html", ["import screwkit as sk"])
    assert len(first_cell_problems(tmp_path, "notebooks/a.html")) == 1
    assert first_cell_problems(tmp_path, "book/intro.html") == []


def test_only_folded_drawing_code_loses_its_colours():
    from docutils import nodes

    def cell(classes):
        return nodes.container(
            "",
            nodes.literal_block("x = 1", "x = 1", language="ipython3"),
            classes=classes,
        )

    folded = cell(["cell", "tag_hide-input"])
    shown = cell(["cell", "tag_nbval-ignore-output"])
    doctree = nodes.section("", folded, shown)
    light_pages.plain_folded_code(None, doctree, "notebooks/puma_ik")
    assert next(folded.findall(nodes.literal_block))["language"] == "none"
    assert next(shown.findall(nodes.literal_block))["language"] == "ipython3"


def test_spans_that_only_repeat_the_blocks_colour_are_unwrapped(tmp_path):
    css = (
        'html[data-theme="light"] .highlight { background: #fff; color: #080808 }\n'
        'html[data-theme="light"] .highlight .n { color: #080808 } /* Name */\n'
        'html[data-theme="light"] .highlight .k { color: #0000FF } /* Keyword */\n'
        'html[data-theme="light"] .highlight .p { color: #080808; font-weight: bold }\n'
        'html[data-theme="dark"] .highlight { background: #2b2b2b; color: #F8F8F2 }\n'
        'html[data-theme="dark"] .highlight .n { color: #F8F8F2 } /* Name */\n'
        'html[data-theme="dark"] .highlight .k { color: #F8F8F2 } /* Keyword */\n'
        'html[data-theme="dark"] .highlight .p { color: #F8F8F2 }\n'
    )
    # n is the block's colour in both themes; k only in the dark; p is bold too
    assert light_pages.plain_token_classes(css) == ["n"]
    (tmp_path / "_static").mkdir()
    (tmp_path / "_static" / "pygments.css").write_text(css, encoding="utf-8")
    code = (
        '<div class="highlight"><pre><span class="k">def</span> '
        '<span class="n">f</span><span class="p">(</span>&lt;x)</pre></div>'
    )
    prose = '<p><span class="n">kept outside code</span></p>'
    (tmp_path / "page.html").write_text(code + prose, encoding="utf-8")
    assert light_pages.unwrap_plain_tokens(str(tmp_path)) == len(
        '<span class="n"></span>'
    )
    assert (tmp_path / "page.html").read_text(encoding="utf-8") == (
        '<div class="highlight"><pre><span class="k">def</span> '
        'f<span class="p">(</span>&lt;x)</pre></div>' + prose
    )
