# Two commands set up and check everything on a fresh machine:
#   make demo   - create .venv, install guided-lfd, run the main job on the kitchen data
#   make test   - create .venv if needed, install test extras, run the test suite
PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV   ?= .venv
BIN     = $(VENV)/bin
JOBS   ?= 2

.PHONY: setup demo demos reproduce-study test test-slow clean amlgym-setup amlgym-bench

$(BIN)/guided-lfd: pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test,plots,dist,up]'
	@touch $@

setup: $(BIN)/guided-lfd

demo: setup
	@echo "== Kitchen I: what must the human demonstrate?"
	$(BIN)/guided-lfd excuse data/domains/kitchen-1/robot.pddl data/domains/kitchen-1/problem.pddl
	@echo "== Kitchen II"
	$(BIN)/guided-lfd excuse data/domains/kitchen-2/robot.pddl data/domains/kitchen-2/problem.pddl
	@echo "== Kitchen II, as JSON"
	$(BIN)/guided-lfd excuse data/domains/kitchen-2/robot.pddl data/domains/kitchen-2/problem.pddl --json --quiet

demos: setup
	$(BIN)/guided-lfd demos data/demos

# The paper's user study from the shipped data: results/study.md, CSVs, PNGs.
reproduce-study: setup
	$(BIN)/guided-lfd study --root . --out results

test: setup
	$(BIN)/python -m pytest -q -n $(JOBS)

test-slow: setup
	GUIDED_LFD_FUZZ_EXAMPLES=1000 GUIDED_LFD_ADL_EXAMPLES=1000 $(BIN)/python -m pytest -q -n $(JOBS) --slow

# AMLGym (action-model learning benchmark) beside SAM and OffLAM, in an environment of its own.
AMLGYM_VENV ?= .venv-amlgym
amlgym-setup:
	$(PYTHON) -m venv $(AMLGYM_VENV)
	$(AMLGYM_VENV)/bin/python -m pip install --quiet --upgrade pip
	$(AMLGYM_VENV)/bin/python -m pip install --quiet -e '.[amlgym]'
	$(AMLGYM_VENV)/bin/python -m pip install --quiet --no-deps amlgym==1.0.13

amlgym-bench: amlgym-setup
	$(AMLGYM_VENV)/bin/python benchmarks/amlgym_bench.py --jobs $(JOBS) --out benchmarks/amlgym_results

clean:
	rm -rf $(VENV) $(AMLGYM_VENV) build *.egg-info .pytest_cache .hypothesis
