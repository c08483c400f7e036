"""Drive-train torsion: N-mass chain, reduction to one shaft, generator coupling, modes.

The chain runs from the rotor end (blades) to the generator; every inertia, stiffness and
damping is reduced to the reference shaft conserving energy, J′ = i²J, k′ = i²k, d′ = i²d,
with i = (speed of its shaft) / (reference speed) (Hau ch. 7.3.1). The blades' edgewise
flexibility enters as a spring k_b = J_b·ω_edge² between blades and hub (Hau ch. 7.3.1;
DOMAIN.md §3). The generator's electrical coupling (Hau Fig. 7.11) makes the conditions:

* ``grid`` — synchronous on the grid: a torsion spring to ground (:func:`synchronous_stiffness`,
  power dependent); induction on the grid: a damper to ground (:func:`induction_damping`),
  which leaves a 0 Hz rigid-body root; converter-fed: free end with the controller's damping;
* ``free`` — idling, isolated operation or after a grid loss: free end;
* ``locked`` — brake applied: the generator end clamped.
"""

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace

import numpy as np
from numpy.typing import NDArray

from ..judge.analysis import Analysis, Context, Damping, Subsystem, section_damping
from ..judge.excitation import Excitation, OperatingRange
from ..judge.resonance import lines_met
from ..numerics import modal
from ..results import Check, Mode, Rule, Shape, by_frequency, ordinal
from ..rules import MarginRule
from ..spec import ChainShaft, Spec
from ..units import rpm_to_rad_s
from .given import given_modes

Array = NDArray[np.float64]

CONDITIONS = {
    "grid": "generator on the grid",
    "free": "idling / isolated operation (free end)",
    "locked": "brake applied (clamped end)",
}
#: Regimes in which each condition exists: on the grid in operation; free while idling,
#: starting, stopping and after a grid loss (overspeed); locked only at standstill.
REGIMES = {
    "grid": frozenset({"steady", "quick-pass", "overspeed"}),
    "free": frozenset({"start-up", "overspeed"}),
    "locked": frozenset(),
}


def synchronous_stiffness(
    pull_out_power_w: float, power_w: float, pole_pairs: int, grid_hz: float
) -> float:
    """Magnetic torsional stiffness of a grid-coupled synchronous generator. [N·m/rad]

    Notes
    -----
    Electrical torque T = (P_max/Ω_s)·sin δ with Ω_s = 2πf/p and electrical angle δ = p·θ;
    for small oscillations about δ₀ = asin(P/P_max): c_m = dT/dθ = p²·P_max·cos δ₀/(2πf),
    on the generator shaft. Example: P_max 3 MW, P 1.5 MW, p = 2, 50 Hz → δ₀ = 30°,
    c_m ≈ 33,080 N·m/rad.

    References
    ----------
    Hau ch. 7.3.2, Fig. 7.11 (magnetic torsion spring c_m); DOMAIN.md §3.
    """
    if not 0 <= power_w < pull_out_power_w:
        raise ValueError("power must lie between 0 and the pull-out power")
    delta0 = math.asin(power_w / pull_out_power_w)
    return pole_pairs**2 * pull_out_power_w * math.cos(delta0) / (2 * math.pi * grid_hz)


def induction_damping(rated_power_w: float, slip: float, pole_pairs: int, grid_hz: float) -> float:
    """Magnetic damping of a grid-coupled induction generator. [N·m·s/rad]

    Notes
    -----
    In the linear part of the torque–slip curve T = d_m·(Ω − Ω_s), so d_m = T_rated/(s·Ω_s)
    with Ω_s = 2πf/p. The rated torque is taken at the rated, supersynchronous (generating)
    speed Ω_s·(1 + s): T_rated = P/(Ω_s·(1 + s)). Example: 1.5 MW, s = 1 %, p = 2, 50 Hz →
    d_m ≈ 6,019 N·m·s/rad.

    References
    ----------
    Hau ch. 7.3.2, Fig. 7.11 (magnetic damper d_m); DOMAIN.md §3.
    """
    omega_s = 2 * math.pi * grid_hz / pole_pairs
    torque = rated_power_w / (omega_s * (1 + slip))
    return torque / (slip * omega_s)


class ModelInputError(modal.ModalError):
    """A drive-train model that lacks an input it needs for a condition."""


