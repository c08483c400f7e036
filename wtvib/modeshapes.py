"""Mode-shape drawings (drive train: which masses swing against which, Hau Fig. 7.12).

Calculate first, draw second: the shapes come from :class:`~wtvib.results.Mode` objects.
"""

from typing import TYPE_CHECKING

import numpy as np

from .audit import Report

if TYPE_CHECKING:
    from matplotlib.figure import Figure


def drivetrain_shapes_plot(report: Report) -> "Figure | None":
    """One panel per condition: each computed drive-train mode's twist amplitude per mass."""
    from matplotlib.figure import Figure

    modes = [m for m in report.modes if m.subsystem == "drivetrain" and m.shape is not None]
    if not modes:
        return None
    conditions = list(dict.fromkeys(m.id.split(".")[1] for m in modes))
    fig = Figure(figsize=(10, 2.6 * len(conditions) + 0.8), dpi=150, layout="constrained")
    axes = fig.subplots(len(conditions), 1, squeeze=False)[:, 0]
    for ax, condition in zip(axes, conditions, strict=True):
        for m in (m for m in modes if m.id.split(".")[1] == condition):
            assert m.shape is not None
            x = np.arange(len(m.shape.deflection))
            ax.plot(
                x,
                m.shape.deflection,
                marker="o",
                lw=2,
                label=f"{m.id.split('.', 1)[1]}: {m.frequency_hz:.3g} Hz — "
                f"{m.description.split(': ', 1)[-1].replace(' (computed)', '')}",
            )
            ax.set_xticks(x, m.shape.labels or [str(i) for i in x])
        ax.axhline(0, color="#9e9e9e", lw=0.8)
        ax.set_ylabel("twist amplitude")
        ax.set_title(f"condition: {condition}", loc="left", fontsize=10)
        ax.legend(fontsize=7, loc="best")
        ax.grid(True, alpha=0.3)
    fig.suptitle(
        f"{report.spec.turbine.name} — drive-train mode shapes (reduced to the "
        f"{report.spec.drivetrain.reference_shaft} shaft)",
        fontweight="bold",
    )
    return fig


def power_curve_plot(report: Report) -> "Figure | None":
    """The grid-coupled synchronous drive train's first mode over power (Hau Fig. 7.14)."""
    from matplotlib.figure import Figure

    check = next((c for c in report.checks if c.id == "drivetrain.grid.power"), None)
    curve = report.results.get("drivetrain", {}).get("power")
    if check is None or curve is None:
        return None
    power = 100 * np.asarray(curve.power_fraction)
    fig = Figure(figsize=(8, 4.5), dpi=150, layout="constrained")
    ax = fig.add_subplot()
    ax.plot(power, curve.frequency_hz, lw=2.2, color="#1f77b4", label="1st grid mode")
    lo, hi = report.rule.natural_band(1.0)
    for label, f_e in curve.lines:
        ax.axhline(f_e, color="#212121", lw=1.4)
        ax.axhspan(f_e * lo, f_e * hi, color="#e53935", alpha=0.12, lw=0)
        ax.annotate(
            label,
            (power[-1], f_e),
            xytext=(-4, 3),
            textcoords="offset points",
            ha="right",
            fontsize=9,
        )
    ax.set_xlabel("electrical power [% of rated]")
    ax.set_ylabel("frequency [Hz]")
    ax.set_title(
        f"{report.spec.turbine.name} — drive train on the grid: frequency vs power "
        f"({check.status.upper()})",
        fontweight="bold",
    )
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    return fig


