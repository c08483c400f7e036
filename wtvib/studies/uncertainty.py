"""Uncertainty: Monte Carlo propagation of spec tolerances to frequencies and verdicts.

Any number in the spec can carry a tolerance (a quantity with ``tolerance`` and
``distribution``). Samples are drawn reproducibly (``numpy.random.SeedSequence``, one child
per chunk, so the result does not depend on how the chunks are run: here, or on a Dask
cluster). The tower model is linear in each scaling-type input (Young's modulus, densities,
masses, inertias, spring stiffnesses), so its matrices are K = K₀ + Σ (sⱼ − 1)·Kⱼ and
M = M₀ + Σ (sⱼ − 1)·Mⱼ and all samples are solved as one stacked eigenproblem; given
frequencies are scaled directly. Inputs the fast path cannot take are named, not ignored.

References
----------
E. B. Wilson, "Probable inference, the law of succession, and statistical inference",
J. Am. Stat. Assoc. 22, 1927 (confidence interval of a probability).
"""

import copy
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import SpecError
from ..judge.excitation import Excitation, excitations, operating_range
from ..judge.resonance import acts
from ..numerics import modal
from ..results import Mode, Southwell
from ..rules import MarginRule
from ..spec import Quantity, Spec, from_data
from ..spec.messages import _split
from ..spec.ranges import valid_range
from ..subsystems import tower

Array = NDArray[np.float64]

#: Soil and pile inputs (a monopile in soil): sampled one by one, not linear in the tower.
SOIL = "tower.foundation."

#: Tower and head inputs the fast (linear) tower path accepts, by path prefix.
LINEAR_TOWER = (
    "tower.material.youngs_modulus_pa",
    "tower.material.density_kg_m3",
    "tower.material.mass_factor",
    "tower_head.mass_kg",
    "tower_head.inertia_pitch_kgm2",
    "tower_head.inertia_roll_kgm2",
    "tower.foundation.lateral_n_m",
    "tower.foundation.rocking_nm_rad",
)


def draw(q: Quantity, n: int, rng: np.random.Generator) -> Array:
    """Samples of the factor value/nominal for one uncertain quantity."""
    t = float(q.tolerance or 0.0)
    if q.distribution == "uniform":
        return rng.uniform(1 - t, 1 + t, n)
    if q.distribution == "lognormal":
        return np.exp(rng.normal(0.0, math.log(max(t, 1.0)), n))
    return rng.normal(1.0, t, n)


#: Rounds of redrawing before a distribution is declared to lie outside its field's range.
REDRAWS = 200


def draw_valid(path: str, q: Quantity, n: int, rng: np.random.Generator) -> tuple[Array, int]:
    """:func:`draw` truncated to what the spec accepts: a factor is positive (a tolerance
    scatters a value, it never flips or zeroes it) and the value stays within the field's
    schema range (a friction angle in 25–45°); draws outside are drawn again. Returns the
    factors and how many of the first ``n`` draws fell outside (reported as truncation)."""
    low, high, low_open, high_open = valid_range(path)
    value = float(q.value)

    def outside(f: Array) -> NDArray[np.bool_]:
        v = value * f
        below = (v <= low) if low_open else (v < low)
        above = (v >= high) if high_open else (v > high)
        return np.asarray((f <= 0) | below | above)

    f = draw(q, n, rng)
    bad = outside(f)
    first = int(np.count_nonzero(bad))
    for _ in range(REDRAWS):
        if not bad.any():
            return f, first
        f[bad] = draw(q, int(np.count_nonzero(bad)), rng)
        bad = outside(f)
    raise SpecError(
        f"{path}: its tolerance puts almost every sample outside the range the spec accepts "
        f"({low:g} to {high:g}, nominal {value:g}): narrow the tolerance"
    )


def uncertain(spec: Spec) -> dict[str, Quantity]:
    return {p: q for p, q in spec.provenance.items() if q.tolerance}


