# Two commands, both self-contained in a fresh clone (Python >= 3.11, pip, make):
#   make reproduce   writes results/
#   make test        runs the test suite
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: test reproduce benchmark derive clean

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $(STAMP)

test: $(STAMP)
	$(BIN)/python -m pytest -q

reproduce: $(STAMP)
	$(BIN)/mdr-events reproduce --out results

benchmark: $(STAMP)
	$(BIN)/python benchmarks/bench_phase_diagram.py
	$(BIN)/python benchmarks/bench_discrete.py
	$(BIN)/python benchmarks/bench_continuum.py

derive: $(STAMP)
	$(BIN)/mdr-events derive

clean:
	rm -rf $(VENV) build *.egg-info .pytest_cache .hypothesis
