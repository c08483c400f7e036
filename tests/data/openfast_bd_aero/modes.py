"""The modes of OpenFAST's linearisations, as kept here (see SOURCES.md): the 12 ``.lin``
files of one run read by wtvib's MBC3 reader (``wtvib.importers.openfast_lin``, which
reproduces openfast_toolbox's MBC3 on every r-test linearisation, test_openfast_lin.py) and
its operating point's modes written as JSON — their full-system files (420 states, 3.9 MB
each) are too large to keep.

    python tests/data/openfast_bd_aero/modes.py RUN_FOLDER OUT.json
"""

import json
import sys
from pathlib import Path

from wtvib.importers import openfast_lin as ol


def modes(folder: Path) -> dict[str, object]:
    files = sorted(folder.glob("*.lin"), key=lambda p: int(p.name.split(".")[-2]))
    point = ol.operating_point([ol.read(p) for p in files])[0]
    return {
        "files": [p.name for p in files],
        "rpm": round(point.rpm, 6),
        "wind_m_s": point.wind,
        "modes": [
            {
                "name": n,
                "natural_frequency_hz": round(float(f), 6),
                "damping_ratio": round(float(z), 6),
            }
            for n, f, z in zip(point.names, point.frequency_hz, point.damping_ratio, strict=True)
        ],
    }


if __name__ == "__main__":
    data = modes(Path(sys.argv[1]))
    Path(sys.argv[2]).write_text(json.dumps(data, indent=1) + "\n")