def _path_of_mode(path: str) -> str | None:
    """'tower.modes.fa1' or '….fa1.frequency_hz' → the mode id 'tower.fa1'."""
    parts = path.split(".")
    if len(parts) >= 3 and parts[1] == "modes" and parts[-1] in (parts[2], "frequency_hz"):
        return f"{parts[0]}.{parts[2]}"
    return None


def _with_scaled(spec: Spec, path: str, factor: float) -> Spec:
    """A copy of the spec with the number at ``path`` multiplied by ``factor``."""
    data = spec.model_dump()
    _scale(data, path, factor)
    return from_data(data)


@dataclass(frozen=True)
class Samples:
    """Sampled frequencies [Hz] per mode id, (n,) each; inputs not propagated; per input,
    how many draws fell outside its valid range and were drawn again."""

    frequencies: dict[str, Array]
    skipped: tuple[str, ...]
    truncated: dict[str, int] = field(default_factory=dict)


Nominal = Mapping[str, float]


def nominal_of(spec: Spec, modes: Sequence[Mode] | None = None) -> dict[str, float]:
    """Nominal standstill frequencies [Hz] by mode id: the audit's ``modes`` where given,
    else the frequencies the spec gives (all the sampling of given modes needs)."""
    if modes is not None:
        return {m.id: m.frequency_hz for m in modes}
    out = {}
    for path, q in spec.provenance.items():
        mode = _path_of_mode(path)
        if mode is not None:
            out[mode] = float(q.value)
    return out


def sample(
    spec: Spec, n: int, seed: int = 0, chunk: int = 2000, nominal: Nominal | None = None
) -> Samples:
    """Monte Carlo samples of the uncertain modes (chunked, reproducible); ``nominal``: the
    audit's frequencies (:func:`nominal_of`)."""
    return combine([sample_chunk(*args) for args in _chunks(spec, n, seed, chunk, nominal)])


def _chunks(
    spec: Spec, n: int, seed: int, chunk: int, nominal: Nominal | None
) -> list[tuple[Spec, int, np.random.SeedSequence, Nominal, "TowerRitz | None"]]:
    """The arguments of each :func:`sample_chunk` call — the same locally and on a
    cluster, so that both draw the same samples: one seed sequence per chunk of ``chunk``
    samples, the nominal frequencies and the reduced tower built once for all."""
    base = nominal if nominal is not None else nominal_of(spec)
    seqs = np.random.SeedSequence(seed).spawn(max(1, math.ceil(n / chunk)))
    ritz = tower_ritz(spec)
    return [(spec, min(chunk, n - i * chunk), s, base, ritz) for i, s in enumerate(seqs)]


def combine(parts: Sequence[Samples]) -> Samples:
    keys = parts[0].frequencies.keys()
    truncated: dict[str, int] = {}
    for p in parts:
        for k, v in p.truncated.items():
            truncated[k] = truncated.get(k, 0) + v
    return Samples(
        {k: np.concatenate([p.frequencies[k] for p in parts]) for k in keys},
        parts[0].skipped,
        truncated,
    )


