"""Cross-checks the schema alone cannot make (several fields at once), with field and line."""

import numpy as np

from ..errors import SpecError
from .base import Quantity
from .messages import _split
from .turbine import Spec
from .yamlio import Document


def _check_sources(spec: Spec, provenance: dict[str, Quantity], doc: Document) -> None:
    for where, q in provenance.items():
        if q.source is not None and q.source not in spec.sources:
            known = ", ".join(spec.sources) or "none"
            raise SpecError(
                f"source {q.source!r} is not a key of the top-level 'sources' (known: {known})",
                path=f"{where}.source",
                line=doc.line_of(_split(where)),
                source=doc.source,
            )


def _check_rotor_radius(spec: Spec, doc: Document) -> None:
    """A rotor diameter that leaves no blade beyond the hub radius is a mistake."""
    d, s = spec.turbine.rotor_diameter_m, spec.blade.structure
    if d is not None and s is not None and d / 2 <= s.hub_radius_m:
        raise SpecError(
            f"a rotor radius of {d / 2:g} m leaves no blade beyond the blade root at "
            f"blade.structure.hub_radius_m = {s.hub_radius_m:g} m",
            path="turbine.rotor_diameter_m",
            line=doc.line_of(("turbine", "rotor_diameter_m")),
            source=doc.source,
        )


def _check_geometry(spec: Spec, doc: Document) -> None:
    """Geometry no turbine can have: a tower table that ends short of (or past) the tower's
    height, a hub too low for the rotor to turn (its tip through the ground), a blade
    longer than the rotor's radius."""
    t = spec.tower
    table = t.sections.height_m if t.sections is not None else (
        t.distributed.height_m if t.distributed is not None else None
    )  # fmt: skip
    if table is not None and t.height_m is not None:
        top = float(table[-1])
        if abs(top - t.height_m) > max(0.5, 0.01 * t.height_m):
            part = "sections" if t.sections is not None else "distributed"
            raise SpecError(
                f"the tower's {part} end at {top:g} m but tower.height_m is {t.height_m:g} m: "
                "the table must reach the tower top",
                path=f"tower.{part}.height_m",
                line=doc.line_of(("tower", part, "height_m")),
                source=doc.source,
            )
    d, hub = spec.turbine.rotor_diameter_m, spec.turbine.hub_height_m
    horizontal = spec.rotor.orientation != "vertical-axis"
    if d is not None and hub is not None and horizontal and hub <= d / 2:
        raise SpecError(
            f"a hub {hub:g} m high under a {d / 2:g} m rotor radius: the blade tips would "
            "strike the ground",
            path="turbine.hub_height_m",
            line=doc.line_of(("turbine", "hub_height_m")),
            source=doc.source,
        )
    if d is not None and spec.blade.length_m is not None and spec.blade.length_m > d / 2:
        raise SpecError(
            f"a blade of {spec.blade.length_m:g} m is longer than the rotor's radius ({d / 2:g} m)",
            path="blade.length_m",
            line=doc.line_of(("blade", "length_m")),
            source=doc.source,
        )


