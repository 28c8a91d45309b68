"""The answer boxes' verdicts as the page computes them, run in Node.js: one driver for
the tests that compare them with Python's (``sk.exercises.check``)."""

import json
import shutil
import subprocess

from screwkit import exercises

#: The Node.js executable, or None (the tests that need it skip).
NODE = shutil.which("node")


def node_verdicts(cases):
    """[correct, message] of the page's verdict for each [text, key] of ``cases``, by
    ``window.screwkitExercises.verdict`` of the boxes' script."""
    program = (
        "global.window = {}; global.document = {querySelectorAll: () => []};\n"
        + exercises.exercises_script()
        + f"\nconst cases = {json.dumps(cases)};\n"
        "const out = cases.map(([t, key]) => {\n"
        "  const v = window.screwkitExercises.verdict(t, key);\n"
        "  return [v.correct, v.message]; });\n"
        "console.log(JSON.stringify(out));\n"
    )
    result = subprocess.run(  # the program on stdin: it may exceed argv's limit
        [NODE], input=program, capture_output=True, text=True, timeout=60, check=True
    )
    return json.loads(result.stdout)