def sample_chunk(
    spec: Spec,
    n: int,
    seq: np.random.SeedSequence,
    nominal: Nominal | None = None,
    ritz: "TowerRitz | None" = None,
) -> Samples:
    """One chunk of samples: the unit of work for local or distributed runs (``ritz``: the
    spec's :func:`tower_ritz`, built once for all chunks; built here if not given)."""
    rng = np.random.default_rng(seq)
    inputs = uncertain(spec)
    drawn = {p: draw_valid(p, q, n, rng) for p, q in sorted(inputs.items())}
    factors = {p: f for p, (f, _) in drawn.items()}
    truncated = {p: k for p, (_, k) in drawn.items() if k}
    out: dict[str, Array] = {}
    skipped = []
    nominal = nominal if nominal is not None else nominal_of(spec)
    tower_paths = [p for p in factors if p.startswith(LINEAR_TOWER)]
    soil_paths = [p for p in factors if p.startswith(SOIL)]
    sampled: list[str] = []  # the tower inputs its samples were solved with
    if soil_paths and _sampled_tower(spec):  # not linear: every sample solved anew
        sampled = tower_paths + soil_paths
        out.update(_tower_samples_direct(spec, {p: factors[p] for p in sampled}))
    elif tower_paths and _sampled_tower(spec):
        ritz = ritz if ritz is not None else tower_ritz(spec)
        assert ritz is not None and ritz.paths == tuple(tower_paths)
        out.update(ritz.frequencies(np.stack([factors[p] for p in ritz.paths], axis=1)))
        sampled = tower_paths
    for p, f in factors.items():
        mode = _path_of_mode(p)
        if mode is not None and mode in nominal and mode not in out:
            out[mode] = nominal[mode] * f
        elif mode is None and p not in sampled:
            skipped.append(p)
    return Samples(out, tuple(skipped), truncated)


def _tower_samples_direct(spec: Spec, factors: dict[str, Array]) -> dict[str, Array]:
    """fa1 and ss1 for every sample, each solved with its own inputs (soil parameters enter
    the mudline stiffness non-linearly)."""
    n = len(next(iter(factors.values())))
    data = spec.model_dump()
    out: dict[str, list[float]] = {"tower.fa1": [], "tower.ss1": []}
    for i in range(n):
        d = copy.deepcopy(data)
        for path, f in factors.items():
            _scale(d, path, float(f[i]))
        try:
            s = from_data(d)
        except SpecError as e:
            raise SpecError(
                f"--uncertainty: sample {i + 1} of the tolerances is not a valid spec ({e}): "
                "narrow the tolerances"
            ) from None
        b = tower.discretise(s.tower)
        for name, direction in (("tower.fa1", "fa"), ("tower.ss1", "ss")):
            stiff, mass = tower.bending_system(
                b,
                s.tower_head,
                s.tower.point_masses,
                s.tower.foundation,
                direction,  # type: ignore[arg-type]
                s.tower.gravity,
            )
            f = modal.frequencies_stacked(stiff[None], mass[None], 1, unstable_as_nan=True)
            out[name].append(float(f[0, 0]))
    return {k: np.asarray(v) for k, v in out.items()}


def _sampled_tower(spec: Spec) -> bool:
    """Whether the tower's fa1 and ss1 are sampled from its structure: a tower with
    structure on a fixed base (on a floating platform the platform's modes come first, and
    its inputs are left unpropagated, listed as such)."""
    return spec.tower.has_structure and spec.tower.foundation.kind != "platform"


def _scale(data: Any, path: str, factor: float) -> None:
    """Multiply the number at a dotted path (``tower.foundation.soil[0].modulus_pa``)."""
    *parents, last = _split(path)
    node = data
    for k in parents:
        node = node[k]
    node[last] = node[last] * factor


#: nominal modes in the Ritz basis of the tower samples (with one mode per uncertain input)
RITZ_TOWER = 3


def _ritz_basis(k0: Array, m0: Array, perturbed: list[tuple[Array, Array]]) -> Array:
    """An orthonormal basis of the nominal's lowest modes and the perturbed systems' first
    (columns that add nothing dropped)."""
    vectors = [modal.solve(k0, m0, RITZ_TOWER).shapes]
    vectors += [modal.solve(k, m, 1).shapes for k, m in perturbed]
    u, sv, _ = np.linalg.svd(np.concatenate(vectors, axis=1), full_matrices=False)
    return np.asarray(u[:, sv > 1e-10 * sv[0]])


