# The two commands of the course: `make book` and `make test` (`make test-all`: every test).
# Both create .venv on first use and install requirements.txt (which installs screwkit).

# The course supports Python 3.11 to 3.13 (pyproject.toml): the first of python3.11, python3.12,
# python3.13 and python3 on PATH that is one of them, or choose with PYTHON=/path/to/python3.X.
SUPPORTED := import sys; sys.exit(not (3, 11) <= sys.version_info[:2] <= (3, 13))
PYTHON ?= $(firstword $(foreach p,python3.11 python3.12 python3.13 python3,\
            $(shell $(p) -c '$(SUPPORTED)' 2>/dev/null && command -v $(p))))
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
export PATH := $(abspath $(BIN)):$(PATH)
export PIP_DISABLE_PIP_VERSION_CHECK := 1

.PHONY: book answers test test-all lab site-check bench notebooks check-sources lint clean

$(STAMP): requirements.txt pyproject.toml
	@test -x $(BIN)/python || $(PYTHON) -c '$(SUPPORTED)' 2>/dev/null || { echo "make: .venv needs\
	 Python 3.11, 3.12 or 3.13; PYTHON is '$(PYTHON)': run make PYTHON=/path/to/python3.X" >&2; exit 1; }
	@test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --requirement requirements.txt
	@touch $(STAMP)

PYTEST := $(BIN)/python -m pytest
NBVAL  := $(PYTEST) --nbval notebooks --nbval-sanitize-with .nbval_sanitize.cfg -p no:cacheprovider

# $(call beside_nbval,COMMAND): strict nbval over every notebook in the background (its output
# kept, printed after), COMMAND in the foreground, one per core; fails if either failed.
define beside_nbval
@log=$$(mktemp); $(NBVAL) >"$$log" 2>&1 & nbval=$$!; \
echo "== strict nbval over every notebook runs beside these tests (its report follows them)"; \
$(1); tests=$$?; \
wait $$nbval; notebooks=$$?; \
echo "== strict nbval over every notebook:"; cat "$$log"; rm -f "$$log"; \
test $$tests -eq 0 && test $$notebooks -eq 0
endef

## make test: pytest over tests/ and screwkit's doctests, the fast tier (the slow tiers of
## tests/conftest.py, SLOW_TIERS, are left out and counted at the end), and beside it strict
## nbval over every notebook
test: $(STAMP)
	$(call beside_nbval,$(PYTEST) tests screwkit --doctest-modules --tier fast)

## make test-all: every test: `make test` and the slow tiers (60-digit ranks, certificates,
## Binder's pip resolve, which needs PyPI, the reference packages, Chromium's checks, slow
## sweeps). It installs the reference packages (tests/reference-requirements.txt into .venv;
## msolve and EAIK without their dependencies into .ci-nodeps, .ci/nodeps-requirements.txt
## says why) and Playwright (.ci/requirements.txt); a missing reference fails, never skips.
## Chromium's checks need the system Chromium (apt-get install chromium), else they skip
## and say so. make test-all TIER=slow runs only the slow tiers beside nbval: CI does, as
## its other lane runs `make test` (the fast tier) already.
TIER ?= all
test-all: $(STAMP)
	$(BIN)/python -m pip install --quiet --requirement tests/reference-requirements.txt \
	  --requirement .ci/requirements.txt
	$(BIN)/python -m pip install --quiet --no-deps --upgrade --target .ci-nodeps \
	  --requirement .ci/nodeps-requirements.txt
	$(call beside_nbval,PYTHONPATH=.ci-nodeps SCREWKIT_REFERENCES=required \
	  SCREWKIT_PROOF=required SCREWKIT_SLOW_TESTS=1 \
	  $(PYTEST) tests screwkit --doctest-modules --tier $(TIER))

## make book: the HTML book in _build/html, from the notebooks' stored outputs (`make test`
## checks them; `make notebooks` writes them); fails on any Sphinx warning
## make book EDITION=course: the course edition in _build/course/html, with no solution and no
## answer key of the exercises book/assessed.yml lists (book/_ext/editions.py)
EDITION ?= self-study
JB_BUILD = $(BIN)/jupyter-book build . --builder html --warningiserror --nitpick --keep-going
book: $(STAMP)
ifeq ($(EDITION),course)
	rm -rf _build/course/html _build/course-build
	SCREWKIT_EDITION=course $(JB_BUILD) --path-output _build/course-build
	@mkdir -p _build/course && mv _build/course-build/_build/html _build/course/html
	@echo "The course edition is built: _build/course/html/index.html (make answers: the keys)."
else ifeq ($(EDITION),self-study)
	$(JB_BUILD) --path-output .
	@echo "The book is built: open _build/html/index.html in a browser."
else
	@echo "make book: EDITION is '$(EDITION)'; expected self-study (the default) or course" >&2
	@exit 1
