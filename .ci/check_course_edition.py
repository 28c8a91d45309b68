"""The course edition hides what it must, and the self-study edition still shows it.

Run after `make book` and `make book EDITION=course`:

    python .ci/check_course_edition.py [_build/course/html] [_build/html]

Over every text file of each build (pages, search index, the notebooks and sources
offered for download):

* no solution: no element of sphinx-exercise's ``solution`` class in the course
  edition, and no sentence of any chapter's solutions (each solution's longest run of
  plain words, read from notebooks/*.md); the self-study edition has them all;
* no key of an assessed exercise (book/assessed.yml): no answer box of it carrying its
  JSON key, and none of the key's JSON in any file; the self-study edition has each;
* the other answer boxes still check: each keeps its key in the course edition;
* no launch button (Binder, Colab) in the course edition, whose notebooks would be the
  repository's, with their solutions; the self-study edition has them.
"""

import html
import json
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "book" / "_ext"))
sys.path.insert(0, str(ROOT))

from editions import assessed, strip_solutions  # noqa: E402
from exercise_syntax import read_exercises  # noqa: E402

TEXT = (".html", ".js", ".ipynb", ".md", ".txt", ".json")
BOX = re.compile(
    r'<div class="sk-answer-box" id="sk-exercise-([a-z0-9_]+)-(\d+)-\d+"[^>]*>\s*'
    r'<script type="application/json">(.*?)</script>',
    re.S,
)
# what a launch button opens (sphinx-book-theme's header_buttons/launch.py): a notebook
# of the repository on Binder, Colab or a hub (nbgitpuller); a mere mention of the sites
# (the how-to page, sphinx-thebe's default settings) is not a button
LAUNCH = re.compile(
    r"mybinder\.org/v2/gh/|colab\.research\.google\.com/github/|/hub/user-redirect/git-pull"
)


def texts(folder):
    """Path -> text of every text file of a build."""
    out = {}
    for path in sorted(Path(folder).rglob("*")):
        if path.suffix in TEXT and path.is_file():
            out[path] = path.read_text(encoding="utf-8", errors="replace")
    return out


def plain(text):
    """A page's words: tags, entities, JSON escapes and white space flattened."""
    text = re.sub(r"<[^>]+>", " ", text)
    text = html.unescape(text).replace("\\n", " ").replace('\\"', '"')
    return re.sub(r"\s+", " ", text)


def probe(solution):
    """The longest run of plain words in a solution (no math, code or markup)."""
    body = re.sub(r"```.*?```", "\n", solution, flags=re.S)
    runs = re.findall(r"[A-Za-z][A-Za-z ,;']{24,}[A-Za-z]", body.replace("\n", " "))
    runs = [re.sub(r"\s+", " ", r) for r in runs if " " in r.strip()]
    return max(runs, key=len) if runs else None


def chapters():
    return sorted(p.stem for p in (ROOT / "notebooks").glob("*.md"))


def boxes(files):
    """(chapter, number) -> the JSON keys of its answer boxes found in the files."""
    found = {}
    for text in files.values():
        for chapter, number, payload in BOX.findall(text):
            found.setdefault((chapter, int(number)), set()).add(payload)
    return found


def check(course_dir, study_dir):
    course, study = texts(course_dir), texts(study_dir)
    assert course and study, "build both editions first"
    course_words = {p: plain(t) for p, t in course.items()}
    study_words = {p: plain(t) for p, t in study.items()}
    problems, probes = [], 0
    solutions = sum(t.count('class="solution') for t in study.values())
    hidden = [p for p, t in course.items() if 'class="solution' in t]
    if hidden:
        problems.append(f"solution elements in the course edition: {hidden[:3]}")
    for chapter in chapters():
        source = (ROOT / "notebooks" / f"{chapter}.md").read_text(encoding="utf-8")
        rest = re.sub(r"\s+", " ", strip_solutions(source))
        for exercise in read_exercises(source, chapter):
            words = probe(exercise["solution"] or "")
            shown = [p for p, t in study_words.items() if words and words in t]
            if not shown or words in rest or any(p.stem != chapter for p in shown):
                # no sentence of plain words, split by markup in the page, or not the
                # solution's own (the same words elsewhere in the book)
                continue
            probes += 1
            where = [p for p, t in course_words.items() if words in t]
            if where:
                problems.append(
                    f"{chapter} exercise {exercise['number']}: its solution "
                    f"({words!r}) is in {[str(p) for p in where[:3]]}"
                )
    marked = assessed()
    course_boxes, study_boxes = boxes(course), boxes(study)
    for chapter, number in sorted(marked):
        if (chapter, number) not in study_boxes:
            problems.append(f"{chapter} {number}: no answer box in the self-study book")
            continue
        if (chapter, number) in course_boxes:
            problems.append(f"{chapter} {number}: its key is in the course edition")
        for payload in study_boxes[(chapter, number)]:
            values = json.dumps(json.loads(payload)["values"])
            for path, text in course.items():
                if payload in text or (
                    "sk-exercise-" + chapter + "-" + str(number) + "-" in text
                    and values in text
                ):
                    problems.append(f"{chapter} {number}: its key is in {path}")
    launching = [p for p, t in course.items() if LAUNCH.search(t)]
    if launching:
        problems.append(f"launch buttons in the course edition: {launching[:3]}")
    launched = sum(bool(LAUNCH.search(t)) for t in study.values())
    if not launched:
        problems.append("no launch button in the self-study book: is it built?")
    kept = set(study_boxes) - marked
    lost = sorted(kept - set(course_boxes))
    if lost:
        problems.append(f"boxes that no longer check in the course edition: {lost}")
    return problems, {
        "solutions in the self-study book": solutions,
        "solution sentences checked": probes,
        "assessed exercises": len(marked),
        "answer boxes still checking": len(kept & set(course_boxes)),
        "self-study pages with launch buttons": launched,
    }


def main(argv):
    course_dir = argv[0] if argv else ROOT / "_build" / "course" / "html"
    study_dir = argv[1] if len(argv) > 1 else ROOT / "_build" / "html"
    problems, counts = check(course_dir, study_dir)
    for name, count in counts.items():
        print(f"{name}: {count}")
    if counts["solutions in the self-study book"] == 0:
        problems.append("the self-study book has no solution: is it built?")
    if counts["solution sentences checked"] < 50:
        problems.append("too few solution sentences found in the self-study book")
    for problem in problems:
        print("FAIL", problem)
    print("course edition: " + ("FAILED" if problems else "OK"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
