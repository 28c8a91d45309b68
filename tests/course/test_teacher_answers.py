"""tools/teacher_answers.py: answers.html stands alone. Its formulas are typeset by the
MathJax it carries (no file beside it, no network), checked in headless Chromium where
there is one (`make test-all`; the browser tier)."""

import importlib.util
import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def answers(tmp_path_factory):
    spec = importlib.util.spec_from_file_location(
        "teacher_answers", ROOT / "tools" / "teacher_answers.py"
    )
    module = importlib.util.module_from_spec(spec)
    sys.modules["teacher_answers"] = module
    spec.loader.exec_module(module)
    folder = tmp_path_factory.mktemp("answers")
    module.main(str(folder))
    return (folder / "answers.html").read_text(encoding="utf-8")


def test_answers_html_loads_nothing_from_elsewhere(answers):
    assert not re.search(r"<script[^>]*\bsrc=", answers)
    assert not re.search(r"<link[^>]*\bhref=", answers)
    assert answers.count("<script>") == 1 and "MathJax" in answers
    assert "\\(" in answers and "\\[" in answers  # formulas, inline and displayed


def test_answers_html_typesets_its_formulas_alone(answers, tmp_path, chromium):
    path = tmp_path / "copied" / "answers.html"  # copied alone, elsewhere
    path.parent.mkdir()
    path.write_text(answers, encoding="utf-8")
    page = chromium.new_page()
    requests = []
    page.on("request", lambda r: requests.append(r.url))
    page.goto(path.as_uri(), timeout=120_000)  # MathJax inline: slow under load
    page.wait_for_function(
        "window.MathJax && MathJax.startup && MathJax.startup.promise",
        timeout=60_000,
    )
    page.evaluate("MathJax.startup.promise")
    typeset = page.locator("mjx-container svg").count()
    errors = page.locator("mjx-merror").count()
    # the text left untypeset, code aside (MathJax skips <pre> and <code>)
    left = page.evaluate(
        "() => { const body = document.body.cloneNode(true);"
        " body.querySelectorAll('pre, code, mjx-container')"
        ".forEach(e => e.remove()); return body.textContent; }"
    )
    assert [url for url in requests if url != path.as_uri()] == []
    assert typeset > 100 and errors == 0
    assert "\\(" not in left and "\\[" not in left