endif

## make answers: every exercise's statement, answer key and solution for the teacher, in
## _build/answers/answers.md and answers.html (the course edition has none of them);
## make answers SEEDS=class.csv (columns student,seed) also writes one sheet per student
## with their numbers of the parametrised exercises, _build/answers/sheets/STUDENT.md,
## and the teacher's keys of them all, _build/answers/keys.csv
answers: $(STAMP)
	$(BIN)/python tools/teacher_answers.py _build/answers $(if $(SEEDS),--seeds $(SEEDS))

## make site-check: serve _build/html on 127.0.0.1 and check every page in headless Chromium
## (Playwright for Python from .ci/requirements.txt; it drives the system Chromium, downloads none)
site-check: $(STAMP)
	$(BIN)/python -m pip install --quiet --requirement .ci/requirements.txt
	$(BIN)/python -m pytest .ci/test_viewer_browser.py .ci/test_site_check_math.py -q
	$(BIN)/python .ci/site_check.py _build/html

## make lab: JupyterLab on notebooks/, opened on the first chapter of _toc.yml (installs the
## JupyterLab that Binder pins into .venv on first use); options: make lab LAB_ARGS="--no-browser"
LAB_ARGS ?=
FIRST_CHAPTER = $(shell grep -m1 -o 'notebooks/[A-Za-z0-9_]*' _toc.yml).ipynb
lab: $(STAMP)
	@test -x $(BIN)/jupyter-lab || $(BIN)/python -m pip install --quiet \
	  "$$(grep -m1 '^jupyterlab==' binder/requirements.txt)"
	$(BIN)/jupyter-lab --ServerApp.root_dir=notebooks $(if $(filter 0,$(shell id -u)),--allow-root) \
	  $(LAB_ARGS) $(FIRST_CHAPTER)

## make bench: the speed tables of benchmarks/ (in .venv-bench, with the Robotics Toolbox beside screwkit),
## also written to benchmarks/results/ for the book
BENCH_STAMP := .venv-bench/.installed
$(BENCH_STAMP): requirements.txt benchmarks/requirements.txt pyproject.toml
	@test -x .venv-bench/bin/python || $(PYTHON) -m venv .venv-bench
	.venv-bench/bin/python -m pip install --quiet --requirement benchmarks/requirements.txt
	@touch $(BENCH_STAMP)

# Each script's tables also go to benchmarks/results/NAME.txt, headed by the date and the machine;
# the book's appendix "screwkit against other libraries" (book/benchmarks.md) prints those files.
BENCH_RESULTS := benchmarks/results
# a subset: make bench BENCH_SCRIPTS="benchmarks/bench_ik_general.py"
BENCH_SCRIPTS ?= benchmarks/bench_*.py
bench: $(BENCH_STAMP)
	@mkdir -p $(BENCH_RESULTS)
	@for script in $(BENCH_SCRIPTS); do \
	  out=$(BENCH_RESULTS)/$$(basename $$script .py).txt; echo "== $$script"; \
	  { echo "# $$script, measured $$(date -u '+%Y-%m-%d %H:%M UTC')"; \
	    echo "# on $$(uname -sm), $$(getconf _NPROCESSORS_ONLN) cores:\
	 $$(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo 2>/dev/null | head -1),\
	 load average $$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null),\
	 $$(.venv-bench/bin/python -c 'import platform; print("Python", platform.python_version())')"; \
	    echo; } > $$out.tmp; \
	  .venv-bench/bin/python $$script >> $$out.tmp 2>&1; status=$$?; cat $$out.tmp; \
	  if [ $$status -ne 0 ]; then rm -f $$out.tmp; echo "make bench: $$script failed" >&2; exit $$status; fi; \
	  mv $$out.tmp $$out; \
	done

clean:
	rm -rf _build

## make notebooks: rebuild each notebooks/NAME.ipynb from its MyST source NAME.md, execute it
## and store its outputs (review the diff after)
notebooks: $(STAMP)
	$(BIN)/python tools/execute_notebooks.py

## make lint: ruff (pinned in .ci/lint-requirements.txt) checks and format-checks every Python
## file of the repository, with the rules of pyproject.toml [tool.ruff]; then every public
## function, class and method of screwkit must have a numpydoc docstring (.ci/check_docstrings.py,
## numpydoc's validator, pinned there too; its own test first)
lint: $(STAMP)
	$(BIN)/python -m pip install --quiet --requirement .ci/lint-requirements.txt
	$(BIN)/ruff check .
	$(BIN)/ruff format --check .
	$(BIN)/python -m pytest -q -p no:cacheprovider .ci/test_check_docstrings.py
	$(BIN)/python .ci/check_docstrings.py

## make check-sources: every .ipynb's inputs equal its .md source; code lines at most 88 chars
check-sources: $(STAMP)
	$(BIN)/python .ci/check_sources.py
