# Everything a fresh machine needs: `make demo` and `make test` create the virtual
# environment themselves (python3 -m venv + pip from PyPI), from the lock files in
# requirements/ (pinned versions with their hashes: the install that worked yesterday works
# today). `make lock` refreshes them; pyproject.toml keeps the ranges a library user gets.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
RUNTIME := $(VENV)/.runtime-installed
DEV     := $(VENV)/.dev-installed
PIP_TOOLS := pip-tools==7.6.2

.PHONY: demo test test-fast lint venv clean fuzz lock install-check docs-images mutate

$(BIN)/python:
	@$(PYTHON) -m venv $(VENV)

# The locked packages (pip checks every hash), then wtvib itself without touching them;
# setuptools, its build backend, is in the lock too (--no-build-isolation uses it).
$(RUNTIME): requirements/runtime.txt pyproject.toml | $(BIN)/python
	@echo "installing wtvib and its locked dependencies into $(VENV) (once) ..."
	@$(BIN)/pip install --quiet --disable-pip-version-check -r requirements/runtime.txt
	@$(BIN)/pip install --quiet --disable-pip-version-check --no-deps --no-build-isolation -e .
	@touch $@

$(DEV): requirements/dev.txt pyproject.toml | $(BIN)/python
	$(BIN)/pip install --quiet --disable-pip-version-check -r requirements/dev.txt
	$(BIN)/pip install --quiet --disable-pip-version-check --no-deps --no-build-isolation -e .
	touch $@ $(RUNTIME)

venv: $(DEV)

# What was audited, the verdict and where the figures are; the whole report in demo/.
demo: $(RUNTIME)
	@mkdir -p demo
	@$(BIN)/wtvib check turbines/wka-60.yaml --out-dir demo/ > demo/wka-60.txt 2> demo/wka-60.log \
		|| test $$? -eq 1
	@sed -n '1,/^Assumptions/p' demo/wka-60.txt | sed '$$d'
	@echo "The whole report: demo/wka-60.txt; Campbell diagrams: $$(ls demo/*.png | tr '\n' ' ')"

lint: $(DEV)
	$(BIN)/ruff check wtvib tests bench
	$(BIN)/ruff format --check wtvib tests bench
	$(BIN)/mypy

# One BLAS thread, as the CLI pins for itself: the tests solve the same small problems, and
# OpenBLAS's spinning threads only slow them on a 2-core machine.
test: lint install-check
	OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 $(BIN)/pytest -q

# The unit tier while working: every test but the slow tier (tests/conftest.py SLOW:
# validation, fuzzing, hostile input, documents, pixels), no lint, no wheel. CI runs `test`.
test-fast: $(DEV)
	OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 $(BIN)/pytest -q -m "not slow"

# wtvib as a user installs it: the wheel built from this tree (isolated build, as `pip
# install .` does), installed into a fresh virtual environment without extras and without
# the lock (pyproject's ranges, from PyPI), then started and run on a catalogue turbine with
# its figures. A module wtvib imports but does not declare fails here.
INSTALL_CHECK := build/install-check
install-check: $(DEV)
	rm -rf $(INSTALL_CHECK) && mkdir -p $(INSTALL_CHECK)/out
	$(BIN)/pip wheel --quiet --disable-pip-version-check --no-deps -w $(INSTALL_CHECK)/dist .
	$(PYTHON) -m venv $(INSTALL_CHECK)/venv
	$(INSTALL_CHECK)/venv/bin/pip install --quiet --disable-pip-version-check $(INSTALL_CHECK)/dist/wtvib-*.whl
	$(INSTALL_CHECK)/venv/bin/wtvib --version
	cd $(INSTALL_CHECK)/out && ../venv/bin/wtvib catalogue > catalogue.txt
	cd $(INSTALL_CHECK)/out && ../venv/bin/wtvib catalogue --copy specs > /dev/null
	test -s $(INSTALL_CHECK)/out/specs/mod-2.yaml
	cd $(INSTALL_CHECK)/out && ../venv/bin/wtvib check mod-2 > check.txt || test $$? -eq 1
	test -s $(INSTALL_CHECK)/out/mod-2.campbell.png
	@echo "install-check: the bare wheel installs, starts, lists, copies and audits its catalogue"

# The README's figure: drawn by the code as it is (tests/test_docs_images.py fails when
# the committed picture no longer matches what `check` draws).
docs-images: $(RUNTIME)
	rm -rf build/docs-images && mkdir -p build/docs-images
	$(BIN)/wtvib check turbines/wka-60.yaml --out-dir build/docs-images > /dev/null || test $$? -eq 1
	cp build/docs-images/wka-60.campbell.png docs/wka-60.campbell.png

# Refresh the lock files from pyproject.toml (newest releases within its ranges), with
# pip-tools in a throwaway environment; commit requirements/ afterwards.
lock:
	rm -rf build/lock-venv && $(PYTHON) -m venv build/lock-venv
	build/lock-venv/bin/pip install --quiet '$(PIP_TOOLS)'
	build/lock-venv/bin/pip-compile --quiet --generate-hashes --allow-unsafe --strip-extras \
		--all-build-deps --no-emit-index-url --no-emit-find-links \
		pyproject.toml -o requirements/runtime.txt
	build/lock-venv/bin/pip-compile --quiet --generate-hashes --allow-unsafe --strip-extras \
		--all-build-deps --no-emit-index-url --no-emit-find-links --extra dev \
		pyproject.toml -o requirements/dev.txt
	rm -rf build/lock-venv

# A mutation campaign over the physics and verdict modules (tests/campaigns/mutate.py: one-
# token bugs on each module's syntax tree, a seeded sample per module, each run against
# that module's tests in a private copy of the tree); the score is recorded in
# tests/MUTATION.md. About half an hour on two cores.
mutate: $(DEV)
	$(BIN)/python tests/campaigns/mutate.py --per-module 12 --workers 2 --seed 1

# A long fuzzing campaign (>= 100,000 cases: 3 spec properties x 40,000 examples, 2
# importer properties x 2,000, 5 reader properties x 25,000: .lin, HAWCStab2, Campbell
# tables, output paths, batch discovery); the outcome is recorded by hand in tests/FUZZ.md. CI runs
# the short profile inside `make test`. The invariant's bounds: 30 s per example (the
# profile's deadline) and 2 GB of address space per process (ulimit -v: a MemoryError is a
# failure like any other exception).
fuzz: $(DEV)
	ulimit -v 2000000 && OPENBLAS_NUM_THREADS=1 HYPOTHESIS_PROFILE=fuzz $(BIN)/pytest -q tests/test_fuzz.py \
		tests/test_fuzz_importers.py tests/test_fuzz_readers.py -p no:cacheprovider \
		--hypothesis-show-statistics

clean:
	rm -rf $(VENV) demo build .pytest_cache .mypy_cache .ruff_cache