@dataclass(frozen=True)
class Chain:
    """A drive train reduced to the reference shaft: inertias, and springs/dampers between."""

    names: tuple[str, ...]
    inertia: Array
    stiffness: Array
    damping: Array
    generator_factor: float  # i² of the generator shaft, to reduce generator-side values
    #: Per mass: Σ J_own (inertia on its own shaft) and Σ J_own·i (i its speed over the
    #: reference shaft's): how each mass's rotation reacts on the nacelle (roll), used by
    #: the coupled model (``wtvib.subsystems.coupled``).
    own: Array = field(default_factory=lambda: np.zeros(0))
    coupling: Array = field(default_factory=lambda: np.zeros(0))

    def matrices(self) -> tuple[Array, Array, Array]:
        """M, K, D of the free–free chain."""
        n = len(self.names)
        k = np.zeros((n, n))
        d = np.zeros((n, n))
        for j, (kj, dj) in enumerate(zip(self.stiffness, self.damping, strict=True)):
            for mat, val in ((k, kj), (d, dj)):
                mat[j, j] += val
                mat[j + 1, j + 1] += val
                mat[j, j + 1] -= val
                mat[j + 1, j] -= val
        return np.diag(self.inertia), k, d


def hub_inertia(spec: Spec) -> float:
    """The hub's polar inertia about the shaft: the coupled block's ``hub_inertia_kgm2``,
    else the first mass of the chain after the blades (reduced to the rotor's shaft, with
    what is rigidly joined to it), 0 without a chain. [kg·m²]"""
    cm = spec.coupled
    if cm is not None and cm.hub_inertia_kgm2 is not None:
        return cm.hub_inertia_kgm2
    dt = spec.drivetrain
    if not dt.chain:
        return 0.0
    skip = 1 if dt.chain[0].name == "blades" else 0
    rest, shafts = dt.chain[skip:], dt.shafts[skip:]
    rigid_shafts = all(s.stiffness_nm_rad is None and s.fluid_coupling is None for s in shafts)
    if len(rest) < 2 or rigid_shafts:  # a rigid shaft (a deck's DrTrDOF off): the hub's own
        return rest[0].inertia_kgm2 if rest else 0.0
    sub = spec.model_copy(
        update={
            "drivetrain": dt.model_copy(
                update={"chain": rest, "shafts": shafts, "reference_shaft": "rotor"}
            )
        }
    )
    return float(reduce(sub, rigid_ok=True).inertia[0])


def reduce(spec: Spec, edge_hz: float | None = None, rigid_ok: bool = False) -> Chain:
    """The spec's chain reduced to its reference shaft.

    With a first mass named ``blades`` and the blades' first edgewise frequency known, the
    blade–hub connection gets the edgewise spring k_b = J_b·ω_edge² (in series with a given
    shaft; alone where the connection is rigid). Other rigid connections merge their masses.
    """
    dt = spec.drivetrain
    ref = 1.0 if dt.reference_shaft == "rotor" else dt.chain[-1].speed_ratio
    names = [dt.chain[0].name]
    inertia = [dt.chain[0].inertia_kgm2 * (dt.chain[0].speed_ratio / ref) ** 2]
    own = [dt.chain[0].inertia_kgm2]
    coupling = [dt.chain[0].inertia_kgm2 * dt.chain[0].speed_ratio / ref]
    stiffness: list[float] = []
    damping: list[float] = []
    for j, (shaft, mass) in enumerate(zip(dt.shafts, dt.chain[1:], strict=True)):
        i2 = (shaft.speed_ratio / ref) ** 2
        k = None if shaft.stiffness_nm_rad is None else shaft.stiffness_nm_rad * i2
        shaft_damping = shaft.damping_nms_rad
        if shaft.fluid_coupling is not None:
            k, shaft_damping = 0.0, fluid_coupling_damping(spec, shaft)
        if j == 0 and dt.blade_edge_spring and edge_hz and names[0] == "blades":
            k_b = inertia[0] * (2 * math.pi * edge_hz) ** 2
            k = k_b if k is None else 1.0 / (1.0 / k_b + 1.0 / k)
        j_mass = mass.inertia_kgm2 * (mass.speed_ratio / ref) ** 2
        if k is None:  # rigid: one mass
            names[-1] = f"{names[-1]}+{mass.name}"
            inertia[-1] += j_mass
            own[-1] += mass.inertia_kgm2
            coupling[-1] += mass.inertia_kgm2 * mass.speed_ratio / ref
            continue
        names.append(mass.name)
        inertia.append(j_mass)
        own.append(mass.inertia_kgm2)
        coupling.append(mass.inertia_kgm2 * mass.speed_ratio / ref)
        stiffness.append(k)
        damping.append(shaft_damping * i2)
    if not stiffness and not rigid_ok:
        raise ModelInputError("the drive-train chain has no flexible connection left")
    gen = (dt.chain[-1].speed_ratio / ref) ** 2
    return Chain(
        tuple(names),
        np.array(inertia),
        np.array(stiffness),
        np.array(damping),
        gen,
        np.array(own),
        np.array(coupling),
    )


