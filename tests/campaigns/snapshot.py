"""What wtvib says about a corpus of inputs, kept to compare two trees byte for byte.

    .venv/bin/python tests/campaigns/snapshot.py take DIR [--figures] [--jobs N]
    .venv/bin/python tests/campaigns/snapshot.py compare DIR_A DIR_B

``take`` runs ``wtvib check`` on every input of the corpus — the catalogue, the reference
decks and windIO files in ../shared/reference, the windio package's examples, the deck
sets, HAWC2 model and OpenFAST linearisations in tests/data, the HAWCStab2 and table
Campbell results — once as JSON and once as the terminal's text (``--detail``, wide, no
colour), and keeps stdout, stderr and the exit code of each (with ``--figures``, every PNG
too). The inputs are unpacked into a fixed folder first so that the paths the reports name
are the same in every snapshot. ``compare`` lists what differs (``--rel 1e-9``: JSON numbers that
close are the same — a sum taken in another order). A refactor leaves the two snapshots
identical; a speed-up that reorders arithmetic, identical in every printed digit.
"""

import argparse
import concurrent.futures
import gzip
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tarfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SHARED = ROOT.parent / "shared" / "reference"
DATA = ROOT / "tests" / "data"
INPUTS = Path("/tmp/wtvib-snapshot-inputs")
ENV = {
    **os.environ,
    "OPENBLAS_NUM_THREADS": "1",
    "OMP_NUM_THREADS": "1",
    "MPLBACKEND": "Agg",
    "COLUMNS": "120",
    "NO_COLOR": "1",
    "SOURCE_DATE_EPOCH": "1700000000",
}


def unpack() -> Path:
    """The archives of tests/data unpacked into :data:`INPUTS` (once; a deck archive added
    since is unpacked beside the others — a single marker for all of them once left the
    IEA-15 semisubmersible and the r-test special cases out of every snapshot)."""
    INPUTS.mkdir(parents=True, exist_ok=True)
    for archive in sorted((DATA / "openfast_decks").glob("*.tar.gz")):
        folder = INPUTS / archive.name.removesuffix(".tar.gz")
        if not (folder / ".unpacked").exists():
            with tarfile.open(archive) as tar:
                tar.extractall(folder, filter="data")
            (folder / ".unpacked").touch()
    for archive in sorted((DATA / "hawc2").glob("*.tar.gz")):  # every HAWC2 model, each once
        marker = INPUTS / "hawc2" / f".{archive.name}"
        if not marker.exists():
            with tarfile.open(archive) as tar:
                tar.extractall(INPUTS / "hawc2", filter="data")
            marker.touch()
    semi = INPUTS / "hawc2" / ".iea15_semi.hydrodata"  # the UMaineSemi floater's WAMIT files
    if not semi.exists():
        with tarfile.open(DATA / "openfast_decks" / "iea15_semi.tar.gz") as tar:
            wamit = [m for m in tar.getmembers() if "/HydroData/" in m.name]
            tar.extractall(INPUTS / "hawc2", members=wamit, filter="data")
        semi.touch()
    done = INPUTS / ".unpacked"
    if done.exists():
        return INPUTS
    lin = INPUTS / "lin"
    lin.mkdir(exist_ok=True)
    for gz in sorted((DATA / "openfast_lin").glob("*.lin.gz")):
        case = gz.name.split(".")[0]
        (lin / case).mkdir(exist_ok=True)
        (lin / case / gz.name.removesuffix(".gz")).write_bytes(gzip.decompress(gz.read_bytes()))
    cmb = INPUTS / "cmb"
    cmb.mkdir(exist_ok=True)
    for gz in sorted((DATA / "campbell" / "hawcstab2" / "iea15").glob("*.gz")):
        (cmb / gz.name.removesuffix(".gz")).write_bytes(gzip.decompress(gz.read_bytes()))
    done.touch()
    return INPUTS


def corpus() -> list[tuple[str, list[str]]]:
    """(name, arguments of ``wtvib check``) for every input."""
    inputs = unpack()
    cases: list[tuple[str, list[str]]] = []
    for spec in sorted((ROOT / "turbines").glob("*.yaml")):
        cases.append((f"catalogue/{spec.stem}", [str(spec)]))
    for fst in sorted(SHARED.glob("*/*.fst")):
        cases.append((f"reference/{fst.parent.name}/{fst.stem}", [str(fst)]))
    for ed in sorted(SHARED.glob("*/*ElastoDyn.dat")):
        cases.append((f"reference/{ed.parent.name}/{ed.stem}", [str(ed), "--rpm", "6:12"]))
    heads = {"IEA10": "605000", "IEA15": "1017000", "IEA3.4": "170000"}  # windIO 1.x: none
    for yml in sorted(SHARED.glob("*/*.yaml")):
        head = ["--head-mass", heads[yml.parent.name]] if yml.parent.name in heads else []
        cases.append((f"reference/{yml.parent.name}/{yml.stem}", [str(yml), *head]))
    try:
        import windIO

        examples = Path(windIO.__file__).parent / "examples" / "turbine"
        for yml in sorted(examples.glob("*.yaml")):
            extra = ["--head-mass", "1017000"] if "VolturnUS" in yml.name else []
            if "Floater" in yml.name:
                extra = ["--head-mass", "1217711"]
            cases.append((f"windio/{yml.stem}", [str(yml), *extra]))
    except ImportError:
        pass
    for fst in sorted(inputs.glob("*/**/*.fst")):
        if "lin" in fst.parts[len(inputs.parts) : len(inputs.parts) + 1]:
            continue
        rel = fst.relative_to(inputs)
        cases.append((f"decks/{rel.parts[0]}/{fst.stem}", [str(fst)]))
        if rel.parts[0].startswith("rtest"):
            cases.append((f"decks/{rel.parts[0]}/{fst.stem}+dofs", [str(fst), "--deck-dofs"]))
    for htc in sorted((inputs / "hawc2").glob("**/htc/*.htc")):
        cases.append((f"hawc2/{htc.stem}", [str(htc)]))
    for folder in sorted((inputs / "lin").iterdir()):
        cases.append((f"lin/{folder.name}", [str(folder), "--rpm", "5:12"]))
    for f in [
        *sorted((DATA / "campbell" / "hawcstab2").glob("*.cmb")),
        *sorted((inputs / "cmb").glob("*.cmb")),
    ]:
        cases.append((f"campbell/{f.parent.name}/{f.name}", [str(f)]))
    cases.append(("campbell/openfast", [str(DATA / "campbell" / "openfast"), "--rpm", "5:12"]))
    return cases


