"""book/_ext/kernel_transport.py: a chapter's kernel, started as `make book` starts it
(nbclient, no configuration), prints no "running over TCP without encryption" warning
once the extension is set up, and does without it (so the check can fail)."""

import subprocess
import sys
from pathlib import Path

import nbclient  # noqa: F401  # the book's executor: a course test

ROOT = Path(__file__).resolve().parents[2]

RUN = """
import sys
import nbclient, nbformat
if sys.argv[1] == "with":
    sys.path.insert(0, sys.argv[2])
    import kernel_transport
    kernel_transport.setup(None)
nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("print(6 * 7)")])
nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3",
                             "language": "python"}
nbclient.NotebookClient(nb, timeout=120).execute()
print(nb.cells[0].outputs[0]["text"].strip())
"""


def start_a_kernel(extension):
    return subprocess.run(
        [sys.executable, "-c", RUN, extension, str(ROOT / "book" / "_ext")],
        capture_output=True,
        text=True,
        check=True,
        timeout=300,
    )


def test_the_chapters_kernels_run_encrypted_and_do_not_warn():
    without, with_ = start_a_kernel("without"), start_a_kernel("with")
    assert without.stdout.strip() == with_.stdout.strip() == "42"
    assert "without encryption" in without.stderr
    assert "without encryption" not in with_.stderr, with_.stderr