def floquet_plot(report: Report) -> "Figure | None":
    """The two-bladed rotor's stability map: largest Floquet multiplier over rotor speed."""
    from matplotlib.figure import Figure

    check = next((c for c in report.checks if c.id == "rotor.floquet"), None)
    smap = report.results.get("rotor", {}).get("map")
    if check is None or smap is None:
        return None
    rpm, rho = smap.speeds_rpm, smap.largest
    speed = report.spec.rotor.speed
    fig = Figure(figsize=(9, 4.8), dpi=150, layout="constrained")
    ax = fig.add_subplot()
    for a, b in speed.steady_rpm:
        if b > a:
            ax.axvspan(a, b, color="#c8e6c9", alpha=0.6, lw=0, label="steady operation")
        else:
            ax.axvline(a, color="#66bb6a", lw=6, alpha=0.5, label="operating speed")
    ax.axvspan(speed.top_rpm, speed.overspeed, color="#fff3e0", lw=0, label="overspeed")
    for a, b in smap.unstable_rpm:
        ax.axvspan(a, b, color="#e53935", alpha=0.2, lw=0)
    ax.plot(rpm, rho, color="#1f77b4", lw=2, label="largest |ρ| (Floquet multiplier)")
    # a span of at least ±5 % about |ρ| = 1: rounding (1e-12) is not drawn as structure
    finite = rho[np.isfinite(rho)]
    low = min(0.95, float(finite.min(initial=1.0)) - 0.01)
    high = max(1.05, float(finite.max(initial=1.0)) + 0.01)
    ax.set_ylim(low, high)
    ax.ticklabel_format(axis="y", useOffset=False)
    ax.axhline(1.0, color="#212121", lw=1, ls="--", label="stability limit |ρ| = 1")
    ax.set_xlabel("rotor speed [rpm]")
    ax.set_ylabel("largest Floquet multiplier |ρ|")
    ax.set_title(
        f"{report.spec.turbine.name} — {check.numbers['hub']} two-bladed rotor on the "
        f"tower head: stability map ({check.status.upper()})",
        fontweight="bold",
        fontsize=10,
    )
    ax.grid(True, alpha=0.3)
    handles, labels = ax.get_legend_handles_labels()
    unique = dict(zip(labels, handles, strict=True))
    ax.legend(unique.values(), unique.keys(), fontsize=8, loc="best")
    return fig


def flutter_plot(report: Report) -> "Figure | None":
    """V-g and V-f curves (p-k method) of the blade section nearest to flutter."""
    from matplotlib.figure import Figure

    check = next((c for c in report.checks if c.id == "blade.flutter"), None)
    found = report.results.get("aeroelastic", {})
    if check is None or "worst" not in found:
        return None
    worst, required = found["worst"], found["required_speed_m_s"]
    fig = Figure(figsize=(9, 6.4), dpi=150, layout="constrained")
    ax_g, ax_f = fig.subplots(2, 1, sharex=True)
    colours = ("#1f77b4", "#d62728")
    names = ("bending branch", "torsion branch")
    for branch, colour, label in zip(worst.flutter.branches, colours, names, strict=False):
        f = np.asarray(branch.omega, dtype=float) / (2 * np.pi)
        # real (non-oscillatory) roots are outside the p-k method's validity: not drawn
        g = np.where(f > 0, -np.asarray(branch.damping), np.nan)
        ax_g.plot(branch.speed, g, color=colour, lw=2, label=label)
        ax_f.plot(branch.speed, np.where(f > 0, f, np.nan), color=colour, lw=2, label=label)
    for ax in (ax_g, ax_f):
        ax.axvline(worst.section_speed, color="#616161", ls="--", lw=1.2)
        ax.axvspan(
            worst.section_speed,
            required,
            color="#fff3e0",
            lw=0,
            label="required margin",
        )
        ax.grid(True, alpha=0.3)
    ax_g.axhline(0.0, color="#212121", lw=1)
    ax_g.text(
        0.99,
        0.02,
        "where the curves merge or end, the other root is overdamped (not oscillating)",
        transform=ax_g.transAxes,
        fontsize=7,
        ha="right",
        color="#616161",
    )
    ax_g.annotate(
        "highest section speed",
        (worst.section_speed, 0.98),
        xycoords=("data", "axes fraction"),
        fontsize=8,
        rotation=90,
        va="top",
        ha="right",
        color="#616161",
    )
    ax_g.set_ylabel("aeroelastic growth rate −ζ\n(> 0: unstable)")
    ax_f.set_ylabel("frequency [Hz]")
    ax_f.set_xlabel("section air speed [m/s]")
    ax_g.legend(fontsize=8, loc="best")
    ax_g.set_title(
        f"{report.spec.turbine.name}\nblade flutter at r = {worst.radius_m:.3g} m, "
        f"Theodorsen p-k ({check.status.upper()})",
        fontweight="bold",
        fontsize=10,
    )
    return fig