@dataclass(frozen=True)
class TowerRitz:
    """The tower's fa1 and ss1 problems reduced for sampling: K and M are linear in the
    linear tower inputs, so a sample's problem is the nominal one plus each input's change
    (the input doubled) times its factor − 1, all projected on a Rayleigh–Ritz basis of the
    nominal's lowest modes and each doubled input's first (r ≤ 3 + inputs instead of the
    mesh's degrees of freedom; within 1e-9 of the full problem over ±50 %, tests). Built
    once per run (:func:`tower_ritz`); every chunk of samples only sums r × r matrices."""

    paths: tuple[str, ...]  # the uncertain inputs, in the order of the factors' columns
    #: per mode (tower.fa1, tower.ss1): nominal K, M (r, r) and their changes (inputs, r, r)
    reduced: dict[str, tuple[Array, Array, Array, Array]]

    def frequencies(self, factors: Array) -> dict[str, Array]:
        """fa1 and ss1 [Hz] of each sample; ``factors`` (samples, inputs), NaN where a
        sample buckles."""
        s = np.asarray(factors, dtype=float) - 1.0
        out = {}
        for name, (k0, m0, dk, dm) in self.reduced.items():
            k = k0 + np.einsum("nj,jab->nab", s, dk)
            m = m0 + np.einsum("nj,jab->nab", s, dm)
            out[name] = modal.frequencies_stacked(k, m, 1, unstable_as_nan=True)[:, 0]
        return out


def tower_ritz(spec: Spec) -> TowerRitz | None:
    """The spec's reduced tower problems for sampling, or None where no linear tower input
    is uncertain (or soil is: the mudline stiffness is not linear in it)."""
    inputs = sorted(uncertain(spec))
    paths = tuple(p for p in inputs if p.startswith(LINEAR_TOWER))
    soil = any(p.startswith(SOIL) for p in inputs)
    if not paths or soil or not _sampled_tower(spec):
        return None

    def systems(s: Spec) -> list[tuple[Array, Array]]:
        b = tower.discretise(s.tower)
        return [
            tower.bending_system(
                b, s.tower_head, s.tower.point_masses, s.tower.foundation, d, s.tower.gravity
            )
            for d in ("fa", "ss")
        ]

    base = systems(spec)
    deltas = {p: systems(_with_scaled(spec, p, 2.0)) for p in paths}
    reduced = {}
    for i, name in enumerate(("tower.fa1", "tower.ss1")):
        k0, m0 = base[i]
        dk = np.stack([deltas[p][i][0] - k0 for p in paths])
        dm = np.stack([deltas[p][i][1] - m0 for p in paths])
        q = _ritz_basis(k0, m0, [deltas[p][i] for p in paths])
        reduced[name] = (
            q.T @ k0 @ q,
            q.T @ m0 @ q,
            np.einsum("ai,jab,bk->jik", q, dk, q),
            np.einsum("ai,jab,bk->jik", q, dm, q),
        )
    return TowerRitz(paths, reduced)


def wilson(hits: int, n: int, z: float = 1.96) -> tuple[float, float]:
    """95 % Wilson score interval of a probability estimated as hits/n."""
    if n == 0:
        return 0.0, 1.0
    p = hits / n
    den = 1 + z**2 / n
    centre = (p + z**2 / (2 * n)) / den
    half = z * math.sqrt(p * (1 - p) / n + z**2 / (4 * n * n)) / den
    return max(0.0, centre - half), min(1.0, centre + half)


#: Rotor speeds per steady range at which each sample is judged.
SPEEDS_PER_RANGE = 41

#: Samples judged at once by :func:`summary` (blocks of 4,096 × 41 speeds: arrays that stay
#: in the processor's cache, where the whole 10⁵ × 41 made every step a trip to memory).
SUMMARY_BLOCK = 4096


