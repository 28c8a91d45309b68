# The two commands of the course: `make book` and `make test`.
# Both create .venv on first use and install requirements.txt (which installs screwkit).

PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
export PATH := $(CURDIR)/$(BIN):$(PATH)
export PIP_DISABLE_PIP_VERSION_CHECK := 1

.PHONY: book test lab site-check bench notebooks clean

$(STAMP): requirements.txt pyproject.toml
	@test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --requirement requirements.txt
	@touch $(STAMP)

## make test: pytest over tests/, screwkit's doctests and strict nbval over every notebook
test: $(STAMP)
	$(BIN)/python -m pytest tests screwkit --doctest-modules
	$(BIN)/python -m pytest --nbval notebooks --nbval-sanitize-with .nbval_sanitize.cfg -p no:cacheprovider

## make book: the HTML book in _build/html (fails on any cell error or Sphinx warning)
book: $(STAMP)
	$(BIN)/jupyter-book build . --path-output . --builder html --warningiserror --nitpick --keep-going
	@echo "The book is built: open _build/html/index.html in a browser."

## make site-check: serve _build/html on 127.0.0.1 and check every page in headless Chromium
site-check: $(STAMP)
	$(BIN)/python .ci/site_check.py _build/html

## make lab: JupyterLab on the notebooks (installs JupyterLab into .venv on first use)
lab: $(STAMP)
	@test -x $(BIN)/jupyter-lab || $(BIN)/python -m pip install --quiet "jupyterlab>=4,<5"
	$(BIN)/jupyter-lab notebooks

## make bench: the speed tables of benchmarks/ (in .venv-bench, with the Robotics Toolbox beside screwkit)
BENCH_STAMP := .venv-bench/.installed
$(BENCH_STAMP): requirements.txt benchmarks/requirements.txt pyproject.toml
	@test -x .venv-bench/bin/python || $(PYTHON) -m venv .venv-bench
	.venv-bench/bin/python -m pip install --quiet --requirement benchmarks/requirements.txt
	@touch $(BENCH_STAMP)

bench: $(BENCH_STAMP)
	@for script in benchmarks/bench_*.py; do echo "== $$script"; .venv-bench/bin/python $$script || exit 1; done

clean:
	rm -rf _build

## make notebooks: re-execute every notebook and store its outputs (review the diff after)
notebooks: $(STAMP)
	$(BIN)/python tools/execute_notebooks.py