def _check_coupled(spec: Spec, doc: Document) -> None:
    """The coupled model's needs, named with the line: the structures, and a tower head
    heavy enough to carry the rotor it includes."""
    cm = spec.coupled
    if cm is None:
        return
    missing = [
        name
        for name, present in (
            ("blade.structure", spec.blade.structure is not None),
            ("tower sections or distributed properties", spec.tower.has_structure),
            ("tower_head", spec.tower_head is not None),
        )
        if not present
    ]
    if spec.rotor.orientation == "vertical-axis":
        missing.append("a horizontal-axis rotor")
    if missing:
        raise SpecError(
            f"the coupled model needs {', '.join(missing)}",
            path="coupled",
            line=doc.line_of(("coupled",)),
            source=doc.source,
        )
    s, head = spec.blade.structure, spec.tower_head
    assert s is not None and head is not None
    from ..numerics.rigid import nacelle, rotor_points  # the one place that splits the head

    # the rotor's mass and polar inertia: the blades as the coupled model carries them
    points = rotor_points(s.hub_radius_m, np.asarray(s.span_m), np.asarray(s.mass_per_length_kg_m))
    tip_r = s.hub_radius_m + float(s.span_m[-1])
    m_blade = float(points.mass.sum()) + s.tip_mass_kg
    j_blade = points.polar() + s.tip_mass_kg * tip_r**2
    n = spec.rotor.blades
    chain = spec.drivetrain.chain
    hub = cm.hub_inertia_kgm2
    if hub is None and chain and chain[0].name != "blades":
        raise SpecError(
            f"the drive-train chain starts with {chain[0].name!r}: the coupled model models "
            "the blades itself, so it needs the chain's blade inertia as a first mass named "
            "'blades' (or coupled.hub_inertia_kgm2 for the hub alone)",
            path="drivetrain.chain[0].name",
            line=doc.line_of(("drivetrain", "chain", 0, "name")),
            source=doc.source,
        )
    if hub is None and chain:
        hub = chain[1].inertia_kgm2 if len(chain) > 1 else 0.0
    apex = (cm.apex_downwind_m, 0.0, cm.apex_above_top_m)
    try:
        nacelle(head, np.array(apex), n * m_blade + cm.hub_mass_kg, n * j_blade + (hub or 0.0))
    except SpecError as exc:
        raise SpecError(
            exc.message,
            path=exc.path,
            line=doc.line_of(_split(exc.path or "tower_head")),
            source=doc.source,
        ) from None


def _check_aerodynamics(spec: Spec, doc: Document) -> None:
    """The aerodynamic stations must lie on a horizontal-axis rotor whose radius is known,
    inside it, and the given operating points within the rotor's speeds. (Pitch regulation
    without a rated power is estimated and said: aero.bem._rated_estimate.)"""
    aero = spec.aerodynamics
    if aero is None:
        return

    def fail(message: str, *where: str | int) -> None:
        raise SpecError(
            message,
            path=".".join(str(w) for w in ("aerodynamics", *where)),
            line=doc.line_of(("aerodynamics", *where)),
            source=doc.source,
        )

    if spec.rotor.orientation == "vertical-axis":
        fail("the blade-element momentum model is for horizontal-axis rotors")
    d = spec.turbine.rotor_diameter_m
    if d is None:
        raise SpecError(
            "aerodynamics needs turbine.rotor_diameter_m (the tip radius)",
            path="turbine.rotor_diameter_m",
            line=doc.line_of(("turbine",)),
            source=doc.source,
        )
    tip = aero.stations.radius_m[-1]
    if tip > d / 2 * (1 + 1e-6):
        fail(
            f"the last station at {tip:g} m lies beyond the rotor radius {d / 2:g} m",
            "stations",
            "radius_m",
        )
    c = aero.control
    pts = c.operating_points
    if pts is not None:
        low = min(a for a, _ in spec.rotor.speed.steady_rpm)
        high = max(b for _, b in spec.rotor.speed.steady_rpm)
        for i, n in enumerate(pts.rpm):
            if not low * (1 - 0.01) <= n <= high * (1 + 0.01):
                fail(
                    f"operating point {i + 1} turns at {n:g} rpm, outside the rotor's "
                    f"operating speeds {low:g}–{high:g} rpm (rotor.speed)",
                    "control",
                    "operating_points",
                    "rpm",
                    i,
                )
        return


def _check_results(spec: Spec, doc: Document) -> None:
    """Another tool's whole-turbine modes replace the coupled model: not both."""
    if spec.results is not None and spec.coupled is not None:
        raise SpecError(
            "results (another tool's modes) and coupled (wtvib's whole-turbine model) "
            "cannot both give the system modes: keep one",
            path="results",
            line=doc.line_of(("results",)),
            source=doc.source,
        )
