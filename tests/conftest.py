"""Shared test helpers: spec files written on the fly, and the ../shared reference data."""

import os
import textwrap
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, settings

# Hypothesis profiles for every property test: "ci" (the default) is derandomised, so a test
# run is reproducible and CI cannot fail on a newly drawn example; "fuzz" draws fresh random
# examples for the campaigns recorded in tests/FUZZ.md (HYPOTHESIS_PROFILE=fuzz).
settings.register_profile(
    "ci",
    max_examples=150,
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile(
    "fuzz",
    max_examples=int(os.environ.get("WTVIB_FUZZ_EXAMPLES", "40000")),  # a shorter campaign
    deadline=30_000,  # ms: the time bound of the invariant (no input may take longer)
    suppress_health_check=[HealthCheck.too_slow],
)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))

#: The slow tier (``make test-fast`` leaves it out, ``make test`` and CI run it): validation
#: against published and other tools' numbers, the fuzzing and hostile-input campaigns, the
#: documents whose commands are run and the pixel comparisons of figures and PDF pages.
SLOW = (
    "validation/",
    "test_fuzz",
    "test_hostile",
    "test_readme.py",
    "test_docs_images.py",
    "test_plots.py",
    "test_pdfreport.py",
    "test_windio.py",
)


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """Mark the slow tier's tests ``slow`` by their file (see SLOW)."""
    for item in items:
        path = Path(str(item.fspath)).as_posix()
        if any(part in path for part in SLOW):
            item.add_marker(pytest.mark.slow)


ROOT = Path(__file__).resolve().parents[1]
TURBINES = ROOT / "turbines"
SHARED = ROOT.parent / "shared"

#: The IEA-22-280-RWT repository's published stability results (tests/data/campbell/
#: SOURCES.md): HAWC2's ``hawc2.yaml``, OpenFAST's ``openfast_unsteady_aero_rotoronly.yaml``.
IEA22_STABILITY = ROOT / "tests" / "data" / "campbell" / "hawcstab2" / "iea22"


def iea22_stability(name: str) -> dict[float, tuple[Any, Any]]:
    """One of the IEA-22's stability files (``hawc2`` or ``openfast_unsteady_aero_rotoronly``)
    by wind [m/s]: its unnamed modes' undamped frequencies [Hz] and damping ratios."""
    import gzip

    import numpy as np
    import yaml

    text = gzip.decompress((IEA22_STABILITY / f"{name}.yaml.gz").read_bytes())
    return {
        float(c["configuration"]["wind_speed"]): (
            np.array(c["outputs"]["Frequency_undamped"]),
            np.array(c["outputs"]["Damping_ratio"]),
        )
        for c in yaml.safe_load(text)["cases"]
    }


#: The files of the NREL 5-MW deck set (../shared/reference/NREL5MW) the importer reads from
#: NREL-5MW.fst: the ones the importer fuzzing mutates.
NREL_DECK_FILES = (
    "NREL-5MW.fst",
    "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat",
    "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat",
    "NRELOffshrBsline5MW_Blade.dat",
    "NRELOffshrBsline5MW_Onshore_ServoDyn.dat",
    "NRELOffshrBsline5MW_Onshore_AeroDyn15.dat",
    "NRELOffshrBsline5MW_AeroDyn_blade.dat",
    "DISCON.IN",
    "Airfoils/NACA64_A17.dat",
)

#: A minimal valid spec; tests format it with their own speed and tower blocks.
BASE = """\
wtvib: 1
turbine: {{name: Test turbine}}
rotor:
  blades: {blades}
  orientation: upwind
  hub: {hub}
  speed:
{speed}
tower:
  modes:
{modes}
"""


def spec_text(
    *,
    blades: int = 3,
    speed: str = "fixed_rpm: 20",
    modes: str = "fa1: 0.5",
    extra: str = "",
) -> str:
    """YAML text of a small spec (speed and mode lines are indented for the caller). A
    two-bladed rotor gets a teetering hub: hingeless, a soft tower under it fails
    ``tower.concept`` (Hau 7.5.1), which the tests of other things must not trip over."""
    return (
        BASE.format(
            blades=blades,
            hub="teetered" if blades == 2 else "rigid",
            speed=textwrap.indent(speed, "    "),
            modes=textwrap.indent(modes, "    "),
        )
        + extra
    )


@pytest.fixture
def write_spec(tmp_path: Path) -> Callable[..., Path]:
    """Write a spec (text or keyword parts of :func:`spec_text`) and return its path."""

    def write(text: str | None = None, name: str = "t.yaml", **parts: object) -> Path:
        path = tmp_path / name
        path.write_text(text if text is not None else spec_text(**parts), encoding="utf-8")  # type: ignore[arg-type]
        return path

    return write


@pytest.fixture(scope="session")
def shared() -> Path:
    """The ../shared folder beside the clone; skipped where absent, failed in CI.

    ``.ci/run`` sets WTVIB_REQUIRE_SHARED=1 so that CI never skips these tests silently.
    """
    if (SHARED / "reference").is_dir():
        return SHARED
    reason = f"reference data not found at {SHARED} (clone the project beside ../shared)"
    if os.environ.get("WTVIB_REQUIRE_SHARED"):
        pytest.fail(reason + "; WTVIB_REQUIRE_SHARED is set, so this is an error")
    pytest.skip(reason)


def edited_reference(
    shared: Path, tmp_path: Path, folder: str, file: str, old: str, new: str
) -> Path:
    """A copy of a ``../shared/reference`` folder with one literal edit of one of its files
    (which must still hold ``old``: a reference file that changed fails here, not later)."""
    import shutil

    target = tmp_path / Path(folder).name
    shutil.copytree(shared / "reference" / folder, target)
    path = target / file
    text = path.read_text()
    assert old in text, f"{file} no longer holds {old!r}"
    path.write_text(text.replace(old, new))
    return target


@pytest.fixture(autouse=True)
def _outputs_in_a_temporary_folder(
    tmp_path_factory: pytest.TempPathFactory, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Every test runs in a folder of its own, so that outputs written to the current
    directory (PNGs by default) never land in the clone."""
    monkeypatch.chdir(tmp_path_factory.mktemp("cwd"))


def with_tolerance(s: Any, path: str, tolerance: float) -> Any:
    """A copy of spec ``s`` whose number at the spec ``path`` (``tower.material.
    youngs_modulus_pa``, ``tower.foundation.soil[0].friction_angle_deg``) carries a normal
    ``tolerance``."""
    from wtvib.spec import from_data
    from wtvib.spec.messages import _split

    data = {k: v for k, v in s.model_dump().items() if v is not None}
    *parents, last = _split(path)
    node = data
    for key in parents:
        node = node[key]
    node[last] = {"value": node[last], "provenance": "representative", "tolerance": tolerance}
    return from_data(data)