def fluid_coupling_damping(spec: Spec, shaft: ChainShaft) -> float:
    """The small-oscillation damping [N·m·s/rad, on the shaft's own speed] of a fluid
    coupling (Hau 7.3.3): near its working point the torque it passes grows with the slip,
    T = T_r·s/s_r at the shaft speed ω, so a change of the speed difference Δω across it
    passes ΔT = T_r/(s_r·ω)·Δω — a damper, with no spring. T_r = P_r/ω at rated power and
    rated rotor speed; with the torque proportional to the slip the damping is the same at
    part load (the slip falls with the torque), so one value serves the whole range."""
    assert shaft.fluid_coupling is not None
    rated_kw = (
        spec.drivetrain.generator_model.rated_power_kw
        if spec.drivetrain.generator_model is not None
        else spec.turbine.rated_power_kw
    )
    if rated_kw is None:
        raise ModelInputError(
            "a fluid coupling's damping needs the rated power: turbine.rated_power_kw or "
            "drivetrain.generator_model.rated_power_kw"
        )
    omega = rpm_to_rad_s(max(spec.rotor.speed.dwell_rpm)) * shaft.speed_ratio
    torque = rated_kw * 1e3 / omega
    return float(torque / (shaft.fluid_coupling.rated_slip * omega))


#: Every regime: the condition the turbine runs in throughout.
ALWAYS = frozenset({"steady", "quick-pass", "overspeed", "start-up"})


def held(spec: Spec) -> bool:
    """Whether the generator is held at the rotor's speed while it turns — the coupled
    model's rotating condition ``locked``, as an OpenFAST deck read as OpenFAST models it
    with ElastoDyn's GenDOF off (a fixed-speed generator) has it: then the clamped-end
    modes are the turning turbine's, in every regime, and the free-end modes are no mode of
    it (its generator is never free)."""
    return spec.coupled is not None and spec.coupled.rotating_condition == "locked"


def regimes(spec: Spec, condition: str) -> frozenset[str]:
    """The operating regimes a generator condition exists in.

    With a grid (or converter) coupling the turbine runs on it and is free only while
    idling or after a grid loss (start-up, overspeed); without one, free *is* the operating
    condition (a torque-controlled generator the spec does not model), in every regime.
    Locked (brake applied) exists in none: its modes are reported, never judged — but where
    the generator is held at the rotor's speed (:func:`held`), locked is the condition in
    every regime and free in none.
    """
    if held(spec) and condition in ("free", "locked"):
        return ALWAYS if condition == "locked" else frozenset()
    if condition == "free" and "grid" not in conditions(spec):
        return ALWAYS
    return REGIMES[condition]


def conditions(spec: Spec) -> list[str]:
    """The conditions the turbine can be in: grid (if coupled), free, locked."""
    dt = spec.drivetrain
    out = []
    if dt.grid_coupling != "isolated" and (
        dt.generator in ("synchronous", "induction", "converter") or dt.grid_coupling == "converter"
    ):
        out.append("grid")
    return [*out, "free", "locked"]


