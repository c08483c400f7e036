"""What the Campbell-result readers share (OpenFAST linearisation, HAWCStab2, tables): the
wtvib-format dictionary of another tool's modes, and points at one rotor speed merged."""

from pathlib import Path
from typing import Any

from ..errors import SpecError

#: The most modes wtvib reads from another tool's results (a .cmb, a Campbell table): a
#: whole-turbine Campbell diagram has tens; beyond this a file is not one, and reading on
#: would only cost memory (about 0.3 MB per mode in the audit) and time.
MAX_MODES = 1000


def results_spec(
    path: Path,
    tool: str,
    modes: dict[str, dict[str, Any]],
    blades: int | None,
    files: list[str],
    name: str,
    blades_found: int | None = None,
    rpm: tuple[float, float] | None = None,
) -> dict[str, Any]:
    """The wtvib-format dictionary of another tool's Campbell results: the modes, the
    operating range their points span (or ``rpm``, the command line's [rpm], which the
    importer puts in afterwards), the number of blades (the file's, the option's, or three,
    said), and what was assumed."""
    if len(modes) > MAX_MODES:
        raise SpecError(
            f"{len(modes)} modes: a whole-turbine Campbell diagram has tens; wtvib reads at "
            f"most {MAX_MODES}",
            source=str(path),
        )
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
    if not running and rpm is None:
        assumptions.append(
            "A standstill audit: the results are of a parked rotor (0 rpm) and no operating "
            "range is given — no rotor harmonic is judged (--rpm MIN:MAX judges the parked "
            "modes against one); the modes' stability is."
        )
        return _document(name, n, {"parked": True}, tool, files, modes, assumptions, warnings)
    if not running:
        assert rpm is not None
        warnings.append(
            "rotor.speed: the results are of a parked rotor (0 rpm): each mode's frequency "
            f"is held over the {rpm[0]:g}–{rpm[1]:g} rpm given — the rotor's stiffening and the "
            "cyclic modes' split into whirls (±1P) in operation are not in it"
        )
        running = [rpm[0], rpm[1]] if rpm[1] > rpm[0] else [rpm[0]]
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
    return _document(name, n, speed, tool, files, modes, assumptions, warnings)


def _document(
    name: str,
    blades: int,
    speed: dict[str, Any],
    tool: str,
    files: list[str],
    modes: dict[str, dict[str, Any]],
    assumptions: list[str],
    warnings: list[str],
) -> dict[str, Any]:
    return {
        "wtvib": 1,
        "turbine": {"name": name},
        "rotor": {"blades": blades, "orientation": "upwind", "hub": "rigid", "speed": speed},
        "results": {"tool": tool, "files": files, "modes": modes},
        "assumptions": assumptions,
        "warnings": warnings,
    }


#: A result mode's per-point lists merged as the mean of a speed's points; ``AT_LOWEST``:
#: taken at the point of lowest damping; any other per-point list: at the first point.
MEANS = ("frequency_hz", "damped_frequency_hz")
AT_LOWEST = ("damping_ratio", "wind_m_s")


def merge_speeds(m: dict[str, Any]) -> float:
    """Merge a result mode's points that share a rotor speed (a rated speed held over several
    winds) into one: the mean frequency (natural and damped), the lowest damping (with its
    wind), the first point's whirl and every other per-point list's (an OpenFAST
    linearisation's energy share). Returns the largest relative spread of the merged
    frequencies (0 if none merged)."""
    rpm = m["rpm"]
    order = sorted(range(len(rpm)), key=lambda i: (rpm[i], i))
    groups: list[list[int]] = []
    for i in order:
        if groups and abs(rpm[groups[-1][0]] - rpm[i]) <= 1e-6 * max(1.0, rpm[i]):
            groups[-1].append(i)
        else:
            groups.append([i])
    spread = 0.0
    per_point = [k for k, v in m.items() if isinstance(v, list) and len(v) == len(rpm)]
    out: dict[str, list[Any]] = {k: [] for k in per_point}
    for g in groups:
        f = [m["frequency_hz"][i] for i in g]
        assert min(f) > 0, "the readers refuse frequencies that are not positive"
        spread = max(spread, (max(f) - min(f)) / min(f))
        low = min(g, key=lambda i: m["damping_ratio"][i]) if "damping_ratio" in m else g[0]
        for key in per_point:
            values = [m[key][i] for i in g]
            if key in MEANS:
                out[key].append(sum(values) / len(values))
            else:
                out[key].append(m[key][low] if key in AT_LOWEST else values[0])
    m.update(out)
    return spread