def stability_chart_plot(report: Report) -> "Figure | None":
    """Hau Fig. 7.6 for the blade section nearest to flutter: torsional stiffness against the
    centre-of-mass offset, divergence and flutter limits at the required speed, the blade."""
    from matplotlib.figure import Figure

    check = next((c for c in report.checks if c.id == "blade.flutter"), None)
    found = report.results.get("aeroelastic", {})
    ae = report.spec.blade.aeroelastic
    if check is None or "chart" not in found or ae is None:
        return None
    n = check.numbers
    chart, speed, worst = found["chart"], found["required_speed_m_s"], found["worst"]
    x = 100 * chart.offset_chord
    kilo = 1e-3
    fig = Figure(figsize=(9, 5.6), dpi=150, layout="constrained")
    ax = fig.add_subplot()
    flutter_k = chart.flutter_k_theta * kilo
    top = 3 * max(
        np.nanmax(flutter_k, initial=0.0),
        chart.divergence_k_theta * kilo,
        chart.blade_k_theta * kilo,
    )
    bottom = 0.1 * min(chart.blade_k_theta * kilo, chart.divergence_k_theta * kilo or top)
    ax.fill_between(
        x,
        bottom,
        np.where(np.isfinite(flutter_k), flutter_k, bottom),
        where=np.isfinite(flutter_k),
        color="#e53935",
        alpha=0.18,
        lw=0,
        label="flutter",
    )
    ax.plot(x, flutter_k, color="#c62828", lw=2, label="flutter limit")
    if chart.divergence_k_theta > 0:
        ax.axhspan(
            bottom,
            chart.divergence_k_theta * kilo,
            color="#fb8c00",
            alpha=0.15,
            lw=0,
            label="divergence",
        )
        ax.axhline(
            chart.divergence_k_theta * kilo,
            color="#ef6c00",
            lw=2,
            ls="--",
            label="divergence limit",
        )
    ax.plot(
        100 * chart.blade_offset_chord,
        chart.blade_k_theta * kilo,
        "o",
        ms=10,
        color="#1565c0",
        label=f"blade section at r = {worst.radius_m:.3g} m",
    )
    ratio = n.get("speed_ratio")
    ax.annotate(
        f"flutter at {ratio:.2f}× the highest section speed" if ratio else "no flutter found",
        (100 * chart.blade_offset_chord, chart.blade_k_theta * kilo),
        xytext=(10, 10),
        textcoords="offset points",
        fontsize=8,
        color="#1565c0",
    )
    ax.axvline(0.0, color="#616161", lw=0.8)
    ax.set_yscale("log")
    ax.set_ylim(bottom, top)
    ax.set_xlabel("centre of mass behind the elastic axis [% chord]")
    ax.set_ylabel("torsional stiffness k_θ [kN·m/rad per m]")
    ax.set_title(
        f"{report.spec.turbine.name}\nblade stability limits at {speed:.3g} m/s "
        f"({1 + ae.speed_margin:g}× the highest section speed; Hau Fig. 7.6)",
        fontweight="bold",
        fontsize=10,
    )
    ax.grid(True, which="both", alpha=0.25)
    ax.legend(fontsize=8, loc="lower right")
    return fig