def sampled_curves(mode: Mode, factors: Array, omega: Array) -> Array:
    """Frequencies [Hz] of each sample (rows) at rotor speeds ``omega`` [rad/s] (columns).

    ``factors`` are the sampled standstill frequencies over the nominal one. A Southwell
    curve keeps its rotational term, f² = (s·f₀)² + K·(Ω/2π)² (the tolerance is on the
    standstill value the spec gives); any other curve is scaled by s.
    """
    if isinstance(mode.curve, Southwell):
        rev = omega[None, :] / (2 * math.pi)
        f0 = mode.curve.f0_hz * factors[:, None]
        return np.sqrt(f0**2 + mode.curve.k * rev**2)
    return factors[:, None] * mode.frequency_at(omega)[None, :]


def summary(
    spec: Spec,
    samples: Samples,
    modes: Sequence[Mode] | None = None,
    rule: MarginRule | None = None,
    lines: Sequence[Excitation] | None = None,
) -> dict[str, Any]:
    """Percentiles per mode and, per rotor line that is not minor, the probability that the
    sampled mode violates the margin somewhere in steady operation (with its 95 % interval).

    Judged as the deterministic checks of the run are: the run's ``rule`` and margin
    (``--margin``, ``--preset``), the predicate ``rule.violates`` of the one resonance
    routine, every steady speed (quick-pass bands included) — not only the dwell speed —
    and only where the mode exists; speed-dependent modes along their curves
    (:func:`sampled_curves`).
    """
    rule = rule or spec.audit.margin_rule()
    op = operating_range(spec.rotor.speed)
    judged = excitations(spec) if lines is None else lines  # the audit's: every subsystem's
    lines = [e for e in judged if e.energy != "minor"]
    by_id = {m.id: m for m in modes or ()}
    omega = np.concatenate([np.linspace(a, b, SPEEDS_PER_RANGE) for a, b in op.steady])
    out: dict[str, dict[str, Any]] = {}
    for mode_id, f in sorted(samples.frequencies.items()):
        mode = by_id.get(mode_id)
        stable = np.isfinite(f)
        if not stable.any():
            out[mode_id] = {"unstable": _share(len(f), len(f))}
            continue
        p5, p50, p95 = np.percentile(f[stable], [5, 50, 95])
        probs = {}
        exists = (
            mode is not None and mode.judged and (mode.regimes is None or "steady" in mode.regimes)
        )
        if exists:
            assert mode is not None
            line_hz = {e.id: e.frequency_hz(omega)[None, :] for e in lines if acts(e, mode)}
            hits = dict.fromkeys(line_hz, 0)
            factors = f[stable] / mode.frequency_hz
            # in blocks of samples: each block's (samples × speeds) arrays stay in cache
            for start in range(0, len(factors), SUMMARY_BLOCK):
                curves = sampled_curves(mode, factors[start : start + SUMMARY_BLOCK], omega)
                for key, f_e in line_hz.items():
                    sep = rule.separation(f_e, curves)
                    hits[key] += int(np.count_nonzero(rule.violates(sep).any(axis=1)))
            probs = {key: _share(n, len(f)) for key, n in hits.items()}
        out[mode_id] = {
            "mean_hz": round(float(np.mean(f[stable])), 6),
            "std_hz": round(float(np.std(f[stable])), 6),
            "p5_hz": round(float(p5), 6),
            "p50_hz": round(float(p50), 6),
            "p95_hz": round(float(p95), 6),
            "in_margin_band": probs,
            **({"unstable": _share(int(np.sum(~stable)), len(f))} if not stable.all() else {}),
        }
    return {
        "samples": len(next(iter(samples.frequencies.values()), [])),
        "rule": rule.label,
        "judged_over": "every steady speed where the mode exists, along its curve",
        "modes": out,
        "not_propagated": list(samples.skipped),
        "truncated": {
            p: {"redrawn": k, "range": _range_text(p)} for p, k in sorted(samples.truncated.items())
        },
    }


def _share(hits: int, n: int) -> dict[str, Any]:
    """A probability from ``hits`` of ``n`` samples, with its Wilson 95 % interval."""
    lo, hi = wilson(hits, n)
    return {"probability": round(hits / n, 6), "ci95": [round(lo, 6), round(hi, 6)]}


