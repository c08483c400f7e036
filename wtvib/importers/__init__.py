"""Reading the files users already have: wtvib specs, OpenFAST ElastoDyn decks, windIO.

:func:`load` detects the format and returns a validated :class:`~wtvib.spec.Spec`. An
importer produces a plain wtvib-format dictionary first, so ``wtvib convert`` can write
it out as an editable spec.
"""

import math
from pathlib import Path
from typing import Any

from ..errors import SpecError
from ..spec import Spec, from_data, load_document, read_text

FORMATS = "a wtvib spec (YAML with 'wtvib: 1'), a windIO turbine YAML (1.x or 2.x), an "
FORMATS += "OpenFAST ElastoDyn / FAST v7 deck (.dat/.fst), or Campbell results: OpenFAST "
FORMATS += "linearisation (.lin, or a folder of them), HAWCStab2 (.cmb) or a table (.csv)"


def detect(path: Path, text: str) -> str:
    """``wtvib``, ``windio`` or ``elastodyn`` by content; SpecError for anything else."""
    head = text[:4000]
    suffix = path.suffix.lower()
    if path.is_dir() or suffix == ".lin":
        return "openfast-lin"
    if suffix == ".cmb":
        return "hawcstab2"
    if suffix == ".csv":
        from .campbell_table import looks_like

        if looks_like(text):
            return "campbell-table"
    deck_like = path.suffix.lower() in (".dat", ".fst") or "ELASTODYN" in head.upper()
    if deck_like and ("TwrFile" in text or "NumBl" in text or "EDFile" in text):
        return "elastodyn"  # ElastoDyn deck, FAST v7 .fst, or an OpenFAST .fst naming one
    if path.suffix.lower() in (".yaml", ".yml"):
        windio_like = "components:" in text and ("assembly:" in text or "windIO" in text)
        return "windio" if windio_like and "wtvib:" not in head else "wtvib"
    first = next((ln for ln in head.splitlines() if ln.strip() and ln.lstrip()[0] != "#"), "")
    if first.replace(" ", "").startswith("wtvib:"):
        return "wtvib"
    raise SpecError(f"not a format wtvib reads; expected {FORMATS}", source=str(path))


def to_data(
    path: str | Path,
    *,
    rpm: tuple[float, float] | None = None,
    rated: float | None = None,
    head_mass: float | None = None,
    clamped_base: bool = False,
    blades: int | None = None,
) -> dict[str, Any]:
    """The wtvib-format dictionary of any supported file (for ``wtvib convert``).

    ``head_mass`` [kg] replaces the tower-head assembly of a windIO file (needed for 1.x
    files, which hold no hub or nacelle masses).
    """
    p = Path(path)
    text = "" if p.is_dir() else read_text(p)
    kind = detect(p, text)
    _check_options(p, kind, rpm, rated, head_mass)
    if kind == "openfast-lin":
        from . import openfast_lin

        data = openfast_lin.to_spec_data(p, blades)
    elif kind == "hawcstab2":
        from . import hawcstab2

        data = hawcstab2.to_spec_data(p, text, blades)
    elif kind == "campbell-table":
        from . import campbell_table

        data = campbell_table.to_spec_data(p, text, blades)
    elif kind == "elastodyn":
        from . import elastodyn

        data = elastodyn.to_spec_data(p, text)
    elif kind == "windio":
        from . import windio

        data = windio.to_spec_data(p, text, head_mass, clamped_base)
    else:
        doc = load_document(p, text)
        data = doc.data
    return _with_speed(data, rpm, rated) if (rpm or rated) else data


def load(
    path: str | Path,
    *,
    rpm: tuple[float, float] | None = None,
    rated: float | None = None,
    head_mass: float | None = None,
    clamped_base: bool = False,
    blades: int | None = None,
) -> Spec:
    """Any supported file as a validated spec; ``rpm``/``rated`` set the operating range,
    ``blades`` the number of blades of Campbell results that do not say."""
    p = Path(path)
    text = "" if p.is_dir() else read_text(p)
    kind = detect(p, text)
    _check_options(p, kind, rpm, rated, head_mass)
    if kind == "wtvib" and rpm is None and rated is None:
        from ..spec import from_document

        return from_document(load_document(p, text))
    data = to_data(
        p, rpm=rpm, rated=rated, head_mass=head_mass, clamped_base=clamped_base, blades=blades
    )
    return from_data(data, source=str(p))


def _check_options(
    path: Path,
    kind: str,
    rpm: tuple[float, float] | None,
    rated: float | None,
    head_mass: float | None,
) -> None:
    """The import options, one rule and one message each, for every format."""
    if head_mass is not None:
        if kind != "windio":
            what = "the deck's" if kind == "elastodyn" else "the spec's"
            raise SpecError(
                f"--head-mass applies to windIO files only; {what} own tower-head masses are "
                "used (edit them, or convert the file and edit the spec)",
                source=str(path),
            )
        if not (math.isfinite(head_mass) and head_mass > 0):
            raise SpecError(f"--head-mass must be a mass above 0 kg (got {head_mass:g})")
    if rated is not None and not (math.isfinite(rated) and rated > 0):
        raise SpecError(f"--rated must be a speed above 0 rpm (got {rated:g})")
    if (
        rpm is not None
        and rated is not None
        and rpm[0] != rpm[1]
        and not (rpm[0] <= rated <= rpm[1])
    ):
        raise SpecError(f"--rated {rated:g} rpm lies outside --rpm {rpm[0]:g}:{rpm[1]:g}")


