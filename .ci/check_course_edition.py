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
  repository's, with their solutions; the self-study edition has them;
* no button to the repository (sphinx-book-theme's repository, issues, source and edit
  buttons) and no link to it in the course edition: it holds the solutions and the
  teacher's keys (book/teacher_keys); the self-study edition has the button.

And, with no build (``--package`` runs only these), over what a student installs:

* the installed package holds no key of an assessed exercise: the files of the wheel
  pip builds (pyproject.toml's packages and package-data) have no ``answer`` of an
  assessed exercise, none of its keys' answer lines, and no teacher's file;
* the live path: with only those files on its path, a fresh Python's
  ``sk.exercises.check`` of an assessed exercise's right answer says that the teacher
  marks it, and its ``answer_box`` (HTML and plain text) carries no key and no way to
  check it; another exercise still checks (the harness is live).
"""

import html
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import tomllib
import zipfile
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "book" / "_ext"))
sys.path.insert(0, str(ROOT))

from convert_exercises import read_exercises  # noqa: E402
from editions import assessed, strip_solutions  # noqa: E402

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


# sphinx-book-theme's buttons to the repository (header_buttons/source.py: each link's
# class is btn-<label>, the group's dropdown-source-buttons)
REPOSITORY_BUTTON = re.compile(
    r"btn-source-(?:repository|issues|edit|file)-button|dropdown-source-buttons"
)


def repository_url(config=ROOT / "_config.yml"):
    """The repository's address, as _config.yml gives it to the theme."""
    with open(config, encoding="utf-8") as f:
        return yaml.safe_load(f)["repository"]["url"].rstrip("/")


def repository_links(files, url):
    """The files (of a build) with a button or a link to the repository."""
    link = re.compile(r'href="' + re.escape(url) + r'(?:[/?#."]|\.git)')
    return [
        p for p, t in files.items() if REPOSITORY_BUTTON.search(t) or link.search(t)
    ]


# ---- what a student installs ---------------------------------------------------------


def package_files(root=ROOT):
    """Relative path -> text of every text file setuptools puts in the package: the
    modules of pyproject.toml's packages and the files its package-data names."""
    with open(Path(root) / "pyproject.toml", "rb") as f:
        tool = tomllib.load(f)["tool"]["setuptools"]
    out = {}
    for package in tool["packages"]:
        folder = Path(root, *package.split("."))
        for path in folder.glob("*.py"):
            out[path.relative_to(root).as_posix()] = path.read_text(encoding="utf-8")
        for pattern in tool.get("package-data", {}).get(package, []):
            for path in folder.glob(pattern):
                if path.is_file():
                    text = path.read_text(encoding="utf-8", errors="replace")
                    out[path.relative_to(root).as_posix()] = text
    return out


def wheel_files(root=ROOT):
    """Relative path -> text of every file of the wheel pip builds from ``root`` (a
    copy of its pyproject.toml, README.md and screwkit/, so that the checkout gets no
    build folder): what ``pip install`` puts in a student's site-packages."""
    with tempfile.TemporaryDirectory() as work:
        source = Path(work, "source")
        source.mkdir()
        for name in ("pyproject.toml", "README.md"):
            shutil.copy(Path(root, name), source / name)
        shutil.copytree(
            Path(root, "screwkit"),
            source / "screwkit",
            ignore=shutil.ignore_patterns("__pycache__"),
        )
        subprocess.run(
            [sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation"]
            + ["--quiet", "--wheel-dir", str(Path(work, "dist")), str(source)],
            check=True,
            capture_output=True,
            timeout=600,
        )
        (wheel,) = Path(work, "dist").glob("*.whl")
        with zipfile.ZipFile(wheel) as archive:
            return {
                name: archive.read(name).decode("utf-8", errors="replace")
                for name in archive.namelist()
                if ".dist-info/" not in name and not name.endswith("/")
            }


def teacher_keys(folder=ROOT / "book" / "teacher_keys"):
    """(chapter, number) -> the teacher's key entry, from book/teacher_keys/*.toml."""
    keys = {}
    for path in sorted(Path(folder).glob("*.toml")):
        with open(path, "rb") as f:
            for number, entry in tomllib.load(f).get("exercise", {}).items():
                keys[path.stem, int(number)] = entry
    return keys


def answer_lines(text, number):
    """The lines of [exercise.NUMBER] in a key file's text (answer, alternatives)."""
    block = re.search(
        r"^\[exercise\." + str(number) + r"\]\n(.*?)(?=^\[|\Z)", text, re.S | re.M
    )
    if block is None:
        return []
    return [
        line.strip()
        for line in block.group(1).split("\n")
        if re.match(r"\s*(answer|alternatives)\s*=", line)
    ]


def package_leaks(files, marked, keys):
    """Problems: a key of an assessed exercise in the package's files (path -> text).
    ``keys`` is the teacher's (chapter, number) -> entry."""
    problems = []
    teacher = [p for p in files if "teacher_keys" in p]
    if teacher:
        problems.append(f"the teacher's keys are in the package: {teacher}")
    for chapter, number in sorted(marked):
        name = f"screwkit/answers/{chapter}.toml"
        if name in files:
            table = tomllib.loads(files[name]).get("exercise", {})
            entry = table.get(str(number), {})
            if "answer" in entry or "alternatives" in entry:
                problems.append(
                    f"{chapter} {number}: its key is in the package ({name})"
                )
        key = keys.get((chapter, number))
        if key is None:
            problems.append(f"{chapter} {number}: no teacher's key (book/teacher_keys)")
            continue
        source = f"[exercise.{number}]\n" + "\n".join(
            f"{k} = {json.dumps(v)}" for k, v in key.items() if k in ("answer",)
        )
        lines = answer_lines(source, number)
        for path, text in files.items():
            found = [line for line in lines if line in text]
            if found:
                problems.append(
                    f"{chapter} {number}: its key {found[0]!r} is in {path}"
                )
    return problems


LIVE = """
import json, sys
import screwkit as sk
trials = json.loads(sys.argv[1])
out = []
for chapter, number, answer in trials:
    verdict = sk.exercises.check(chapter, number, answer)
    box = sk.exercises.answer_box(chapter, number, script=False)
    out.append([verdict.correct, verdict.message, repr(box), box._repr_html_()])
print(json.dumps(out))
"""


def live_problems(files, trials, control):
    """Problems of the live path: a fresh Python with only the package's ``files``
    (path -> text) on its path checks the assessed exercises' right answers
    (``trials``: chapter, number, answer) and renders their boxes; ``control`` is a
    trial of an exercise that must still check."""
    problems = []
    with tempfile.TemporaryDirectory() as site:
        for path, text in files.items():
            target = Path(site, path)
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text(text, encoding="utf-8")
        env = {k: v for k, v in os.environ.items() if k != "SCREWKIT_TEACHER_KEYS"}
        env["PYTHONPATH"] = site
        run = subprocess.run(
            [sys.executable, "-c", LIVE, json.dumps([control, *trials])],
            capture_output=True,
            text=True,
            cwd=site,
            env=env,
            timeout=300,
        )
        if run.returncode != 0:
            return [f"the installed package fails: {run.stderr.strip()[-400:]}"]
        results = json.loads(run.stdout.strip().splitlines()[-1])
    if not results[0][0]:
        problems.append(f"the live check refuses a right answer: {control}")
    for (chapter, number, _), (correct, message, plain, page) in zip(
        trials, results[1:]
    ):
        where = f"{chapter} {number}"
        if correct or "teacher marks it" not in message:
            problems.append(f"{where}: the live check grades it: {message!r}")
        if "application/json" in page or "sk-answer-box" in page:
            problems.append(f"{where}: the live answer_box carries its key")
        if "assessed" not in plain or "sk.exercises.check" in plain:
            problems.append(f"{where}: the live box's text says how to check it")
    return problems


def check_package(root=ROOT):
    """Problems of what a student installs: the wheel's files, the live path."""
    marked, keys = assessed(), teacher_keys(Path(root) / "book" / "teacher_keys")
    files = wheel_files(root)
    problems = package_leaks(files, marked, keys)
    trials = []
    for chapter, number in sorted(marked):
        if (chapter, number) in keys:
            answer = keys[chapter, number]["answer"]
            text = ", ".join(answer) if isinstance(answer, list) else answer
            trials.append([chapter, number, re.sub(r"[\[\]]", "", str(text))])
    control = ["screws", 4, "0.5"]
    return problems + live_problems(files, trials, control)


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
    url = repository_url()
    linked = repository_links(course, url)
    if linked:
        problems.append(
            f"buttons or links to the repository in the course edition: "
            f"{[str(p) for p in linked[:3]]}"
        )
    if not repository_links(study, url):
        problems.append("no repository button in the self-study book: is it built?")
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
    if argv[:1] == ["--package"]:
        problems = check_package()
        for problem in problems:
            print("FAIL", problem)
        print("installed package: " + ("FAILED" if problems else "OK"))
        return 1 if problems else 0
    course_dir = argv[0] if argv else ROOT / "_build" / "course" / "html"
    study_dir = argv[1] if len(argv) > 1 else ROOT / "_build" / "html"
    problems, counts = check(course_dir, study_dir)
    for name, count in counts.items():
        print(f"{name}: {count}")
    if counts["solutions in the self-study book"] == 0:
        problems.append("the self-study book has no solution: is it built?")
    if counts["solution sentences checked"] < 50:
        problems.append("too few solution sentences found in the self-study book")
    problems += check_package()
    for problem in problems:
        print("FAIL", problem)
    print("course edition: " + ("FAILED" if problems else "OK"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