def system(
    chain: Chain, spec: Spec, condition: str, power_fraction: float = 1.0
) -> tuple[Array, Array, Array]:
    """M, K, D of the chain in one condition (generator coupling applied to the last mass)."""
    m, k, d = chain.matrices()
    dt = spec.drivetrain
    g = dt.generator_model
    if condition == "locked":
        return m[:-1, :-1], k[:-1, :-1], d[:-1, :-1]
    if condition == "grid" and g is not None:
        if dt.generator == "synchronous" and dt.grid_coupling == "direct":
            if g.pull_out_power_kw is None:
                raise ModelInputError(
                    "drivetrain.generator_model.pull_out_power_kw is needed "
                    "for a grid-coupled synchronous generator"
                )
            c_m = synchronous_stiffness(
                g.pull_out_power_kw * 1e3,
                power_fraction * g.rated_power_kw * 1e3,
                g.pole_pairs,
                g.grid_frequency_hz,
            )
            k[-1, -1] += c_m * chain.generator_factor
        elif dt.generator == "induction" and dt.grid_coupling == "direct":
            if g.rated_slip is None:
                raise ModelInputError(
                    "drivetrain.generator_model.rated_slip is needed for a "
                    "grid-coupled induction generator"
                )
            d_m = induction_damping(
                g.rated_power_kw * 1e3, g.rated_slip, g.pole_pairs, g.grid_frequency_hz
            )
            d[-1, -1] += d_m * chain.generator_factor
        else:
            d[-1, -1] += g.controller_damping_nms_rad * chain.generator_factor
    return m, k, d


def describe(shape: Array, names: tuple[str, ...], inertia: Array, condition: str) -> str:
    """Which masses swing against which (Hau Fig. 7.12 wording), from a real mode shape.

    Each side is named by the mass with the largest kinetic-energy share J·a² among those
    moving that way; masses with under 1 % of the mode's energy count as standing still.
    """
    energy = inertia * shape**2
    total = float(energy.sum()) or 1.0
    moving = energy > 0.01 * total
    pos = [i for i in range(len(shape)) if moving[i] and shape[i] > 0]
    neg = [i for i in range(len(shape)) if moving[i] and shape[i] < 0]
    ground = {
        "grid": "the grid",
        "locked": "the brake",
        "free": "the nearly still rest of the train",
    }[condition]
    if not pos or not neg:
        side = pos or neg
        if len(side) == len(shape):
            return f"whole train against {ground}"
        return f"{names[max(side, key=lambda i: energy[i])]} against {ground}"
    return (
        f"{names[max(pos, key=lambda i: energy[i])]} against "
        f"{names[max(neg, key=lambda i: energy[i])]}"
    )


def edge_frequency(spec: Spec, blade_modes: list[Mode]) -> float | None:
    """The blades' first edgewise frequency at standstill, computed or given. [Hz]"""
    return next((m.frequency_hz for m in blade_modes if m.id == "blade.edge1"), None)


#: A mode whose damping ratio from the train's dampers is below this has none worth stating:
#: its damping ratio is the train's material damping alone.
DAMPERS_FLOOR = 1e-6


def rigid(spec: Spec, blade_modes: list[Mode]) -> bool:
    """Whether a deck's switches leave the chain without a flexible connection: its blades
    rigid in-plane (their edgewise DOF off) and every shaft rigid (ElastoDyn's DrTrDOF
    off) — then it has no torsion modes. A spec that says so by itself is refused where
    the chain is reduced."""
    dt = spec.drivetrain
    edge_off = spec.blade.dofs is not None and "edge1" not in spec.blade.dofs
    return edge_off and all(
        s.stiffness_nm_rad is None and s.fluid_coupling is None for s in dt.shafts
    )


def modes(spec: Spec, blade_modes: list[Mode] | None = None) -> list[Mode]:
    """Drive-train modes per condition (ids ``drivetrain.<condition>.<k>``)."""
    if not spec.drivetrain.chain or rigid(spec, blade_modes or []):
        return _given(spec)
    chain = reduce(spec, edge_frequency(spec, blade_modes or []))
    material = default_damping(spec)
    out: list[Mode] = []
    for condition in conditions(spec):
        m, k, d = system(chain, spec, condition)
        res = modal.damped(k, m, d)
        names = chain.names[: m.shape[0]]
        positions = tuple(float(i) for i in range(len(names)))
        for j, f in enumerate(res.frequency_hz, start=1):
            # the dampers' part (generator, couplings, shafts) adds to the train's material
            # damping: a mode that barely moves the generator must not lose it to the
            # generator's 2e-5 (Aeroman, grid: its third mode)
            ratio, source = material.with_dampers(
                float(res.damping_ratio[j - 1]), DAMPERS_FLOOR, "the dampers"
            )
            out.append(
                Mode(
                    id=f"drivetrain.{condition}.{j}",
                    subsystem="drivetrain",
                    description=f"{ordinal(j)} drive-train torsion, {CONDITIONS[condition]}: "
                    f"{describe(res.shapes[:, j - 1], names, np.diag(m), condition)} (computed)",
                    frequency_hz=float(f),
                    damping_ratio=ratio,
                    damping_source=source,
                    shape=Shape(positions, tuple(res.shapes[:, j - 1].tolist()), names),
                    regimes=regimes(spec, condition),
                    condition=CONDITIONS[condition],
                    origin="computed",
                )
            )
    return out


