"""A mutation campaign over the physics and verdict modules (``make mutate``).

Each mutant is one plausible one-token bug in a module — an arithmetic operator swapped
(+ ↔ −, × ↔ ÷, ** → ×), a comparison loosened or tightened (< ↔ ≤, > ↔ ≥), a number changed
(c → 1.1·c, an integer c → c + 1, 0 → 1), a unary minus dropped — made on the module's
syntax tree, written over the module in a private copy of the repository, and run against
the module's tests (``tests/test_<module>.py``, ``tests/validation/test_<module>.py``, every
test file that imports the module, the extra files :data:`TESTS` names and the catalogue's
audits, :data:`WHOLE`), stopping at the first failure. A mutant the tests
fail (or that runs past :data:`TIMEOUT_S`, or no longer imports) is killed; one they pass
survived. Mutants are sampled: ``--per-module N`` of each module's, seeded, so that a run
is repeatable and bounded. Docstrings are not mutated.

    .venv/bin/python tests/campaigns/mutate.py [--per-module 12] [--workers 2] [--seed 1]

Prints one line per survivor and the score as JSON; tests/MUTATION.md records the runs.
"""

import argparse
import ast
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
TIMEOUT_S = 300

#: The modules mutated and the tests each runs beside its own test files.
TESTS: dict[str, tuple[str, ...]] = {
    "numerics.beam": ("tests/test_tower.py",),
    "numerics.modal": ("tests/test_tower.py", "tests/test_drivetrain.py"),
    "subsystems.tower": (
        "tests/validation/test_structure.py",
        "tests/validation/test_tower_head.py",
    ),
    "subsystems.blade": ("tests/validation/test_structure.py",),
    "subsystems.drivetrain": (),
    "subsystems.yaw": (),
    "aero.aeroelastic": (),
    "aero.stall": (),
    "judge.resonance": ("tests/validation/test_daf.py",),
    "rules": ("tests/test_resonance.py",),
    "judge.excitation": ("tests/test_resonance.py",),
    "subsystems.soil": (
        "tests/validation/test_soil_pybmodes.py",
        "tests/validation/test_soil_hawc2.py",
    ),
    "subsystems.platform": ("tests/validation/test_floating.py",),
    "numerics.hull": ("tests/validation/test_windio_floating.py", "tests/test_windio_platform.py"),
    "judge.closeness": (),
    "numerics.rigid": ("tests/test_coupled.py",),
    "aero.bem": ("tests/validation/test_aerodynamics.py",),
    "aero.torsion": ("tests/test_bem.py", "tests/validation/test_hawc2.py"),
    "aero.aerodamping": ("tests/validation/test_aerodynamics.py",),
    "numerics.unsteady": ("tests/validation/test_unsteady.py", "tests/test_aerodamping.py"),
    "aero.tuned_damper": ("tests/validation/test_tuned_damper.py",),
    "subsystems.polynomials": ("tests/test_polynomials.py", "tests/validation/test_polynomials.py"),
    "importers.hawcstab2": (
        "tests/test_campbell_import.py",
        "tests/validation/test_campbell_import.py",
    ),
    "subsystems.multiblade": (
        "tests/validation/test_one_story.py",
        "tests/validation/test_floating.py",
        "tests/validation/test_coupled.py",
    ),
}


@dataclass(frozen=True)
class Mutant:
    module: str
    line: int
    what: str
    source: str  # the module's mutated text


class _Site(ast.NodeVisitor):
    """Every node a mutation applies to, in order, skipping docstrings."""

    def __init__(self) -> None:
        self.sites: list[tuple[ast.AST, str]] = []
        self._docstrings: set[int] = set()

    def visit(self, node: ast.AST) -> None:
        if isinstance(node, ast.Module | ast.FunctionDef | ast.ClassDef | ast.AsyncFunctionDef):
            body = node.body
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
                self._docstrings.add(id(body[0].value))
        super().visit(node)

    def visit_BinOp(self, node: ast.BinOp) -> None:
        if isinstance(node.op, ast.Add | ast.Sub | ast.Mult | ast.Div | ast.Pow):
            self.sites.append((node, "binop"))
        self.generic_visit(node)

    def visit_Compare(self, node: ast.Compare) -> None:
        if len(node.ops) == 1 and isinstance(node.ops[0], ast.Lt | ast.LtE | ast.Gt | ast.GtE):
            self.sites.append((node, "compare"))
        self.generic_visit(node)

    def visit_Constant(self, node: ast.Constant) -> None:
        value = node.value
        number = isinstance(value, int | float) and not isinstance(value, bool)
        if number and id(node) not in self._docstrings:
            self.sites.append((node, "number"))

    def visit_UnaryOp(self, node: ast.UnaryOp) -> None:
        if isinstance(node.op, ast.USub):
            self.sites.append((node, "minus"))
        self.generic_visit(node)


_SWAP = {
    ast.Add: ast.Sub,
    ast.Sub: ast.Add,
    ast.Mult: ast.Div,
    ast.Div: ast.Mult,
    ast.Pow: ast.Mult,
}
_COMPARE = {ast.Lt: ast.LtE, ast.LtE: ast.Lt, ast.Gt: ast.GtE, ast.GtE: ast.Gt}
_SYMBOL = {
    ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.Pow: "**",
    ast.Lt: "<", ast.LtE: "<=", ast.Gt: ">", ast.GtE: ">=",
}  # fmt: skip


def _path(root: Path, module: str) -> Path:
    """The file of a module named below wtvib (``subsystems.tower``)."""
    return root / "wtvib" / (module.replace(".", "/") + ".py")


