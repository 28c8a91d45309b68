"""Sliders in JupyterLab against a live kernel, in headless Chromium (a slider must move
the figure where students use it, not only in the built page).

Starts the JupyterLab of .venv headless on a free 127.0.0.1 port with a token of its
own, serving a temporary directory with a copy of the redundancy chapter
(its ipywidgets slider, the null-space gain, re-runs a resolution in Python) and a small
notebook with ``sk.widgets.joint_sliders`` and the in-page ``sk.viewer.robot_viewer``;
nothing under notebooks/ changes. The system Chromium, driven by Playwright, with every
host but 127.0.0.1 unresolvable, opens each in Lab, runs all its cells against the live
kernel, then:

- moves an ipywidgets slider with the keyboard and waits for the kernel's new figure
  (the PNG differs): the chapter's gain k, and the PUMA 560's q2;
- moves a slider of the in-page viewer (its script ran, as the output is trusted) and
  checks that its canvas and caption change;
- fails on any cell error or stderr output and on any error in the browser console.

Every wait is bounded; kernels and server are shut down (and checked gone) whatever
happens. Prints how long each step took; on failure, where a screenshot of the page was
saved. Usage: .venv/bin/python .ci/check_lab_live.py (needs .ci/requirements.txt and
JupyterLab in .venv: `make lab` installs it on first use).
"""

import json
import os
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
import urllib.error
import urllib.request
from contextlib import contextmanager
from pathlib import Path

import harness
import nbformat

try:
    from playwright.sync_api import Error as PlaywrightError
    from playwright.sync_api import TimeoutError as PlaywrightTimeout
except ImportError:
    sys.exit(
        "check_lab_live: FAILED: Playwright is not installed in this Python: "
        f"{sys.executable} -m pip install -r .ci/requirements.txt"
    )

ROOT = Path(__file__).resolve().parent.parent
BIN = Path(sys.executable).parent
TOTAL = float(
    os.environ.get("LAB_LIVE_TOTAL", 420)
)  # s: the watchdog ends the check after it
CHAPTER = "redundancy.ipynb"  # copied from notebooks/
NOTEBOOK = "live_sliders.ipynb"  # written here
CELLS = [
    "import numpy as np\nimport screwkit as sk\n\npuma = sk.robots.puma560()",
    "sk.widgets.joint_sliders(puma)",
    "sk.viewer.robot_viewer(puma, np.radians([0, -30, 20, 0, 30, 0]), ellipsoid=True)",
    (
        'print(f"live kernel: PUMA 560 tool z at home = '
        '{puma.fk(np.zeros(6))[2, 3]:.4f} m")'
    ),
]
STDERR = (
    '.jp-OutputArea-output[data-mime-type="application/vnd.jupyter.stderr"], '
    '.jp-OutputArea-output[data-mime-type="application/vnd.jupyter.error"]'
)


class CheckFailed(Exception):
    """One step of the check failed; the message says what was expected and what was
    seen."""


def log(message):
    print(f"check_lab_live: {message}", flush=True)


@contextmanager
def timed(name):
    start = time.monotonic()
    try:
        yield
    except Exception:
        log(f"{name}: FAILED after {time.monotonic() - start:.1f} s")
        raise
    log(f"{name}: {time.monotonic() - start:.1f} s")


