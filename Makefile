# Everything a fresh machine needs: `make demo` and `make test` create the virtual
# environment themselves (python3 -m venv + pip from PyPI).
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: demo test lint venv clean fuzz

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --upgrade pip
	$(BIN)/pip install --quiet -e '.[dev]'
	touch $(STAMP)

venv: $(STAMP)

demo: $(STAMP)
	$(BIN)/wtvib check turbines/wka-60.yaml --out demo/ || test $$? -eq 1
	@echo "Campbell diagram written to demo/"

lint: $(STAMP)
	$(BIN)/ruff check wtvib tests bench
	$(BIN)/ruff format --check wtvib tests bench
	$(BIN)/mypy

# One BLAS thread, as the CLI pins for itself: the tests solve the same small problems, and
# OpenBLAS's spinning threads only slow them on a 2-core machine.
test: lint
	OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 $(BIN)/pytest -q

# A long fuzzing campaign (>= 100,000 cases: 3 spec properties x 40,000 examples, 2
# importer properties x 2,000); the outcome is recorded by hand in tests/FUZZ.md. CI runs
# the short profile inside `make test`. The invariant's bounds: 30 s per example (the
# profile's deadline) and 2 GB of address space per process (ulimit -v: a MemoryError is a
# failure like any other exception).
fuzz: $(STAMP)
	ulimit -v 2000000 && OPENBLAS_NUM_THREADS=1 HYPOTHESIS_PROFILE=fuzz $(BIN)/pytest -q tests/test_fuzz.py \
		tests/test_fuzz_importers.py -p no:cacheprovider --hypothesis-show-statistics

clean:
	rm -rf $(VENV) demo .pytest_cache .mypy_cache .ruff_cache