def mutants(module: str) -> list[Mutant]:
    """Every mutant of a module (one per site)."""
    path = _path(ROOT, module)
    text = path.read_text()
    out = []
    count = len(_sites(text))
    for i in range(count):
        tree = ast.parse(text)
        node, kind = _sites_of(tree)[i]
        line = getattr(node, "lineno", 0)
        if kind == "binop":
            assert isinstance(node, ast.BinOp)
            old = type(node.op)
            node.op = _SWAP[old]()
            what = f"{_SYMBOL[old]} → {_SYMBOL[type(node.op)]}"
        elif kind == "compare":
            assert isinstance(node, ast.Compare)
            old = type(node.ops[0])
            node.ops = [_COMPARE[old]()]
            what = f"{_SYMBOL[old]} → {_SYMBOL[type(node.ops[0])]}"
        elif kind == "number":
            assert isinstance(node, ast.Constant)
            v = node.value
            new = (v + 1 if v else 1) if isinstance(v, int) else (v * 1.1 if v else 1.0)
            what = f"{v!r} → {new!r}"
            node.value = new
        else:
            assert isinstance(node, ast.UnaryOp)
            what = "unary minus dropped"
            node.op = ast.UAdd()
        out.append(Mutant(module, line, what, ast.unparse(tree)))
    return out


def _sites(text: str) -> list[tuple[ast.AST, str]]:
    return _sites_of(ast.parse(text))


def _sites_of(tree: ast.AST) -> list[tuple[ast.AST, str]]:
    finder = _Site()
    finder.visit(tree)
    return finder.sites


#: Every mutant also runs the audits of the catalogue and the verdicts' coherence: the
#: physics reaches the verdict through them.
WHOLE = (
    "tests/test_audit.py",
    "tests/validation/test_catalogue.py",
    "tests/validation/test_verdict_coherence.py",
)


def _imports(module: str) -> list[str]:
    """The test files that import the module (``from wtvib import … module …``,
    ``wtvib.module``), the fuzzing campaigns left out."""
    last = module.rsplit(".", 1)[-1]
    package = ("wtvib." + module).rsplit(".", 1)[0].replace(".", r"\.")
    pattern = re.compile(rf"from {package} import [^\n]*\b{last}\b|wtvib\.{re.escape(module)}\b")
    files = sorted((ROOT / "tests").glob("test_*.py")) + sorted(
        (ROOT / "tests" / "validation").glob("test_*.py")
    )
    return [
        str(f.relative_to(ROOT))
        for f in files
        if "fuzz" not in f.name and pattern.search(f.read_text(encoding="utf-8"))
    ]


def _tests(module: str) -> list[str]:
    last = module.rsplit(".", 1)[-1]
    own = [f"tests/test_{last}.py", f"tests/validation/test_{last}.py"]
    every = [*own, *TESTS[module], *_imports(module), *WHOLE]
    return [t for t in dict.fromkeys(every) if (ROOT / t).is_file()]


def run(mutant: Mutant, tree: Path) -> str:
    """killed, survived or timeout: the module's tests on the mutant, in ``tree``."""
    target = _path(tree, mutant.module)
    original = target.read_text()
    target.write_text(mutant.source)
    env = {**os.environ, "PYTHONPATH": str(tree), "OPENBLAS_NUM_THREADS": "1"}
    cmd = [sys.executable, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider"]
    cmd += [str(tree / t) for t in _tests(mutant.module)]
    try:
        done = subprocess.run(
            cmd, cwd=tree, env=env, capture_output=True, timeout=TIMEOUT_S, check=False
        )
        return "survived" if done.returncode == 0 else "killed"
    except subprocess.TimeoutExpired:
        return "timeout"
    finally:
        target.write_text(original)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--per-module", type=int, default=12)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--modules", nargs="*", default=list(TESTS))
    args = ap.parse_args()
    rng = random.Random(args.seed)
    chosen: list[Mutant] = []
    for module in args.modules:
        every = mutants(module)
        chosen += rng.sample(every, min(args.per_module, len(every)))
    work = Path(tempfile.mkdtemp(prefix="wtvib-mutate-"))
    trees = []
    for k in range(args.workers):  # a private copy each: mutants are written in place
        tree = work / f"tree{k}"
        shutil.copytree(ROOT / "wtvib", tree / "wtvib")
        shutil.copytree(ROOT / "tests", tree / "tests")
        shutil.copytree(ROOT / "turbines", tree / "turbines")
        shutil.copy(ROOT / "pyproject.toml", tree / "pyproject.toml")
        trees.append(tree)
    if (ROOT.parent / "shared").is_dir() and not (work / "shared").exists():
        (work / "shared").symlink_to(ROOT.parent / "shared")  # ../shared beside each tree
    start = time.perf_counter()
    free = list(trees)

    def one(m: Mutant) -> tuple[Mutant, str]:
        tree = free.pop()
        try:
            return m, run(m, tree)
        finally:
            free.append(tree)

    with ThreadPoolExecutor(args.workers) as pool:
        results = list(pool.map(one, chosen))
    counts = {"killed": 0, "survived": 0, "timeout": 0}
    by_module: dict[str, dict[str, int]] = {}
    for m, outcome in results:
        counts[outcome] += 1
        row = by_module.setdefault(m.module, {"killed": 0, "survived": 0, "timeout": 0})
        row[outcome] += 1
        if outcome == "survived":
            print(f"SURVIVED wtvib/{m.module}.py:{m.line} {m.what}")
    total = len(results)
    score = (counts["killed"] + counts["timeout"]) / total if total else 1.0
    summary = {
        "mutants": total,
        **counts,
        "score": round(score, 4),
        "seconds": round(time.perf_counter() - start),
        "per_module": by_module,
    }
    print(json.dumps(summary))
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