def wait_until(condition, timeout, what, interval=0.5):
    """Poll ``condition()`` until it is true; CheckFailed naming ``what`` after
    ``timeout`` s."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if condition():
            return
        time.sleep(interval)
    raise CheckFailed(f"{what}: not seen within {timeout:.0f} s")


class Lab:
    """A headless JupyterLab on a free port, its state in ``home``
    (settings, runtime, kernels)."""

    def __init__(self, home):
        self.home = home
        self.token = secrets.token_hex(16)
        with socket.socket() as s:
            s.bind(("127.0.0.1", 0))
            self.port = s.getsockname()[1]
        self.url = f"http://127.0.0.1:{self.port}"
        self.log_path = home / "lab.log"
        self.process = None

    def start(self, timeout=180):
        lab = BIN / "jupyter-lab"
        if not lab.exists():
            raise CheckFailed(
                f"JupyterLab is not installed in {BIN.parent}: run `make lab` "
                "once, or pip install its pin from binder/requirements.txt"
            )
        env = dict(
            os.environ,
            JUPYTER_CONFIG_DIR=str(self.home / "config"),
            JUPYTER_DATA_DIR=str(self.home / "data"),
            JUPYTER_RUNTIME_DIR=str(self.home / "runtime"),
            JUPYTERLAB_SETTINGS_DIR=str(self.home / "settings"),
            JUPYTERLAB_WORKSPACES_DIR=str(self.home / "workspaces"),
            IPYTHONDIR=str(self.home / "ipython"),
        )
        env.pop(
            "MPLBACKEND", None
        )  # the kernel's own default, inline, as for a student
        args = [
            str(lab),
            "--no-browser",
            "--ip=127.0.0.1",
            f"--port={self.port}",
            "--port-retries=0",
            f"--IdentityProvider.token={self.token}",
            f"--ServerApp.root_dir={self.home / 'notebooks'}",
        ]
        if os.geteuid() == 0:
            args.append("--allow-root")  # as `make lab` does (containers, cloud VMs)
        with open(self.log_path, "w") as server_log:
            self.process = subprocess.Popen(
                args,
                env=env,
                stdout=server_log,
                stderr=subprocess.STDOUT,
                start_new_session=True,
            )

        def answers():
            if self.process.poll() is not None:
                raise CheckFailed(
                    f"JupyterLab exited with {self.process.returncode} before it "
                    f"answered:\n{self.server_log()}"
                )
            try:
                self.api("status")
                return True
            except (OSError, CheckFailed):
                return False

        wait_until(answers, timeout, f"JupyterLab answering on port {self.port}")

    def api(self, path, method="GET", timeout=10):
        request = urllib.request.Request(
            f"{self.url}/api/{path}",
            method=method,
            headers={"Authorization": f"token {self.token}"},
        )
        try:
            with urllib.request.urlopen(request, timeout=timeout) as answer:
                body = answer.read()
        except urllib.error.HTTPError as error:
            raise CheckFailed(f"{method} /api/{path} answered {error.code}") from None
        return json.loads(body) if body else None

    def kernel_pids(self):
        """Processes whose command line names a connection file of this server's runtime
        dir."""
        runtime = str(self.home / "runtime")
        pids = []
        for entry in Path("/proc").iterdir():
            if not entry.name.isdigit():
                continue
            try:
                cmdline = (entry / "cmdline").read_bytes().split(b"\0")
            except OSError:
                continue
            if any(
                part.decode(errors="replace").startswith(runtime) for part in cmdline
            ):
                pids.append(int(entry.name))
        return pids

    def stop(self, timeout=30):
        """Shut down kernels and server through the API; signals only if that fails."""
        if self.process is None:
            return
        if self.process.poll() is None:
            try:
                for session in self.api("sessions"):
                    self.api(f"sessions/{session['id']}", method="DELETE", timeout=30)
                self.api("shutdown", method="POST")
            except (OSError, CheckFailed) as error:
                log(f"shutdown through the API failed ({error}); sending SIGTERM")
                try:
                    os.killpg(self.process.pid, signal.SIGTERM)
                except ProcessLookupError:
                    pass
            try:
                self.process.wait(timeout)
            except subprocess.TimeoutExpired:
                log(f"JupyterLab did not stop within {timeout} s; sending SIGKILL")
                kill(self.process.pid, group=True)
                self.process.wait(10)
        left = self.kernel_pids()
        for pid in left:
            kill(pid)
        if left:
            raise CheckFailed(f"kernel processes {left} outlived the server; killed")

    def server_log(self, lines=40):
        text = self.log_path.read_text(errors="replace").splitlines()
        return "\n".join(text[-lines:])


def write_notebooks(folder):
    """The chapter's copy and the small notebook of CELLS in ``folder``; code cells of
    each."""
    folder.mkdir()
    shutil.copy(ROOT / "notebooks" / CHAPTER, folder / CHAPTER)
    notebook = nbformat.v4.new_notebook()
    notebook.cells = [nbformat.v4.new_code_cell(source) for source in CELLS]
    notebook.metadata["kernelspec"] = {
        "display_name": "Python 3 (ipykernel)",
        "language": "python",
        "name": "python3",
    }
    nbformat.write(notebook, folder / NOTEBOOK)
    chapter = nbformat.read(folder / CHAPTER, as_version=4)
    return {
        CHAPTER: sum(cell.cell_type == "code" for cell in chapter.cells),
        NOTEBOOK: len(CELLS),
    }


def open_notebook(page, lab, name, timeout=120):
    """Open ``name`` in Lab (a workspace of its own) and wait for its kernel to be
    idle."""
    page.goto(
        f"{lab.url}/lab/workspaces/{Path(name).stem}/tree/{name}?token={lab.token}",
        timeout=timeout * 1000,
    )
    page.locator(".jp-NotebookPanel .jp-Cell").first.wait_for(timeout=timeout * 1000)

    def kernel_idle():
        return any(
            s["path"] == name and s["kernel"]["execution_state"] == "idle"
            for s in lab.api("sessions")
        )

    wait_until(kernel_idle, timeout, f"the kernel of {name} idle")


def close_notebook(lab, name):
    """Shut down the kernel of ``name`` (its session), as File > Close and Shut Down
    does."""
    for session in lab.api("sessions"):
        if session["path"] == name:
            lab.api(f"sessions/{session['id']}", method="DELETE", timeout=30)


def check_no_errors(page, when):
    """CheckFailed quoting every error or stderr output of the notebook, if there is
    one."""
    errors = page.locator(STDERR)
    if errors.count():
        raise CheckFailed(
            f"{when}, {errors.count()} output(s) show an error or stderr:\n"
            + "\n".join(errors.all_inner_texts())[-3000:]
        )


def run_all_cells(page, count, timeout=240):
    """Run > Run All Cells; wait until every code cell shows its execution count
    (or errs)."""
    page.locator(".lm-MenuBar-item", has_text="Run").first.click()
    page.locator(
        "li.lm-Menu-item:has(.lm-Menu-itemLabel:text-is('Run All Cells'))"
    ).click()
    try:
        page.wait_for_function(
            """([n, errors]) => {
                const prompts = [...document.querySelectorAll('.jp-CodeCell .jp-InputPrompt')];
                return document.querySelector(errors) !== null || (prompts.length === n
                    && prompts.every(p => /\\[\\d+\\]/.test(p.textContent)));
            }""",  # noqa: E501 (JavaScript: its lines are the string's text)
            arg=[count, STDERR],
            timeout=timeout * 1000,
            polling=500,
        )
    except PlaywrightTimeout:
        prompts = page.locator(".jp-CodeCell .jp-InputPrompt").all_inner_texts()
        raise CheckFailed(
            f"the {count} code cells did not all run within {timeout} s; "
            f"their prompts: {prompts}"
        ) from None
    check_no_errors(page, "after Run All Cells")


def move_widget_slider(page, handles_expected=None, handle=0, timeout=90):
    """Move the ``handle``-th slider of the first ipywidget to its end with the
    keyboard.

    The kernel must answer with a different figure (PNG) in the widget's output. With
    ``handles_expected``, the widget must show that many sliders.
    """
    index = page.evaluate("""() => [...document.querySelectorAll('.jp-CodeCell')]
        .findIndex(c => c.querySelector('.widget-slider .noUi-handle') !== null)""")
    if index < 0:
        raise CheckFailed(
            "no ipywidgets slider in the notebook after running it "
            "(is the widget manager loaded?)"
        )
    cell = page.locator(".jp-CodeCell").nth(index)
    handles = cell.locator(".widget-slider .noUi-handle")
    if handles_expected is not None and handles.count() != handles_expected:
        raise CheckFailed(
            f"the widget should show {handles_expected} sliders in Lab, "
            f"found {handles.count()}"
        )
    figure_changed = """([index, before, errors]) => {
        const cell = document.querySelectorAll('.jp-CodeCell')[index];
        const img = cell.querySelector('.widget-output img');
        return cell.querySelector(errors) !== null || (img !== null && img.src !== before);
    }"""  # noqa: E501 (JavaScript: its lines are the string's text)
    page.wait_for_function(
        figure_changed, arg=[index, None, STDERR], timeout=timeout * 1000
    )
    check_no_errors(page, "drawing the widget's first figure")
    before = cell.locator(".widget-output img").first.get_attribute("src")
    slider, readout = handles.nth(handle), cell.locator(".widget-readout").nth(handle)
    label = cell.locator(".widget-slider .widget-label").nth(handle).inner_text()
    value = readout.inner_text()
    at_end = slider.get_attribute("aria-valuenow") == slider.get_attribute(
        "aria-valuemax"
    )
    slider.focus()
    start = time.monotonic()
    slider.press("Home" if at_end else "End")
    try:
        page.wait_for_function(
            figure_changed,
            arg=[index, before, STDERR],
            timeout=timeout * 1000,
            polling=50,
        )
    except PlaywrightTimeout:
        raise CheckFailed(
            f"moving the slider {label} from {value} to {readout.inner_text()} "
            f"brought no new figure from the kernel within {timeout} s"
        ) from None
    took = time.monotonic() - start
    check_no_errors(page, f"after moving the slider {label}")
    log(
        f"ipywidgets slider {label}: {value} -> {readout.inner_text()}; "
        f"the kernel's new figure arrived {took * 1000:.0f} ms after the key press"
    )


def move_page_viewer(page):
    """The in-page viewer mounted in Lab: q2 redraws canvas and caption; a drag
    orbits."""
    root = page.locator(".jp-CodeCell div.screwkit-viewer").first
    root.wait_for(state="attached", timeout=30_000)
    figure_id = root.get_attribute("id")
    mounted = page.evaluate(
        "id => Boolean(window.screwkit && window.screwkit.viewers[id])", figure_id
    )
    if not mounted or root.get_attribute("data-mounted") != "1":
        raise CheckFailed(
            "robot_viewer's output is in Lab but its script did not mount it "
            "(is the output trusted?)"
        )
    snapshot = "id => document.getElementById(id).querySelector('canvas').toDataURL()"
    before, caption = (
        page.evaluate(snapshot, figure_id),
        root.locator(".screwkit-caption"),
    )
    text = caption.inner_text()
    slider = root.locator("input[type=range]").nth(1)
    slider.focus()
    slider.press("Home")
    after = page.evaluate(snapshot, figure_id)
    if after == before or caption.inner_text() == text:
        raise CheckFailed(
            "moving the in-page viewer's q2 slider changed "
            f"{'neither the canvas nor' if after == before else 'not'} "
            "the caption"
        )
    box = root.locator("canvas").bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(x + 80, y + 30, steps=5)
    page.mouse.up()
    if page.evaluate(snapshot, figure_id) == after:
        raise CheckFailed(
            "dragging across the in-page viewer (orbit) did not redraw it in Lab"
        )
    log(
        f"in-page viewer: q2 -> {slider.input_value()} deg and a drag (orbit) "
        "redrew the canvas in Lab"
    )


def keep_screenshot(page):
    """Save what the browser showed when a step failed; the sentence that says where."""
    path = Path(tempfile.gettempdir()) / f"check_lab_live-{os.getpid()}.png"
    try:
        page.screenshot(path=path, full_page=True, timeout=10_000)
    except Exception:  # a screenshot is a help, never a second failure
        return ""
    return f"\n(the page at that moment: {path})"


def check_in_browser(lab, notebooks):
    """Each notebook in Lab: run all, move its sliders; then no error in the console."""
    console = []
    with harness.launch() as browser:
        page = browser.new_page(viewport={"width": 1280, "height": 1600})
        page.on("pageerror", lambda error: console.append(f"page error: {error}"))
        page.on("console", lambda m: m.type == "error" and console.append(m.text))
        try:
            for name, count in notebooks.items():
                with timed(f"{name}: open in Lab, kernel idle"):
                    open_notebook(page, lab, name)
                with timed(f"{name}: run its {count} code cells on the live kernel"):
                    run_all_cells(page, count)
                with timed(
                    f"{name}: move an ipywidgets slider, new figure from kernel"
                ):
                    if name == NOTEBOOK:
                        move_widget_slider(page, handles_expected=6, handle=1)
                    else:
                        move_widget_slider(page)
                if name == NOTEBOOK:
                    with timed(f"{name}: move the in-page viewer's slider"):
                        move_page_viewer(page)
                close_notebook(lab, name)
        except PlaywrightError as error:
            raise CheckFailed(
                f"the browser step failed: {error}{keep_screenshot(page)}"
            ) from None
        except CheckFailed as failure:
            raise CheckFailed(f"{failure}{keep_screenshot(page)}") from None
    if console:
        raise CheckFailed("the browser console logged errors:\n" + "\n".join(console))


def kill(pid, group=False):
    """SIGKILL a process (or its group) that this check started; gone already is
    fine."""
    try:
        (os.killpg if group else os.kill)(pid, signal.SIGKILL)
    except ProcessLookupError:
        pass


def watchdog(lab, seconds):
    """End the whole check (server and kernel included) if it runs longer than
    ``seconds``."""

    def expire():
        log(f"FAILED: the check did not finish within {seconds:.0f} s (LAB_LIVE_TOTAL)")
        if lab.process is not None:
            kill(lab.process.pid, group=True)
        for pid in lab.kernel_pids():
            kill(pid)
        shutil.rmtree(lab.home, ignore_errors=True)
        os._exit(2)  # Playwright's driver, its pipe closed, closes Chromium

    timer = threading.Timer(seconds, expire)
    timer.daemon = True
    timer.start()
    return timer


def main():
    if harness.CHROMIUM is None:
        log("FAILED: no Chromium on PATH (apt-get install chromium)")
        return 1
    start, failures = time.monotonic(), []
    with tempfile.TemporaryDirectory(prefix="lab-live-") as home:
        lab = Lab(Path(home))
        timer = watchdog(lab, TOTAL)
        try:
            notebooks = write_notebooks(lab.home / "notebooks")
            with timed(f"JupyterLab answers on port {lab.port}"):
                lab.start()
            check_in_browser(lab, notebooks)
        except CheckFailed as failure:
            failures.append(str(failure))
            if lab.process is not None:
                failures.append(
                    f"--- JupyterLab's log (last lines) ---\n{lab.server_log()}"
                )
        finally:
            try:
                with timed("shut down kernel and server"):
                    lab.stop()
            except CheckFailed as failure:
                failures.append(str(failure))
            timer.cancel()
    if failures:
        log("FAILED: " + "\n".join(failures))
        return 1
    log(f"passed in {time.monotonic() - start:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