def _given(spec: Spec) -> list[Mode]:
    out: list[Mode] = []
    for condition, entries in spec.drivetrain.modes.items():
        found = given_modes(
            "drivetrain",
            {f"{condition}.{k}": e for k, e in enumerate(entries, start=1)},
            lambda name, c=condition: (  # type: ignore[misc]
                f"{ordinal(int(name.split('.')[1]))} drive-train torsion, {CONDITIONS[c]}"
            ),
        )
        out += [
            replace(m, regimes=regimes(spec, condition), condition=CONDITIONS[condition])
            for m in found
        ]
    return out


@dataclass(frozen=True)
class PowerCurve:
    """The first grid mode of a synchronous drive train over electrical power, and the
    dominant lines it is judged against (what ``drivetrain-power.png`` draws)."""

    power_fraction: tuple[float, ...]  # of rated power [-]
    frequency_hz: tuple[float, ...]
    damping_ratio: tuple[float, ...]
    lines: tuple[tuple[str, float], ...]  # label, frequency [Hz] at each steady range's start


def power_curve(spec: Spec) -> PowerCurve | None:
    """Synchronous generator on the grid: the first grid mode at 0–95 % power.

    The magnetic stiffness falls with power (cos δ₀), so the grid modes sweep a band at a
    fixed speed (Hau Fig. 7.14, MOD-0). None for any other generator.
    """
    dt = spec.drivetrain
    if not (
        dt.chain
        and dt.generator == "synchronous"
        and dt.grid_coupling == "direct"
        and dt.generator_model
    ):
        return None
    chain = reduce(spec, None)
    fractions = np.linspace(0.0, 0.95, 20)
    curve, zetas = [], []
    for p in fractions:
        m, k, d = system(chain, spec, "grid", float(p))
        res = modal.damped(k, m, d)
        if not len(res.frequency_hz):
            raise modal.ModalError(
                f"the grid-coupled drive train has no oscillatory mode at {p:.0%} power (every "
                "mode damped past critical): check the shafts' damping_nms_rad and the inertias"
            )
        curve.append(float(res.frequency_hz[0]))
        zetas.append(float(res.damping_ratio[0]))
    lines = tuple(
        (f"{k}P at {a:g} rpm", k * a / 60.0)
        for k in sorted({1, spec.rotor.blades})
        for a, _ in spec.rotor.speed.steady_rpm
    )
    return PowerCurve(tuple(fractions.tolist()), tuple(curve), tuple(zetas), lines)


def power_check(
    power: PowerCurve,
    op: OperatingRange,
    rule: MarginRule,
    lines: Sequence[Excitation],
    heavy_damping: float = 0.3,
) -> Check:
    """``drivetrain.grid.power``: the power curve against the dominant excitations over the
    steady operating speeds."""
    fractions, curve, zetas = power.power_fraction, power.frequency_hz, power.damping_ratio
    hits = [
        (float(p), line)
        for f, z, p in zip(curve, zetas, fractions, strict=True)
        if z < heavy_damping
        for line in lines_met(f, lines, op, rule, NAME)
    ]
    span = f"{min(curve):.3g}–{max(curve):.3g} Hz"
    if hits:
        powers = [p for p, _ in hits]
        excs = ", ".join(sorted({e for _, e in hits}))
        msg = (
            f"1st grid mode spans {span} over 0–95 % power and comes within the margin "
            f"of {excs} between {100 * min(powers):.0f} and {100 * max(powers):.0f} % "
            "power: the power-dependent resonance of Hau Fig. 7.14"
        )
    elif min(zetas) >= heavy_damping:
        msg = (
            f"1st grid mode spans {span} over 0–95 % power and is heavily damped "
            f"(ζ ≥ {min(zetas):.2f}): no resonant peak (the fluid-coupling cure of Hau 7.3.3)"
        )
    else:
        msg = f"1st grid mode spans {span} over 0–95 % power, clear of the dominant lines"
    return Check(
        id="drivetrain.grid.power",
        subsystem="drivetrain",
        status="fail" if hits else "pass",
        message=msg,
        rule=Rule(
            f"synchronous c_m = p²·P_max·cos δ₀/(2πf); {rule.label}",
            "Hau ch. 7.3.2–7.3.3, Figs. 7.11, 7.14",
        ),
        numbers={
            "power_fraction": [round(float(p), 4) for p in fractions],
            "frequency_hz": [round(f, 6) for f in curve],
        },
    )