def warnings_of(summary: Mapping[str, Any]) -> list[str]:
    """What the sampling changed or found that a reader must not miss."""
    out = []
    n = summary["samples"]
    for path, t in summary.get("truncated", {}).items():
        out.append(
            f"--uncertainty: {t['redrawn']} of {n} draws of {path} fell outside what the spec "
            f"accepts ({t['range']}) and were drawn again: its distribution is truncated there"
        )
    for mode_id, m in summary["modes"].items():
        if "unstable" in m:
            p = m["unstable"]
            out.append(
                f"--uncertainty: {mode_id} buckles (a negative stiffness: the weight on top "
                f"exceeds what the sampled structure carries) in {p['probability']:.2%} of "
                f"the samples [{p['ci95'][0]:.2%}–{p['ci95'][1]:.2%}]; its statistics are "
                "over the others"
            )
    if summary.get("not_propagated"):
        out.append(
            "--uncertainty: not propagated (no model of them is sampled): "
            + ", ".join(summary["not_propagated"])
        )
    return out


def _range_text(path: str) -> str:
    low, high, low_open, high_open = valid_range(path)
    parts = [f"{'>' if low_open else '≥'} {low:g}"] if math.isfinite(low) else []
    parts += [f"{'<' if high_open else '≤'} {high:g}"] if math.isfinite(high) else []
    if not low >= 0:
        parts.append("its sign kept")
    return ", ".join(parts)


NO_TOLERANCE = (
    "--uncertainty: no value in the spec carries a tolerance, so there is nothing to sample; "
    "give one as e.g. youngs_modulus_pa: {value: 2.1e11, tolerance: 0.05, distribution: "
    "normal} (README, 'Design-stage answers')"
)


def sensitivities(
    spec: Spec, nominal: Nominal | None = None, step: float = 0.01
) -> dict[str, dict[str, float]]:
    """One-at-a-time normalised sensitivities (∂f/∂p)·(p/f) of the uncertain modes, by
    central differences on the same fast paths the sampling takes (a given frequency: 1;
    a tower input: the linearly decomposed tower matrices) — no audit is rerun."""
    base = nominal if nominal is not None else nominal_of(spec)
    out: dict[str, dict[str, float]] = {}
    ritz = tower_ritz(spec)
    for p in sorted(uncertain(spec)):
        mode = _path_of_mode(p)
        if mode is not None:
            out[p] = {mode: 1.0}
            continue
        if not (p.startswith((*LINEAR_TOWER, SOIL)) and spec.tower.has_structure):
            continue  # not propagated (listed in not_propagated)
        if ritz is not None and p in ritz.paths:  # this input ± step, the others nominal
            factors = np.ones((2, len(ritz.paths)))
            factors[:, ritz.paths.index(p)] = (1 + step, 1 - step)
            found = ritz.frequencies(factors)
        else:  # soil (or a tower input beside soil): each solved anew
            found = _tower_samples_direct(spec, {p: np.array([1 + step, 1 - step])})
        out[p] = {
            k: round(float(f[0] - f[1]) / (2 * step * base[k]), 4)
            for k, f in found.items()
            if base.get(k, 0.0) > 0 and abs(f[0] - f[1]) > 1e-12 * base[k]
        }
    return out


def sample_distributed(
    spec: Spec,
    n: int,
    seed: int,
    client: Any,
    chunk: int = 2000,
    nominal: Nominal | None = None,
) -> Samples:
    """:func:`sample` on a Dask cluster (``client``: a ``distributed.Client``): the same
    chunks and seeds, so the same samples as a local run (optional extra ``distributed``)."""
    calls = _chunks(spec, n, seed, chunk, nominal)
    from .cluster import gather

    futures = client.map(sample_chunk, *zip(*calls, strict=True), pure=False)
    return combine(gather(client, futures))
