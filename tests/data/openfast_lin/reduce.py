"""How the .lin.gz files here were made from OpenFAST's regression tests (see SOURCES.md):
each kept up to its table of state derivatives, then its A matrix — the inputs, outputs and
B, C, D matrices, which no test reads, left out — and gzipped.

    python tests/data/openfast_lin/reduce.py R_TEST/glue-codes/openfast CASE [CASE …]
"""

import gzip
import re
import sys
from pathlib import Path


def reduce(text: str) -> str:
    """The header, the state tables and A of a .lin file's text."""
    cut = text.find("\nOrder of inputs")
    head = text if cut < 0 else text[: cut + 1]
    a = re.search(r"^[ \t]*A:.*$", text, re.MULTILINE)
    if a is None:
        raise ValueError("no A matrix")
    nxt = re.search(r"^[ \t]*[B-Z]:", text[a.end() :], re.MULTILINE)
    block = text[a.start() : a.end() + nxt.start() if nxt else len(text)]
    return head.rstrip("\n") + "\n\nLinearized state matrices:\n\n" + block.rstrip("\n") + "\n"


def main(root: str, cases: list[str]) -> None:
    here = Path(__file__).parent
    for case in cases:
        for lin in sorted((Path(root) / case).glob(f"{case}.*.lin")):
            if re.match(rf"{re.escape(case)}\.\d+\.lin$", lin.name):
                data = reduce(lin.read_text()).encode()
                (here / f"{lin.name}.gz").write_bytes(gzip.compress(data, mtime=0))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2:])
