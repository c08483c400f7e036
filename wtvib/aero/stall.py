"""Stall-induced vibration: quasi-steady aerodynamic damping of the blade's flap and edge modes.

A section vibrating along a direction at angle ψ to the relative wind W feels the damping
force per unit length and velocity (Hau ch. 7.2.3; DOMAIN.md §3)

    c(ψ) = ½ρcW [2C_D cos²ψ + (C_L + C_D′) sinψ cosψ + (C_L′ + C_D) sin²ψ],   ′ = d/dα.

Flapwise motion (normal to the rotor plane) has ψ = 90° − φ, edgewise motion (in the plane)
ψ = 180° − φ, with φ the inflow angle of W to the rotor plane. The modal aerodynamic damping
ratio is ζ_a = ∫ c·φ_m² dr / (2ω·∫ m·φ_m² dr) with the mode shape φ_m. Past stall C_L′ < 0:
the edgewise (and in deep stall the flapwise) damping can become negative — the
stall-induced vibrations of stall-regulated rotors.

Inflow model (stated in every check): steady uniform wind V, constant axial induction a (a
setting, default 0: the geometric angle of attack, the highest — conservative for stall
onset), no tangential induction; α = φ − (twist + pitch), φ = atan(V(1−a)/(Ω·r)). Rotor
speed: each fixed speed, or for variable speed Ω = clamp(λ_opt·V/R, Ω_min, Ω_rated). Pitch
is held; a pitch-regulated rotor is checked up to its rated wind only (above it, pitching
to feather lowers the angles of attack).
The mode moves normal to the rotor plane (flap) or in it (edge): the structural twist of the
principal axes is ignored here.
"""

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from ..judge.analysis import Analysis, Context, Subsystem, no_modes
from ..rules import NEGATIVE
from ..subsystems.blade import default_damping as blade_damping
from ..units import rad_s_to_rpm, rpm_to_rad_s
from .aerodamping import attached_flow_note, blade_mass, blade_shape, isolated_in_attached_flow

if TYPE_CHECKING:
    from ..results import Check, Mode, OperatingDamping, Rule
    from ..rules import Status
    from ..spec import BladeAeroelastic, Spec

Array = NDArray[np.float64]

#: The built-in polar's stall: linear lift 2πα up to STALL_DEG, then a linear fall to the flat
#: plate (C_L = 2 sinα cosα, C_D = 2 sin²α) at FLAT_PLATE_DEG. Illustrative, not an aerofoil.
STALL_DEG, FLAT_PLATE_DEG, CD0 = 12.0, 45.0, 0.01


def aero_damping_coefficient(
    rho: float, chord: Any, w: Any, psi: Any, cl: Any, cd: Any, dcl: Any, dcd: Any
) -> Any:
    """c(ψ) per unit length [N·s/m²] of a section vibrating at angle ψ to the relative wind
    (derivatives per radian); scalars or arrays along the span."""
    s, c = np.sin(psi), np.cos(psi)
    return 0.5 * rho * chord * w * (2 * cd * c * c + (cl + dcd) * s * c + (dcl + cd) * s * s)


def builtin_polar(alpha_deg: Array) -> tuple[Array, Array]:
    """Thin-aerofoil lift with a flat-plate stall (see STALL_DEG): C_L, C_D at α [deg]."""
    a = np.radians(alpha_deg)
    flat_cl, flat_cd = 2 * np.sin(a) * np.cos(a), 2 * np.sin(a) ** 2
    s, f = math.radians(STALL_DEG), math.radians(FLAT_PLATE_DEG)
    mag = np.abs(a)
    t = np.clip((mag - s) / (f - s), 0.0, 1.0)
    attached_cl = 2 * np.pi * np.sign(a) * np.minimum(mag, s)
    cl = np.where(mag <= s, 2 * np.pi * a, (1 - t) * attached_cl + t * flat_cl)
    plate_at_f = 2 * math.sin(f) ** 2
    cd = np.where(
        mag <= s, CD0, np.where(mag >= f, np.maximum(flat_cd, CD0), CD0 + t * (plate_at_f - CD0))
    )
    return cl, cd


