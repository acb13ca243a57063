# Two commands set up and check everything on a fresh machine:
#   make demo   - create .venv, install guided-lfd, run the main job on the kitchen data
#   make test   - create .venv if needed, install test extras, run the test suite
PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV   ?= .venv
BIN     = $(VENV)/bin
JOBS   ?= 2

.PHONY: setup demo demos reproduce-study test test-slow clean

$(BIN)/guided-lfd: pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test,plots,dist]'
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
	GUIDED_LFD_FUZZ_EXAMPLES=1000 $(BIN)/python -m pytest -q -n $(JOBS) --slow

clean:
	rm -rf $(VENV) build *.egg-info .pytest_cache .hypothesis
