"""How the deck-set archives here were made: each holds exactly the files wtvib reads for
one OpenFAST deck set (found by running ``wtvib.importers.load`` on it with every read
logged), at their paths in the source repository, so the decks' relative file names
resolve. Run once against local copies of the repositories (see SOURCES.md):

    python tests/data/openfast_decks/pack.py rtest /path/to/r-test \
        glue-codes/openfast/5MW_OC3Mnpl_Linear/5MW_OC3Mnpl_Linear.fst ...
"""

import importlib
import sys
import tarfile
from pathlib import Path


def read_by(deck: Path) -> list[Path]:
    """Every file wtvib reads to audit the deck set."""
    load_module = importlib.import_module("wtvib.spec.load")
    seen: list[Path] = []
    original = load_module.read_bytes

    def logged(path, **kwargs):  # type: ignore[no-untyped-def]
        seen.append(Path(path).resolve())
        return original(path, **kwargs)

    load_module.read_bytes = logged
    try:
        from wtvib import importers

        importers.load(deck)
    finally:
        load_module.read_bytes = original
    return list(dict.fromkeys(seen))


def main() -> None:
    name, root, decks = sys.argv[1], Path(sys.argv[2]).resolve(), sys.argv[3:]
    files = sorted({f for d in decks for f in read_by(root / d)})
    out = Path(__file__).with_name(f"{name}.tar.gz")
    with tarfile.open(out, "w:gz") as tar:
        for f in files:
            info = tar.gettarinfo(f, arcname=str(f.relative_to(root)))
            info.mtime, info.uid, info.gid, info.uname, info.gname = 0, 0, 0, "", ""
            with f.open("rb") as fh:
                tar.addfile(info, fh)
    print(out, len(files), "files")


if __name__ == "__main__":
    main()