#: Condition key of a mode's condition text (Mode.condition holds the words).
_CONDITION_KEY = {text: key for key, text in CONDITIONS.items()}


def torque_refiner(spec: Spec, modes: Sequence[Mode]) -> Callable[[Check], Check] | None:
    """Adds the forced-response torque amplification to a drive-train resonance check, in
    the generator condition of the check's governing mode (None without a chain)."""
    if not spec.drivetrain.chain or rigid(spec, list(modes)):
        return None
    chain = reduce(spec, edge_frequency(spec, [m for m in modes if m.subsystem == "blade"]))
    condition_of = {
        m.id: _CONDITION_KEY[m.condition]
        for m in modes
        if m.subsystem == "drivetrain" and m.condition in _CONDITION_KEY
    }
    gear = [i for i, n in enumerate(chain.names) if "gear" in n]

    def refine(c: Check) -> Check:
        condition = condition_of.get(str(c.numbers.get("mode", "")))
        if condition is None or "excitation_hz" not in c.numbers:
            return c
        mesh = str(c.numbers.get("excitation", "")).startswith("mesh.")
        at = gear[0] if mesh and gear else 0
        amp = torque_amplification(spec, chain, condition, float(c.numbers["excitation_hz"]), at)
        return replace(
            c,
            numbers={**c.numbers, "torque_amplification": round(amp, 4)},
            message=f"{c.message}; shaft torque amplification {amp:.3g}",
        )

    return refine


def torque_amplification(
    spec: Spec, chain: Chain, condition: str, f_hz: float, at: int = 0
) -> float:
    """Largest shaft torque over an input torque of unit amplitude on mass ``at``.

    Rotor harmonics act on the rotor end (mass 0); a gear mesh acts at the gearbox.

    Notes
    -----
    Steady harmonic response (K − ω²M + iωD)·q = F with F = e_at; shaft torque
    k_j·(q_j − q_{j+1}) + iω·d_j·(q_j − q_{j+1}). Below the first mode a grid-coupled train
    passes the torque on (≈1); at a lightly damped resonance it is amplified. D holds the
    chain's dampers and the modal damping the DAF uses (:func:`modal_damping`, the drive
    train's damping ratio): at resonance the amplification is bounded by about 1/(2ζ), not
    by the dampers alone (Aeroman's undamped train gave 9·10⁵ at 5P).
    """
    m, k, d = system(chain, spec, condition)
    d = d + modal_damping(m, k, default_damping(spec).ratio)
    w = 2 * math.pi * f_hz
    force = np.zeros(m.shape[0], dtype=complex)
    force[min(at, m.shape[0] - 1)] = 1.0
    try:
        q = np.linalg.solve(k - w**2 * m + 1j * w * d, force)
    except np.linalg.LinAlgError:
        return float("inf")
    n = m.shape[0]
    twist = q[: n - 1] - q[1:n]
    torques = (chain.stiffness[: n - 1] + 1j * w * chain.damping[: n - 1]) * twist
    if condition == "locked":
        torques = np.append(torques, (chain.stiffness[-1] + 1j * w * chain.damping[-1]) * q[-1])
    return float(np.max(np.abs(torques)))


def modal_damping(m: Array, k: Array, zeta: float) -> Array:
    """The damping matrix that gives every elastic mode of (K, M) the ratio ζ:
    D = (MΦ)·diag(2ζωᵢ)·(MΦ)ᵀ with Φ mass-normalised (a rigid-body mode, ω = 0, gets none)."""
    modes = modal.solve(k, m)
    omega = 2.0 * np.pi * modes.frequency_hz
    mp = m @ modes.shapes
    return np.asarray((mp * (2 * zeta * omega)) @ mp.T)


# ---------------------------------------------------------------------------------------
# The lines that act on the drive train alone (the rotor's harmonics act on it too)


