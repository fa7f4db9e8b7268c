# One-command set-up: every target creates .venv and installs the project on first use.
PYTHON ?= python3
VENV   ?= .venv
BIN     = $(VENV)/bin
STAMP   = $(VENV)/.installed-stamp
OUT    ?= out

.PHONY: run test test-fast test-long bench lint docs clean system-deps dist

# setup.py compiles the FMU export library (build/export/) and the modules of
# physics/compiled.py's MODULES (each X.py with its X.pxd) at install: an edit there reinstalls
PXD      = $(shell find fmu_src/servofmu/physics -name '*.pxd')
COMPILED = fmu_src/servofmu/physics/compiled.py fmu_src/servofmu/physics/pair/continuation.py \
           $(PXD) $(PXD:.pxd=.py)
$(STAMP): pyproject.toml setup.py $(wildcard build/export/src/*/*) $(COMPILED)
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $(STAMP)

## main job: scenario 1, Yu's electrical method on the seeker-gimbal co-simulation (builds the
## FMUs and systems on first use; table printed, CSV and PNG under out/)
SCENARIO ?= friction_vs_temperature
run: $(STAMP)
	$(BIN)/servofmu scenario $(SCENARIO) --out $(OUT)/$(SCENARIO)

## system library of a test engine: ecos (ecospy) needs Debian's libtbb12. Installed with
## apt-get when missing and run as root (CI); otherwise the ecos tests are skipped and say why.
system-deps:
	@if { ldconfig -p || /sbin/ldconfig -p; } 2>/dev/null | grep -q 'libtbb\.so\.12 '; then :; \
	elif [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then \
	  echo "installing libtbb12 (needed by ecos, a co-simulation engine of the tests)"; \
	  (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends libtbb12 >/dev/null) \
	    || echo "libtbb12 could not be installed: the ecos tests will be skipped"; \
	else echo "libtbb12 is missing (install it as root: apt-get install libtbb12): the ecos tests will be skipped"; fi

## tests: lint, format check, the documentation, test suite
test: $(STAMP) system-deps lint docs
	$(BIN)/python -m pytest

## the fast loop while working: lint and the tests not marked slow (a few minutes; make test is
## the full suite)
test-fast: $(STAMP) lint
	$(BIN)/python -m pytest -m "not slow" -q

## documentation site into docs/_build/html, offline, warnings as errors; the examples gallery
## runs its scripts (SERVOFMU_GALLERY=coarse: a few points per curve; full: as a user runs them)
SERVOFMU_GALLERY ?= coarse
docs: $(STAMP)
	SERVOFMU_GALLERY=$(SERVOFMU_GALLERY) $(BIN)/sphinx-build -W --keep-going -q -b html docs docs/_build/html

## long mode: full-size fuzzing (10,000 cases per FMU) and soaks (1,000,000 steps); ~1 h
test-long: $(STAMP) system-deps lint
	$(BIN)/python -m pytest --long tests/fmus/test_robustness.py tests/packaging/test_archives.py

## release: the sdist from the checkout, then the wheel from the sdist, into dist/ (the PyPA
## frontend runs outside the checkout: the project's own build/ folder would shadow its package)
dist: $(STAMP)
	rm -rf dist && mkdir dist
	cd "$$(mktemp -d)" && $(CURDIR)/$(BIN)/pyproject-build --sdist --outdir $(CURDIR)/dist $(CURDIR) \
	  && $(CURDIR)/$(BIN)/pyproject-build --wheel --outdir $(CURDIR)/dist $(CURDIR)/dist/servofmu-*.tar.gz

lint: $(STAMP)
	$(BIN)/ruff check .
	$(BIN)/ruff format --check .

## benchmarks (not part of the test run): each prints its table and saves its figures with
## the run's context to benchmarks/results/NAME.json, which the documentation's Performance
## page reads (commit them after a run)
RESULTS = benchmarks/results
bench: $(STAMP)
	$(BIN)/python benchmarks/bench_bearing.py --models --save $(RESULTS)/bench_bearing.json
	$(BIN)/python benchmarks/bench_actuator.py --save $(RESULTS)/bench_actuator.json
	$(BIN)/python benchmarks/bench_fmus.py --models --save $(RESULTS)/bench_fmus.json
	$(BIN)/python benchmarks/bench_worst_step.py --save $(RESULTS)/bench_worst_step.json
	$(BIN)/python benchmarks/bench_harness.py --save $(RESULTS)/bench_harness.json
	$(BIN)/python benchmarks/bench_peers.py --save $(RESULTS)/bench_peers.json
	$(BIN)/python benchmarks/bench_sweep.py --save $(RESULTS)/bench_sweep.json
	$(BIN)/python benchmarks/bench_thermal_network.py --save $(RESULTS)/bench_thermal_network.json
	$(BIN)/python benchmarks/bench_calibration.py --save $(RESULTS)/bench_calibration.json

clean:
	rm -rf $(VENV) $(OUT) .pytest_cache .ruff_cache .setuptools-build dist servofmu.egg-info
	rm -rf docs/_build docs/_generated docs/auto_examples docs/api/generated