def _run(wtvib: str, args: list[str], cwd: Path) -> bytes:
    p = subprocess.run(
        [wtvib, "check", *args], cwd=cwd, env=ENV, capture_output=True, timeout=600, check=False
    )
    return b"exit %d\n--- stdout\n%s\n--- stderr\n%s" % (p.returncode, p.stdout, p.stderr)


def take_one(wtvib: str, name: str, args: list[str], out: Path, figures: bool) -> str:
    safe = name.replace("/", "__")
    work = out / "work" / safe
    work.mkdir(parents=True, exist_ok=True)
    (out / f"{safe}.json.txt").write_bytes(
        _run(wtvib, [*args, "--format", "json", "--no-plots"], work)
    )
    plots = ["--out-dir", str(work)] if figures else ["--no-plots"]
    (out / f"{safe}.text.txt").write_bytes(_run(wtvib, [*args, "--detail", *plots], work))
    if figures:
        for png in sorted(work.glob("*.png")):
            shutil.move(png, out / f"{safe}.{png.name}")
    shutil.rmtree(work, ignore_errors=True)
    return name


def take(out: Path, figures: bool, jobs: int) -> None:
    out.mkdir(parents=True, exist_ok=True)
    wtvib = str(Path(sys.executable).parent / "wtvib")
    cases = corpus()
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        futures = [pool.submit(take_one, wtvib, n, a, out, figures) for n, a in cases]
        for f in concurrent.futures.as_completed(futures):
            f.result()
    shutil.rmtree(out / "work", ignore_errors=True)
    print(f"{len(cases)} inputs into {out}")


def _numbers_apart(a: object, b: object) -> float | None:
    """The largest relative difference between two JSON documents' numbers (0 where they
    are equal), None where they differ in anything but numbers."""
    if isinstance(a, bool) or isinstance(b, bool):
        return 0.0 if a == b else None
    if isinstance(a, int | float) and isinstance(b, int | float):
        scale = max(abs(a), abs(b))
        return abs(a - b) / scale if scale else 0.0
    if isinstance(a, dict) and isinstance(b, dict):
        if a.keys() != b.keys():
            return None
        parts = [_numbers_apart(a[k], b[k]) for k in a]
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return None
        parts = [_numbers_apart(x, y) for x, y in zip(a, b, strict=True)]
    else:
        return 0.0 if a == b else None
    return None if None in parts else max(parts, default=0.0)  # type: ignore[type-var]


def _json_of(path: Path) -> object:
    text = path.read_text(encoding="utf-8", errors="replace")
    body = text[text.index("--- stdout\n") + 11 : text.index("\n--- stderr")]
    return json.loads(body) if body.strip() else None


def compare(a: Path, b: Path, rel: float = 0.0) -> int:
    """What differs between two snapshots; with ``rel``, a JSON report whose numbers differ
    by no more than that relative amount (rounding: a sum in another order) is the same."""
    names = sorted({p.name for p in a.iterdir()} | {p.name for p in b.iterdir()})
    differ = 0
    worst = 0.0
    for name in names:
        pa, pb = a / name, b / name
        if not pa.exists() or not pb.exists():
            print(f"only in {'b' if not pa.exists() else 'a'}: {name}")
            differ += 1
            continue
        if hashlib.sha256(pa.read_bytes()).digest() == hashlib.sha256(pb.read_bytes()).digest():
            continue
        if rel and name.endswith(".json.txt"):
            apart = _numbers_apart(_json_of(pa), _json_of(pb))
            if apart is not None and apart <= rel:
                worst = max(worst, apart)
                continue
        print(f"differs: {name}")
        differ += 1
    close = f"; JSON numbers within {worst:.2g} of each other" if worst else ""
    print(f"{len(names)} files, {differ} differ{close}")
    return 1 if differ else 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="what", required=True)
    t = sub.add_parser("take")
    t.add_argument("dir", type=Path)
    t.add_argument("--figures", action="store_true")
    t.add_argument("--jobs", type=int, default=2)
    c = sub.add_parser("compare")
    c.add_argument("a", type=Path)
    c.add_argument("b", type=Path)
    c.add_argument("--rel", type=float, default=0.0, help="JSON numbers this close are equal")
    args = parser.parse_args()
    if args.what == "take":
        take(args.dir, args.figures, args.jobs)
        return 0
    return compare(args.a, args.b, args.rel)


if __name__ == "__main__":
    sys.exit(main())