def gear_mesh(spec: Spec) -> list[Excitation]:
    """Tooth-mesh excitations of the gearbox stages: teeth × shaft rotational frequency.

    References
    ----------
    Hau ch. 7.3.4 (Aeroman: mesh frequency of the second gear stage, Fig. 7.15).
    """
    return [
        Excitation(
            f"mesh.{stage.name}",
            stage.teeth * stage.shaft_speed_ratio,
            "dominant",
            f"gear mesh {stage.name}: {stage.teeth} teeth × {stage.shaft_speed_ratio:g}·P",
            frozenset({"drivetrain"}),
        )
        for stage in spec.drivetrain.gear_stages
    ]


def shaft_imbalance(spec: Spec) -> list[Excitation]:
    """The high-speed shaft's mass imbalance: a line at the generator's speed (gear ratio ×
    1P) acting on the drive train, where the spec gives a gear ratio above 1.

    Hau ch. 7.3.4 names "mass imbalances of the rotating parts" beside the gear mesh as the
    drive train's internal excitations (the Aeroman's centrifugal switch on its high-speed
    shaft, Fig. 7.15). An imbalance's force is lateral: it twists the train only through
    the eccentric mass's gravity torque m·g·e, once a turn of the shaft — a minor line,
    which a crossing marks without failing the audit (the shaft's own bending, which the
    force drives directly, is not modelled).
    """
    ratio = spec.drivetrain.gear_ratio
    if ratio is None or ratio <= 1.0:
        return []
    return [
        Excitation(
            "1G",
            ratio,
            "minor",
            f"high-speed shaft imbalance: once a turn of the generator, {ratio:g}·P",
            frozenset({"drivetrain"}),
        )
    ]


def electrical(spec: Spec) -> list[Excitation]:
    """Generator-side excitations at fixed frequencies (Hau ch. 7.3.4: grid oscillations,
    inverters, control), acting on the drive train."""
    return [
        Excitation(
            f"electrical.{e.name}",
            0.0,
            e.energy,
            f"generator side: {e.name}",
            frozenset({"drivetrain"}),
            e.frequency_hz,
        )
        for e in spec.drivetrain.electrical_excitations
    ]


def excitations(spec: Spec) -> list[Excitation]:
    """The drive train's own lines: gear mesh, shaft imbalance, generator side."""
    return gear_mesh(spec) + shaft_imbalance(spec) + electrical(spec)


# ---------------------------------------------------------------------------------------
# The subsystem (wtvib.judge.analysis)

NAME = "drivetrain"


def default_damping(spec: Spec) -> Damping:
    return section_damping(spec.drivetrain, "drivetrain")


def build_modes(spec: Spec, built: Mapping[str, list[Mode]]) -> list[Mode]:
    """Per generator condition; the blades' edgewise frequency (built before) sets the
    blades' flexibility in the chain."""
    return modes(spec, built.get("blade", []))


def analyse(spec: Spec, ctx: Context) -> Analysis:
    """Torque amplification on each resonance check; the power curve of a synchronous
    generator on the grid (``drivetrain.grid.power``), an induction generator's coupling
    (``drivetrain.grid.induction``)."""
    curve = power_curve(spec)
    chain = _drawn_chain(spec, ctx.modes)  # the chain the modes were computed on
    found = (
        power_check(curve, ctx.op, ctx.rule, ctx.lines, ctx.settings.heavy_damping_ratio)
        if curve is not None
        else None,
        induction_check(spec, chain, ctx.modes) if chain is not None else None,
    )
    checks = tuple(c for c in found if c is not None)
    shares = inertia_shares(spec)
    return Analysis(
        checks=checks,
        refine=torque_refiner(spec, ctx.modes),
        results=DrivetrainResults(curve, chain) if curve or chain else None,
        assumptions=(shares_statement(shares, _tuned_chain(spec)),) if shares else (),
    )