def polar_with_slopes(ae: "BladeAeroelastic", alpha_deg: Array) -> tuple[Array, ...]:
    """C_L, C_D and their slopes per radian (central differences, ±0.25°) at α [deg]."""

    def table(a: Array) -> tuple[Array, Array]:
        if ae.polar is None:
            return builtin_polar(a)
        p = ae.polar
        return np.interp(a, p.alpha_deg, p.cl), np.interp(a, p.alpha_deg, p.cd)

    h = 0.25
    cl, cd = table(alpha_deg)
    cl_p, cd_p = table(alpha_deg + h)
    cl_m, cd_m = table(alpha_deg - h)
    per_rad = 1 / math.radians(2 * h)
    return cl, cd, (cl_p - cl_m) * per_rad, (cd_p - cd_m) * per_rad


@dataclass(frozen=True)
class Point:
    """Damping of one mode at one operating point."""

    wind: float  # [m/s]
    rpm: float
    aero: float  # aerodynamic damping ratio ζ_a
    total: float  # ζ_a + structural
    alpha_tip_deg: float  # angle of attack at the outermost planform station


def _planform(spec: "Spec", radius: float) -> tuple[Array, Array, Array] | None:
    """Radii [m], chords [m] and chord angles to the rotor plane [deg] along the blade."""
    ae = spec.blade.aeroelastic
    assert ae is not None
    if ae.planform is not None:
        p = ae.planform
        return (
            np.asarray(p.radius_fraction) * radius,
            np.asarray(p.chord_m, float),
            np.asarray(p.twist_deg, float),
        )
    if len(ae.sections) >= 2:
        secs = sorted(ae.sections, key=lambda s: s.radius_fraction)
        return (
            np.array([s.radius_fraction * radius for s in secs]),
            np.array([s.chord_m for s in secs]),
            np.array([s.chord_angle_deg for s in secs]),
        )
    return None


def operating_points(spec: "Spec", radius: float) -> list[tuple[float, float]]:
    """(wind [m/s], rotor speed [rpm]) pairs over min_wind … max_wind in 0.5 m/s steps."""
    ae = spec.blade.aeroelastic
    assert ae is not None
    speed = spec.rotor.speed
    top_wind = ae.max_wind_m_s
    if ae.regulation == "pitch":  # pitching to feather lowers α above rated wind
        rated = ae.rated_wind_m_s
        if rated is None:  # the wind at which the variable-speed rotor reaches rated speed
            top_rpm = speed.rated_rpm or speed.top_rpm
            rated = float(rpm_to_rad_s(top_rpm)) * radius / ae.tip_speed_ratio
        top_wind = min(top_wind, rated)
    winds = np.arange(ae.min_wind_m_s, max(top_wind, ae.min_wind_m_s) + 1e-9, 0.5)
    if speed.fixed_rpm is not None:
        fixed = speed.fixed_rpm if isinstance(speed.fixed_rpm, list) else [speed.fixed_rpm]
        return [(float(v), float(n)) for n in fixed for v in winds]
    low, top = speed.steady_rpm[0][0], speed.rated_rpm or speed.top_rpm
    rpm = np.clip(rad_s_to_rpm(ae.tip_speed_ratio * winds / radius), low, top)
    return [(float(v), float(n)) for v, n in zip(winds, rpm, strict=True)]