def stall_damping_plot(report: Report) -> "Figure | None":
    """Total and aerodynamic damping of the first flap and edge modes over the wind speed."""
    from matplotlib.figure import Figure

    found = report.results.get("stall", {}).get("curves", {})
    by_id = {c.id: c for c in report.checks}
    curves = {name: by_id[f"blade.stall.{name}"] for name in found}
    if not curves:
        return None
    fig = Figure(figsize=(9, 5.2), dpi=150, layout="constrained")
    axes = fig.subplots(len(curves), 1, sharex=True, squeeze=False)[:, 0]
    colours = {"pass": "#2e7d32", "warn": "#ef6c00", "fail": "#c62828", "info": "#1565c0"}
    for ax, (name, check) in zip(axes, curves.items(), strict=True):
        pts = found[name]
        wind = np.array([p.wind for p in pts])
        total = 100 * np.array([p.total for p in pts])
        aero = 100 * np.array([p.aero for p in pts])
        ax.axhline(0.0, color="#212121", lw=1)
        ax.fill_between(
            wind,
            total,
            0,
            where=total < 0,
            color="#e53935",
            alpha=0.25,
            lw=0,
            label="negative total damping",
        )
        ax.plot(wind, total, color=colours[check.status], lw=2, label="total (aero + structural)")
        ax.plot(wind, aero, color="#616161", lw=1.2, ls="--", label="aerodynamic")
        ax.set_ylabel(f"{name}: ζ [%]")
        ax.set_title(f"{name}: {check.status.upper()} — {check.message}", fontsize=8, loc="left")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="best")
    axes[-1].set_xlabel("wind speed [m/s]")
    fig.suptitle(
        f"{report.spec.turbine.name}\nstall-induced vibration: quasi-steady damping "
        "(Hau ch. 7.2.3)",
        fontweight="bold",
        fontsize=10,
    )
    return fig


#: Colours of the coordinate groups in the coupled-mode energy chart.
_GROUP_COLOUR = {
    "tower.fa": "#1f77b4",
    "tower.ss": "#17becf",
    "tower.tor": "#7f7f7f",
    "yaw": "#bcbd22",
    "drivetrain": "#8c564b",
}
_BLADE_COLOURS = ["#d62728", "#ff9896", "#2ca02c", "#98df8a", "#9467bd", "#c5b0d5"]


def coupled_energy_plot(report: Report) -> "Figure | None":
    """Where each parked coupled mode's kinetic energy sits (check ``system.coupling``):
    one bar per mode, split by tower, yaw, drive train and blade groups — a mode of one
    colour is a subsystem mode, a mixed bar is a coupling mode (Hau §7.6)."""
    from matplotlib.figure import Figure

    check = next((c for c in report.checks if c.id == "system.coupling"), None)
    if check is None:
        return None
    rows = check.numbers["modes"]
    groups = list(dict.fromkeys(g for r in rows for g in r["energy"]))
    blade_groups = [g for g in groups if g.startswith("blade.")]
    colour = {**_GROUP_COLOUR, **dict(zip(blade_groups, _BLADE_COLOURS * 3, strict=False))}
    fig = Figure(figsize=(10, 0.32 * len(rows) + 1.8), dpi=150, layout="constrained")
    ax = fig.subplots()
    y = np.arange(len(rows))[::-1]
    for g in groups:
        left = [sum(r["energy"].get(h, 0.0) for h in groups[: groups.index(g)]) for r in rows]
        width = [r["energy"].get(g, 0.0) for r in rows]
        ax.barh(y, width, left=left, color=colour.get(g, "#cccccc"), label=g, height=0.7)
    ax.set_yticks(y, [f"{r['id'].removeprefix('system.')}  {r['coupled_hz']:.3g} Hz" for r in rows])
    ax.tick_params(axis="y", labelsize=7)
    ax.set_xlim(0, 1)
    ax.set_xlabel("share of the mode's kinetic energy")
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=4, frameon=False)
    ax.set_title(
        f"{report.spec.turbine.name} — coupled modes, {check.numbers['condition']}: "
        "where the energy is",
        fontweight="bold",
        fontsize=10,
    )
    return fig
