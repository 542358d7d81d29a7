# Forced mass-spring-damper: a reproducible report. `make` lists the targets.
.DEFAULT_GOAL := help
SHELL := /bin/bash

PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV := .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed
BUILD := build
CHROMIUM ?= /usr/bin/chromium
# The numerical environment of `make test`: generic machine code from numba, numpy's SIMD loops limited to
# x86-64-v2, OpenBLAS's oldest x86-64 kernels, one thread. `make notebooks` writes the nbval references in
# the machine's own environment, so every `make test` proves that they reproduce under other arithmetic.
PORTABLE := NUMBA_CPU_NAME=generic NPY_DISABLE_CPU_FEATURES="X86_V3 X86_V4 AVX512_ICL AVX512_SPR" \
	OPENBLAS_CORETYPE=Prescott OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 MKL_NUM_THREADS=1 VIBRATION_PORTABLE=1
# pytest workers, one per core (--dist loadfile keeps a notebook's cells, and a module's fixtures, in one worker)
JOBS ?= 2

.PHONY: help setup report test test-slow test-library test-fast bench lint format notebooks lab browser clean

help: ## list the targets
	@awk 'BEGIN {FS = ":.*## "} /^[a-zA-Z_-]+:.*## / {printf "  make %-11s %s\n", $$1, $$2}' $(MAKEFILE_LIST)

$(STAMP): environment.txt pyproject.toml
	@$(PYTHON) -c 'import sys; assert sys.version_info[:2] == (3, 11), f"Python 3.11 needed, found {sys.version.split()[0]}"'
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -r environment.txt
	$(PY) -m pip install --quiet --no-deps --no-build-isolation -e .
	$(PY) -m ipykernel install --sys-prefix --name vibration --display-name "Python 3 (vibration)" >/dev/null
	touch $(STAMP)

setup: $(STAMP) ## create .venv from environment.txt (again only when it changes)

browser: ## install Debian's Chromium for the browser tests if it is missing
	@test -x $(CHROMIUM) || { echo "installing chromium with apt-get"; \
	  SUDO=$$([ "$$(id -u)" = 0 ] || echo sudo); \
	  $$SUDO apt-get update -qq && $$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium >/dev/null; }

report: $(STAMP) browser ## run every chapter with papermill, build the book: build/report/index.html and report.pdf
	$(PY) -m vibration.report --out $(BUILD)

test: $(STAMP) browser ## lint, layers, unit, property, doctests, strict nbval and browser tests (all but those marked slow)
	$(PY) -m ruff check src tests notebooks
	$(VENV)/bin/lint-imports
	@mkdir -p $(BUILD); rc=0; \
	$(PORTABLE) $(PY) -m pytest -n $(JOBS) --dist loadfile -m "not slow" --nbval --nbval-sanitize-with tests/nbval_sanitize.cfg tests src notebooks || rc=$$?; \
	echo $$rc > $(BUILD)/pytest.rc; \
	if [ $$rc -eq 5 ]; then echo "error: pytest collected no tests (exit code 5)" >&2; fi; \
	exit $$rc

test-slow: $(STAMP) browser ## the tests marked slow: the report under far parameters, runner signals, JupyterLab (CI runs them too)
	$(PORTABLE) $(PY) -m pytest -n $(JOBS) --dist loadfile -m "slow and not notebooks and not far" tests src
	$(PORTABLE) $(PY) -m pytest -m "slow and (notebooks or far)" tests src  # one at a time: each runs kernels or the report on both cores

test-library: $(STAMP) ## the library's own tests alone (physics, bad-input battery, API, doctests): no book
	$(PY) -m pytest -n $(JOBS) -m "not slow" tests/physics tests/fuzz tests/test_package_api.py src/vibration/physics

test-fast: $(STAMP) ## unit, property and doctests only (no kernels, no browser)
	$(PY) -m pytest -n $(JOBS) -m "not browser and not notebooks"

bench: $(STAMP) ## print speed ratios measured side by side in one run
	$(PY) -m vibration.bench

lint: $(STAMP) ## ruff check and format check (notebooks included), import-linter layers, no repeated code in src
	$(PY) -m ruff check src tests notebooks
	$(PY) -m ruff format --check src tests notebooks
	$(VENV)/bin/lint-imports
	$(PY) -m pylint --rcfile pyproject.toml --score n src/vibration

format: $(STAMP) ## apply ruff formatting and safe fixes
	$(PY) -m ruff check --fix src tests notebooks
	$(PY) -m ruff format src tests notebooks

notebooks: $(STAMP) ## re-execute the notebooks in place (after an intended change of outputs)
	$(PY) -m vibration.report --in-place

lab: $(STAMP) ## open JupyterLab on the notebooks
	$(VENV)/bin/jupyter lab notebooks/

clean: ## remove build output and the virtual environment
	rm -rf $(BUILD) $(VENV) .pytest_cache .ruff_cache .hypothesis