def damping_curve(spec: "Spec", mode: "Mode", radius: float) -> list[Point] | None:
    """The mode's aerodynamic and total damping over the operating points; None without
    planform or mass data. With the spec's aerodynamics: the mode's damping in operation
    (the BEM operating points, :mod:`wtvib.aero.aerodamping`), so that this check and
    ``aerodynamics.stability`` judge the same numbers."""
    if spec.aerodynamics is not None:
        return _in_operation(spec, mode)
    ae = spec.blade.aeroelastic
    assert ae is not None
    plan = _planform(spec, radius)
    if plan is None:
        return None
    r_plan, chord_plan, twist_plan = plan
    root = spec.blade.structure.hub_radius_m if spec.blade.structure else float(r_plan[0])
    r = np.linspace(max(r_plan[0], root), radius, 60)
    chord = np.interp(r, r_plan, chord_plan)
    theta = np.interp(r, r_plan, twist_plan) + ae.pitch_deg
    shape = blade_shape(mode, np.concatenate([[root], r]), root)[1:]
    m = blade_mass(spec, r, root)
    if m is None:
        return None
    flap = mode.id.startswith("blade.flap")
    gen_mass = float(np.trapezoid(m * shape**2, r))
    if not gen_mass > 0:  # no blade outboard of the root (e.g. radius at the hub): no curve
        return None
    structural = mode.damping_ratio if mode.damping_ratio is not None else spec.blade.damping_ratio
    out = []
    for wind, rpm in operating_points(spec, radius):
        omega = float(rpm_to_rad_s(rpm))
        axial = wind * (1 - ae.axial_induction)
        phi = np.arctan2(axial, omega * r)
        w = np.hypot(axial, omega * r)
        alpha = np.degrees(phi) - theta
        cl, cd, dcl, dcd = polar_with_slopes(ae, alpha)
        psi = (np.pi / 2 - phi) if flap else (np.pi - phi)
        coeff = aero_damping_coefficient(ae.air_density_kg_m3, chord, w, psi, cl, cd, dcl, dcd)
        w_mode = 2 * math.pi * float(mode.frequency_at(omega)[()])
        zeta = float(np.trapezoid(coeff * shape**2, r)) / (2 * w_mode * gen_mass)
        out.append(Point(wind, rpm, zeta, zeta + structural, float(alpha[-1])))
    return out


_KIND = {"flap1": "flapwise", "edge1": "edgewise"}


def by_part(
    spec: "Spec", part: str, modes: "list[Mode] | tuple[Mode, ...]"
) -> tuple[list[Point], list[str]] | None:
    """At each operating point the least damped mode in operation whose energy sits mostly
    in ``part`` there (``blade.flap1``: the coupled model's modes, whose parts are known
    point by point — a mode followed through a veering changes part, so a name alone does
    not say which modes are flapwise where): the points and the mode of each; None where no
    mode has that part at any point — one truth per mode."""
    known = [m for m in modes if m.operating is not None and m.operating.part is not None]
    if not known:
        return None
    alpha = _tip_alpha(spec)
    points, ids = [], []
    for k in range(len(alpha)):
        here = [m for m in known if m.operating.part[k] == part]  # type: ignore[union-attr,index]
        if not here:
            continue
        low = min(here, key=lambda m: m.operating.total[k])  # type: ignore[union-attr]
        assert low.operating is not None
        points.append(_point(low.operating, k, alpha))
        ids.append(low.id)
    return (points, ids) if points else None


def _tip_alpha(spec: "Spec") -> Array:
    """The angle of attack [deg] at each operating point at the station inboard of the tip."""
    from .bem import schedule

    return np.asarray(np.degrees(schedule(spec).solution.alpha[:, -2]))


def _point(op: "OperatingDamping", k: int, alpha: Array) -> Point:
    """Operating point k of a mode's damping in operation."""
    rpm = float(rad_s_to_rpm(op.omega[k]))
    return Point(op.wind[k], rpm, op.aero[k], op.total[k], float(alpha[k]))


def _in_operation(spec: "Spec", mode: "Mode") -> list[Point] | None:
    op = mode.operating
    if op is None:
        return None
    alpha = _tip_alpha(spec)
    if len(alpha) != len(op.wind):
        raise ValueError("the mode's operating points are not the schedule's")
    return [_point(op, k, alpha) for k in range(len(alpha))]


