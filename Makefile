# Everything a fresh machine needs: `make demo` and `make test` create the virtual
# environment themselves (python3 -m venv + pip from PyPI).
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: demo test lint venv clean

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

test: lint
	$(BIN)/pytest -q

clean:
	rm -rf $(VENV) demo .pytest_cache .mypy_cache .ruff_cache