def is_main_input(path: Path) -> bool:
    """True for files a batch should audit: specs, windIO files and ElastoDyn main decks."""
    suffix = path.suffix.lower()
    if suffix in (".yaml", ".yml"):
        return True
    if suffix in (".dat", ".fst"):
        try:
            head = path.read_bytes()[:200_000]
        except OSError:
            return True  # let the audit report the read error
        return b"TwrFile" in head or (suffix == ".fst" and b"EDFile" in head)
    return False


def _with_speed(
    data: dict[str, Any], rpm: tuple[float, float] | None, rated: float | None
) -> dict[str, Any]:
    speed = dict(data["rotor"]["speed"])
    if rpm is not None:
        low, high = rpm
        speed = {"fixed_rpm": low} if low == high else {"min_rpm": low, "max_rpm": high}
    if rated is not None:
        if "fixed_rpm" in speed:
            speed = {"fixed_rpm": rated}
        else:
            speed["rated_rpm"] = rated
    speed["source"] = "the command line (--rpm/--rated)"
    notes = [*data.get("assumptions", []), "Operating speeds set on the command line."]
    # a range given on the command line answers the importer's "speed not found"
    warnings = [w for w in data.get("warnings", []) if "--rpm" not in w]
    out = {**data, "rotor": {**data["rotor"], "speed": speed}, "assumptions": notes}
    if "warnings" in data:
        out["warnings"] = warnings
    return out


def results_spec(
    path: Path,
    tool: str,
    modes: dict[str, dict[str, Any]],
    blades: int | None,
    files: list[str],
    name: str,
    blades_found: int | None = None,
) -> dict[str, Any]:
    """The wtvib-format dictionary of another tool's Campbell results: the modes, the
    operating range their points span, the number of blades (the file's, the option's, or
    three, said), and what was assumed."""
    assumptions: list[str] = []
    warnings: list[str] = []
    spread = max(merge_speeds(m) for m in modes.values())
    if spread > 0:
        assumptions.append(
            "Operating points that share a rotor speed (the rated speed over several winds) "
            "are merged per mode: the mean frequency (spread up to "
            f"{spread:.1%}) and the lowest damping."
        )
    if blades is not None and blades_found is not None and blades != blades_found:
        raise SpecError(
            f"--blades {blades}, but the results have {blades_found} blades", source=str(path)
        )
    n = blades or blades_found
    if n is None:
        n = 3
        warnings.append(
            f"rotor.blades: {path.name} does not say how many blades the rotor has — 3 "
            "assumed (give --blades N); the excitation lines depend on it"
        )
    speeds = sorted({round(r, 4) for m in modes.values() for r in m["rpm"]})
    running = [r for r in speeds if r > 0]
    if not running:
        raise SpecError(
            "the results hold standstill points only; give the operating range with --rpm MIN:MAX",
            source=str(path),
        )
    speed = (
        {"fixed_rpm": running[0]}
        if len(running) == 1
        else {"min_rpm": running[0], "max_rpm": running[-1]}
    )
    if speeds[0] == 0 and len(running) > 1 and running[0] < 0.5 * running[-1]:
        warnings.append(
            f"rotor.speed: the results sweep rotor speed from standstill; their "
            f"{running[0]:.4g}–{running[-1]:.4g} rpm is audited as the operating range — "
            "give the turbine's own with --rpm MIN:MAX (and --rated)"
        )
    assumptions.append(
        f"Operating range from the results' operating points: {running[0]:.4g}"
        + (f"–{running[-1]:.4g}" if len(running) > 1 else "")
        + " rpm (--rpm to set it); rotor upwind with a rigid hub assumed."
    )
    return {
        "wtvib": 1,
        "turbine": {"name": name},
        "rotor": {"blades": n, "orientation": "upwind", "hub": "rigid", "speed": speed},
        "results": {"tool": tool, "files": files, "modes": modes},
        "assumptions": assumptions,
        "warnings": warnings,
    }


def merge_speeds(m: dict[str, Any]) -> float:
    """Merge a result mode's points that share a rotor speed (a rated speed held over several
    winds) into one: the mean frequency, the lowest damping (with its wind), the first whirl.
    Returns the largest relative spread of the merged frequencies (0 if none merged)."""
    rpm = m["rpm"]
    order = sorted(range(len(rpm)), key=lambda i: (rpm[i], i))
    groups: list[list[int]] = []
    for i in order:
        if groups and abs(rpm[groups[-1][0]] - rpm[i]) <= 1e-6 * max(1.0, rpm[i]):
            groups[-1].append(i)
        else:
            groups.append([i])
    spread = 0.0
    out: dict[str, list[Any]] = {
        k: [] for k in ("rpm", "frequency_hz", "damping_ratio", "whirl", "wind_m_s") if k in m
    }
    for g in groups:
        f = [m["frequency_hz"][i] for i in g]
        spread = max(spread, (max(f) - min(f)) / min(f))
        low = min(g, key=lambda i: m["damping_ratio"][i]) if "damping_ratio" in m else g[0]
        out["rpm"].append(rpm[g[0]])
        out["frequency_hz"].append(sum(f) / len(f))
        for key in ("damping_ratio", "wind_m_s"):
            if key in out:
                out[key].append(m[key][low])
        if "whirl" in out:
            out["whirl"].append(m["whirl"][g[0]])
    m.update(out)
    return spread