def _attached(spec: "Spec", mode: "Mode", curve: list[Point]) -> bool:
    """Whether the negative points of an isolated mode's damping in operation (``curve``,
    the mode's operating points) lie in attached flow
    (:func:`wtvib.aero.aerodamping.isolated_in_attached_flow`)."""
    op = mode.operating
    if op is None or len(curve) != len(op.wind):
        return False
    return isolated_in_attached_flow(spec, op, [k for k, p in enumerate(curve) if p.total < 0])


def checks(spec: "Spec", modes: "list[Mode] | tuple[Mode, ...]") -> "list[Check]":
    """The stall checks alone (see :func:`judge`)."""
    return judge(spec, modes)[0]


def judge(
    spec: "Spec", modes: "list[Mode] | tuple[Mode, ...]"
) -> "tuple[list[Check], dict[str, list[Point]]]":
    """``blade.stall.flap1`` and ``blade.stall.edge1``: total damping over the operating
    range — negative fails, aerodynamic damping eating into the structural damping warns."""
    from ..results import Check
    from .aeroelastic import rotor_radius

    if spec.blade.aeroelastic is None and spec.aerodynamics is None:
        return [], {}
    radius = rotor_radius(spec)
    by_id = {m.id: m for m in modes}
    rule = _rule(spec)
    out = []
    curves: dict[str, list[Point]] = {}
    for name in ("flap1", "edge1"):
        cid = f"blade.stall.{name}"
        mode = by_id.get(f"blade.{name}")
        coupled = by_part(spec, f"blade.{name}", modes) if spec.aerodynamics else None
        ids: list[str] | None = None
        curve: list[Point] | None
        if coupled is not None:
            curve, ids = coupled
        else:
            curve = damping_curve(spec, mode, radius) if mode and radius else None
        if curve is None:
            need = ", ".join(_missing(spec, name, mode, radius))
            out.append(Check(cid, "blade", "info", "not analysed: needs " + need, rule))
            continue
        curves[name] = curve
        out.append(_judged(spec, cid, name, curve, ids, mode, rule))
    return out, curves


def _rule(spec: "Spec") -> "Rule":
    """The rule the stall checks apply, with the inflow their damping is computed in."""
    from ..results import Rule

    ae = spec.blade.aeroelastic
    if spec.aerodynamics is not None:
        how = (
            "induction in equilibrium"
            if spec.aerodynamics.induction == "equilibrium"
            else ("frozen induction")
        )
        inflow = (
            f"the aerodynamics' polars at the BEM operating points ({how}); {damping_words(spec)}"
        )
    else:
        assert ae is not None
        polar = "the spec's polar" if ae.polar else "the built-in thin-aerofoil/flat-plate polar"
        inflow = f"{polar}, axial induction a = {ae.axial_induction:g}"
    return Rule(
        "total modal damping (aerodynamic + structural) > 0; warn when the aerodynamic part "
        "is negative",
        "Hau ch. 7.2.3 (stall-induced vibration); blade-element damping c(ψ), M. H. Hansen, "
        "Wind Energy 10 (2007) 551–577; " + inflow,
    )


def _missing(spec: "Spec", name: str, mode: "Mode | None", radius: float | None) -> list[str]:
    """The spec fields a damping curve of ``blade.{name}`` needs and lacks."""
    return [
        n
        for n, ok in (
            (f"blade.modes.{name}", mode is not None),
            ("turbine.rotor_diameter_m", radius is not None),
            (
                "blade.aeroelastic.planform (or two sections)",
                radius is None
                or spec.aerodynamics is not None
                or _planform(spec, radius) is not None,
            ),
            (
                "blade.mass_kg or blade.structure",
                spec.blade.mass_kg is not None or spec.blade.structure is not None,
            ),
        )
        if not ok
    ]


