"""Packaging: every module wtvib imports is declared, and the lock files agree with
pyproject.toml. (`make install-check`, part of `make test`, installs the built wheel into a
fresh environment without extras and runs it — the way users meet it.)"""

import ast
import importlib.metadata
import re
import sys
import tomllib
from pathlib import Path

from packaging.requirements import Requirement

ROOT = Path(__file__).resolve().parents[1]
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text())

#: Modules imported only behind an optional feature, and the extra that brings them.
OPTIONAL = {"distributed": "distributed", "jsonschema": "windio"}


def _imported() -> dict[str, set[str]]:
    """Top-level third-party modules imported anywhere in wtvib → the files importing them."""
    found: dict[str, set[str]] = {}
    for path in (ROOT / "wtvib").rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            names: list[str] = []
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                names = [node.module]
            for name in names:
                top = name.split(".")[0]
                if top not in sys.stdlib_module_names and top != "wtvib":
                    found.setdefault(top, set()).add(path.name)
    return found


def _names(requirements: list[str]) -> set[str]:
    return {re.sub(r"[-_.]+", "-", Requirement(r).name).lower() for r in requirements}


def test_every_imported_module_is_declared() -> None:
    # a module reached only through another package's dependencies breaks a bare install
    # the day that package drops it (typer >= 0.16 no longer brings click)
    declared = _names(PYPROJECT["project"]["dependencies"])
    extras = PYPROJECT["project"]["optional-dependencies"]
    distributions = importlib.metadata.packages_distributions()
    missing = []
    for module, files in sorted(_imported().items()):
        dists = {re.sub(r"[-_.]+", "-", d).lower() for d in distributions.get(module, [module])}
        allowed = _names(extras[OPTIONAL[module]]) if module in OPTIONAL else declared
        if not dists & allowed:
            missing.append(f"{module} (imported by {', '.join(sorted(files))})")
    assert not missing, f"imported but not declared in pyproject.toml: {missing}"


def _pins(path: Path) -> dict[str, str]:
    text = path.read_text()
    return {
        re.sub(r"[-_.]+", "-", m[1]).lower(): m[2]
        for m in re.finditer(r"^([A-Za-z0-9_.-]+)==(\S+)", text, re.MULTILINE)
    }


def test_the_locks_pin_every_dependency_within_its_range_and_agree() -> None:
    runtime = _pins(ROOT / "requirements" / "runtime.txt")
    dev = _pins(ROOT / "requirements" / "dev.txt")
    assert "--hash=sha256:" in (ROOT / "requirements" / "runtime.txt").read_text()
    for text in PYPROJECT["project"]["dependencies"]:
        req = Requirement(text)
        name = re.sub(r"[-_.]+", "-", req.name).lower()
        assert name in runtime, f"{name} is not in requirements/runtime.txt (make lock)"
        assert req.specifier.contains(runtime[name]), f"{name}=={runtime[name]} outside {req}"
    for text in PYPROJECT["project"]["optional-dependencies"]["dev"]:
        name = re.sub(r"[-_.]+", "-", Requirement(text).name).lower()
        assert name in dev, f"{name} is not in requirements/dev.txt (make lock)"
    # setuptools, the build backend the Makefile's --no-build-isolation install uses
    assert "setuptools" in runtime and "setuptools" in dev
    differ = {k: (v, dev[k]) for k, v in runtime.items() if k in dev and dev[k] != v}
    assert not differ, f"the runtime and dev locks pin different versions: {differ} (make lock)"


def test_the_licence_is_an_spdx_expression() -> None:
    # setuptools stops accepting the table form ({text = ...}) in 2027
    assert PYPROJECT["project"]["license"] == "MIT"
