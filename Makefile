# One-command set-up: every target creates .venv and installs the project on first use.
PYTHON ?= python3
VENV   ?= .venv
BIN     = $(VENV)/bin
STAMP   = $(VENV)/.installed-stamp
OUT    ?= out

.PHONY: run test bench lint clean

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $(STAMP)

## main job: the Yu 2017 friction-versus-temperature reproduction (report, CSV, PNG under out/)
run: $(STAMP)
	$(BIN)/servofmu paper yu2017 --out $(OUT)/yu2017

## tests: lint, format check, test suite
test: $(STAMP) lint
	$(BIN)/python -m pytest

lint: $(STAMP)
	$(BIN)/ruff check .
	$(BIN)/ruff format --check .

## benchmarks (not part of the test run)
bench: $(STAMP)
	$(BIN)/python benchmarks/bench_bearing.py
	$(BIN)/python benchmarks/bench_actuator.py
	$(BIN)/python benchmarks/bench_fmus.py

clean:
	rm -rf $(VENV) $(OUT) .pytest_cache .ruff_cache