def _judged(
    spec: "Spec",
    cid: str,
    name: str,
    curve: list[Point],
    ids: list[str] | None,
    mode: "Mode | None",
    rule: "Rule",
) -> "Check":
    """One stall check from its damping curve (``ids``: the coupled mode least damped at
    each point, where the curve is the coupled model's): negative total damping fails —
    warns where the flow is attached there (:func:`_attached`) — and negative aerodynamic
    damping warns."""
    from ..results import Check

    lowest = min(range(len(curve)), key=lambda i: curve[i].total)
    low = curve[lowest]
    low_aero = min(curve, key=lambda p: p.aero)
    # below zero beyond rounding's sign (a ζ of −1e-9 at one point is no band of instability)
    negative = [p for p in curve if p.total < -NEGATIVE]
    where = f"{low.wind:.3g} m/s wind at {low.rpm:.3g} rpm (α_tip = {low.alpha_tip_deg:.1f}°)"
    if ids is not None:
        where += f", as {ids[lowest]} (the least damped {_KIND[name]} mode there)"
    status: Status
    attached = bool(negative) and ids is None and mode is not None and _attached(spec, mode, curve)
    if negative:
        status = "warn" if attached else "fail"
        first, last = negative[0].wind, negative[-1].wind
        span = (
            f"at {first:.4g} m/s"
            if f"{first:.4g}" == f"{last:.4g}"
            else (f"from {first:.4g} to {last:.4g} m/s")
        )
        text = f"negative total damping ζ = {low.total:.4f} at {where}; " + (
            f"negative {span}" if attached else f"unstable {span}"
        )
        if attached:
            assert mode is not None
            text += f" ({attached_flow_note(mode.id)})"
    elif low_aero.aero < -NEGATIVE:
        status = "warn"
        text = (
            f"aerodynamic damping negative (ζ_a = {low_aero.aero:.4f}); "
            f"lowest total {low.total:.4f} at {where}"
        )
    else:
        status = "pass"
        text = f"lowest total damping ζ = {max(low.total, 0.0):.3f} at {where}"
    numbers = {
        "min_total_damping_ratio": round(low.total, 6),
        "at_wind_m_s": low.wind,
        "at_rpm": round(low.rpm, 4),
        "curve": [
            {
                "wind_m_s": p.wind,
                "rpm": round(p.rpm, 4),
                "aero_damping_ratio": round(p.aero, 6),
                "total_damping_ratio": round(p.total, 6),
            }
            for p in curve
        ],
    }
    return Check(cid, "blade", status, text, rule, numbers)


# ---------------------------------------------------------------------------------------
# The subsystem protocol (wtvib.judge.analysis): stall-induced vibration of the blade

NAME = "stall"


default_damping = blade_damping
build_modes = no_modes  # it judges the blade's modes


@dataclass(frozen=True)
class StallResults:
    """What the stall figure draws: each judged mode's total damping over the operating
    points."""

    curves: "dict[str, list[Point]]"
    damping: str = "quasi-steady damping"  # how the curves' damping was computed, in words


def damping_words(spec: "Spec") -> str:
    """How the stall check's damping is computed, as the figure's title says it: Hau's
    quasi-steady blade elements, or the damping in operation of the aerodynamics block with
    the lift's lags it has (shed wake, separation)."""
    aero = spec.aerodynamics
    if aero is None:
        return "quasi-steady damping"
    lags = [
        w for w, on in (("shed wake", aero.shed_wake), ("dynamic stall", aero.dynamic_stall)) if on
    ]
    return "damping in operation" + (
        f", lift lagged ({' and '.join(lags)})" if lags else ", quasi-steady lift"
    )


def analyse(spec: "Spec", ctx: Context) -> Analysis:
    """``blade.stall.flap1`` and ``blade.stall.edge1``, with the damping curves they judge."""
    found, curves = judge(spec, list(ctx.modes))
    results = StallResults(curves, damping_words(spec)) if curves else None
    return Analysis(checks=tuple(found), results=results)


SUBSYSTEM = Subsystem(
    NAME,
    build_modes,
    default_damping,
    analyse,
    figures=("blade-stall",),
)