def induction_check(spec: Spec, chain: Chain, modes: Sequence[Mode]) -> Check | None:
    """``drivetrain.grid.induction`` (information): a grid-coupled induction generator ties
    the train to the grid by its slip — a damper, no spring — so the train's "zeroth
    natural frequency" is its whole rotation at the generator's speed, a real root decaying
    with τ = J/d_m rather than a vibration, and its natural frequencies do not depend on
    power (d_m, the torque–slip curve's slope, is the same over its linear part), unlike a
    synchronous generator's (``drivetrain.grid.power``); ``chain``: the train the modes
    were computed on. Hau 7.3.3, "Grid-coupled induction generator"."""
    dt = spec.drivetrain
    g = dt.generator_model
    if (
        not (dt.chain and dt.generator == "induction" and dt.grid_coupling == "direct" and g)
        or g.rated_slip is None
    ):
        return None
    d_m = induction_damping(g.rated_power_kw * 1e3, g.rated_slip, g.pole_pairs, g.grid_frequency_hz)
    tau = float(chain.inertia.sum()) / (d_m * chain.generator_factor)
    grid = sorted((m for m in modes if m.id.startswith(f"{NAME}.grid.")), key=by_frequency)
    listed = ", ".join(f"{m.id} {m.frequency_hz:.3g} Hz" for m in grid) or "none computed"
    return Check(
        id="drivetrain.grid.induction",
        subsystem="drivetrain",
        status="info",
        message=(
            f"induction generator on the grid: its slip ({g.rated_slip:.1%} at rated) couples "
            f"the train to the grid as a damper (d_m {d_m:.3g} N·m·s/rad on the generator "
            f"shaft), no spring — the train's zeroth natural frequency is its whole rotation at "
            f"the generator's speed, which decays in τ = {tau:.3g} s and does not vibrate; its "
            f"natural frequencies ({listed}) hold at every power, unlike a synchronous "
            "generator's"
        ),
        rule=Rule(
            "induction d_m = T_rated/(s·Ω_s): the slope of the torque–slip curve's linear part",
            "Hau ch. 7.3.3 (grid-coupled induction generator), Fig. 7.11",
        ),
        numbers={"damping_nms_rad": d_m, "time_constant_s": tau},
    )


@dataclass(frozen=True)
class DrivetrainResults:
    """What the drive train's figures draw: a synchronous generator's grid mode over power
    (Hau Fig. 7.14) and the chain its modes were computed on (Fig. 7.10)."""

    power: PowerCurve | None
    chain: Chain | None


def _drawn_chain(spec: Spec, modes: Sequence[Mode]) -> Chain | None:
    """The chain the modes were computed on (the blades' edgewise spring from the blade's
    first edgewise mode), for its figure; None where the spec has no chain."""
    if not spec.drivetrain.chain or not spec.drivetrain.shafts:
        return None
    try:
        return reduce(spec, edge_frequency(spec, list(modes)))
    except ModelInputError:
        return None


def inertia_shares(spec: Spec) -> dict[str, float] | None:
    """The chain's inertia on the rotor shaft (J·i², i its speed over the rotor's) in Hau's
    four shares (Table 7.8): blades, hub, generator, the rest (gearbox, brake, shafts) —
    each mass by its name; None without a chain."""
    chain = spec.drivetrain.chain
    if not chain:
        return None
    out = {"blades": 0.0, "hub": 0.0, "generator": 0.0, "rest": 0.0}
    for mass in chain:
        name = mass.name.lower()
        part = next((k for k in ("blade", "hub", "generator") if k in name), "rest")
        out["blades" if part == "blade" else part] += mass.inertia_kgm2 * mass.speed_ratio**2
    total = sum(out.values())
    return {k: v / total for k, v in out.items()} if total > 0 else None


def _tuned_chain(spec: Spec) -> bool:
    """Whether the chain's inertias were set after the book's shares (provenance tuned)."""
    return any(
        q.provenance == "tuned" and p.startswith("drivetrain.chain[") and p.endswith("inertia_kgm2")
        for p, q in spec.provenance.items()
    )


def shares_statement(shares: dict[str, float], tuned: bool = False) -> str:
    """The inertia shares as the report states them, beside the book's examples (and, where
    the spec's chain was split after them — ``tuned`` — that the likeness is built in)."""
    parts = ", ".join(f"{k} {100 * v:.0f} %" for k, v in shares.items())
    return (
        f"Drive-train inertia on the rotor shaft (Hau Table 7.8): {parts} — the book's "
        "examples: Aeroman 87/2/9/2, WKA-60 91/1/7/1, Growian 85/8/5/2 (blades/hub/"
        "generator/rest); the blades dominate, the generator's share grows with the gear "
        "ratio squared."
        + (
            " This chain's inertias were split after the table (provenance tuned): its "
            "likeness to it is built in."
            if tuned
            else ""
        )
    )


SUBSYSTEM = Subsystem(
    NAME,
    build_modes,
    default_damping,
    analyse,
    part="drivetrain",
    excitations=excitations,
    diagram="campbell-drivetrain",
    title="drive train",
    figures=("drivetrain-modes", "drivetrain-power"),
)
