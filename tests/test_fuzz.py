"""Property-based fuzzing of the spec loader and the audit.

Generated valid specs always audit with finite, non-negative frequencies; mutated specs
(deleted keys, wrong types, extreme numbers) and random bytes always end in a wtvib error
(one line, exit 2) or a valid audit — never another exception. CI runs a short campaign;
``make fuzz`` runs ≥ 100,000 cases (HYPOTHESIS_PROFILE=fuzz) and tests/FUZZ.md records it.
"""

import json
import math

import yaml
from hypothesis import given
from hypothesis import strategies as st

from wtvib import audit, spec
from wtvib.errors import WtvibError

positive = st.floats(min_value=1e-3, max_value=1e3, allow_nan=False)


@st.composite
def valid_specs(draw):  # type: ignore[no-untyped-def]
    blades = draw(st.integers(1, 4))
    if draw(st.booleans()):
        speed = {"fixed_rpm": draw(st.floats(1, 80))}
    else:
        lo = draw(st.floats(1, 40))
        speed = {"min_rpm": lo, "max_rpm": lo * draw(st.floats(1, 3))}
    data = {
        "wtvib": 1,
        "turbine": {"name": draw(st.text(min_size=1, max_size=20).filter(str.strip))},
        "rotor": {
            "blades": blades,
            "orientation": draw(st.sampled_from(["upwind", "downwind", "vertical-axis"])),
            "hub": "rigid",
            "speed": speed,
        },
        "tower": {"modes": {"fa1": draw(st.floats(0.01, 30)), "ss1": draw(st.floats(0.01, 30))}},
        "blade": {
            "modes": {"flap1": draw(st.floats(0.05, 20)), "edge1": draw(st.floats(0.05, 20))}
        },
    }
    if draw(st.booleans()):
        height = draw(st.floats(10, 200))
        data["tower"]["distributed"] = {
            "height_m": [0.0, height / 2, height],
            "mass_per_length_kg_m": [draw(st.floats(50, 2e4))] * 3,
            "ei_fa_nm2": [draw(st.floats(1e8, 1e13))] * 3,
            "ei_ss_nm2": [draw(st.floats(1e8, 1e13))] * 3,
        }
        data["tower"]["gravity"] = False
        data["tower_head"] = {
            "mass_kg": draw(st.floats(10, 2e6)),
            "cm_above_top_m": draw(st.floats(-3, 5)),
        }
    if (
        "tower_head" in data
        and data["rotor"]["orientation"] != "vertical-axis"
        and draw(st.booleans())
    ):  # the coupled whole-turbine model: flexible blades on the tower head
        length, m_root = draw(st.floats(5, 120)), draw(st.floats(20, 2000))
        ei, hub_r = draw(st.floats(1e6, 1e11)), draw(st.floats(0, 5))
        data["blade"]["structure"] = {
            "hub_radius_m": hub_r,
            "span_m": [0.0, length],
            "mass_per_length_kg_m": [m_root, m_root * draw(st.floats(0.05, 1))],
            "ei_flap_nm2": [ei, ei * draw(st.floats(0.01, 1))],
            "ei_edge_nm2": [2 * ei, ei * draw(st.floats(0.01, 2))],
        }
        rotor = blades * m_root * length
        hub = rotor * draw(st.floats(0, 0.5))
        j = rotor * (hub_r + length) ** 2
        data["tower_head"].update(
            mass_kg=(rotor + hub) * draw(st.floats(1.05, 10)),
            inertia_roll_kgm2=j * draw(st.floats(1, 5)),
            inertia_pitch_kgm2=j * draw(st.floats(0.5, 5)),
            inertia_yaw_kgm2=j * draw(st.floats(0.5, 5)),
        )
        data["coupled"] = {
            "apex_downwind_m": draw(st.floats(-10, 10)),
            "apex_above_top_m": draw(st.floats(-3, 6)),
            "hub_mass_kg": hub,
            "blade_modes": draw(st.integers(1, 4)),
        }
    if draw(st.booleans()):
        data["drivetrain"] = {
            "chain": [
                {"name": "blades", "inertia_kgm2": draw(st.floats(1e2, 1e8))},
                {
                    "name": "generator",
                    "inertia_kgm2": draw(st.floats(1, 1e4)),
                    "speed_ratio": draw(st.floats(1, 150)),
                },
            ],
            "shafts": [{"stiffness_nm_rad": draw(st.floats(1e4, 1e11))}],
        }
    if draw(st.booleans()):  # blade divergence, flutter and stall checks
        data["turbine"]["rotor_diameter_m"] = draw(st.floats(2, 300))
        data["blade"]["modes"]["tor1"] = draw(st.floats(0.2, 60))
        data["blade"]["mass_kg"] = draw(st.floats(10, 1e5))
        ea = draw(st.floats(0.0, 0.6))
        data["blade"]["aeroelastic"] = {
            "max_wind_m_s": draw(st.floats(5, 60)),
            "sections": [
                {
                    "radius_fraction": draw(st.floats(0.05, 1.0)),
                    "chord_m": draw(st.floats(0.05, 10)),
                    "elastic_axis_chord": ea,
                    "centre_of_mass_chord": draw(st.floats(0.0, 0.9)),
                    "mass_per_length_kg_m": draw(st.floats(0.5, 2e3)),
                    "torsional_inertia_kgm": draw(st.floats(1e-3, 1e3)),
                    "chord_angle_deg": draw(st.floats(-30, 30)),
                }
            ],
            "planform": {
                "radius_fraction": [0.1, 0.6, 1.0],
                "chord_m": [draw(st.floats(0.05, 10)) for _ in range(3)],
                "twist_deg": [draw(st.floats(-10, 30)) for _ in range(3)],
            },
        }
    return data


@given(valid_specs())
def test_valid_specs_audit_with_finite_frequencies(data):
    try:
        report = audit.run(spec.from_data(data))
    except WtvibError:
        return  # e.g. a model that buckles: a clear, typed error is acceptable
    for m in report.modes:
        assert math.isfinite(m.frequency_hz) and m.frequency_hz >= 0
    assert report.verdict in ("pass", "warn", "fail")
    json.dumps(report.to_dict(), allow_nan=False)  # the JSON contract: no NaN or infinity


junk = st.one_of(
    st.none(),
    st.booleans(),
    st.text(max_size=8),
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(-(10**12), 10**12),
    st.lists(st.integers(), max_size=3),
    st.dictionaries(st.text(max_size=3), st.integers(), max_size=2),
)


@st.composite
def mutated_specs(draw):  # type: ignore[no-untyped-def]
    data = draw(valid_specs())
    for _ in range(draw(st.integers(1, 3))):
        node, path = data, []
        while isinstance(node, dict) and node and draw(st.booleans()):
            key = draw(st.sampled_from(sorted(node, key=str)))
            path.append(key)
            parent, node = node, node[key]
        if not path:
            continue
        if draw(st.booleans()):
            del parent[path[-1]]
        else:
            parent[path[-1]] = draw(junk)
    return data


@given(mutated_specs())
def test_mutated_specs_fail_cleanly(data):
    try:
        text = yaml.safe_dump(data)
    except yaml.YAMLError:
        return
    try:
        loaded = spec.from_document(__import__("wtvib.spec.yamlio", fromlist=["parse"]).parse(text))
    except WtvibError:
        return
    try:
        report = audit.run(loaded)
    except WtvibError:
        return
    assert all(math.isfinite(m.frequency_hz) and m.frequency_hz >= 0 for m in report.modes)


@given(st.binary(max_size=400))
def test_random_bytes_are_a_spec_error(tmp_path_factory, raw):
    path = tmp_path_factory.mktemp("bytes") / "x.yaml"
    path.write_bytes(raw)
    try:
        spec.load(path)
    except WtvibError:
        return
    raise AssertionError("random bytes loaded as a valid spec")  # pragma: no cover


def test_regression_absurd_head_offset_is_refused_cleanly():
    # found by the fuzz campaign of 2026-11-23: a 1.3e154 m head offset overflowed z² in the
    # tower model; now refused by the spec (|offset| ≤ 1000 m), and any overflow in a model
    # is a clean ModalError rather than a traceback
    text = """\
wtvib: 1
turbine: {name: '0'}
rotor: {blades: 1, orientation: upwind, hub: rigid, speed: {min_rpm: 1.0, max_rpm: 1.0}}
tower:
  modes: {fa1: 1.0}
  distributed: {height_m: [0, 5, 10], mass_per_length_kg_m: [50, 50, 50],
                ei_fa_nm2: [1.0e8, 1.0e8, 1.0e8], ei_ss_nm2: [1.0e8, 1.0e8, 1.0e8]}
tower_head: {mass_kg: 10.0, cm_above_top_m: 1.3407807929942597e+154}
"""
    from wtvib.spec.yamlio import parse

    try:
        spec.from_document(parse(text))
    except WtvibError as exc:
        assert "cm_above_top_m" in str(exc)
    else:
        raise AssertionError("the absurd offset was accepted")


def test_regression_rotor_radius_at_the_hub_is_refused_with_the_field():
    # found by the fuzz campaign of 2026-11-23 (campaign 5, coupled specs): a 2 m rotor on a
    # blade whose root sits 1 m from the axis left the stall check no blade to integrate over
    # (ZeroDivisionError); now refused by the spec with the field and line
    text = """\
wtvib: 1
turbine: {name: '0', rotor_diameter_m: 2.0}
rotor: {blades: 1, orientation: upwind, hub: rigid, speed: {fixed_rpm: 1.0}}
blade:
  structure: {hub_radius_m: 1.0, span_m: [0, 5], mass_per_length_kg_m: [20, 20],
              ei_flap_nm2: [1.0e6, 1.0e6], ei_edge_nm2: [2.0e6, 1.0e6]}
"""
    from wtvib.spec.yamlio import parse

    try:
        spec.from_document(parse(text))
    except WtvibError as exc:
        assert str(exc).startswith("line 2: turbine.rotor_diameter_m:")
    else:
        raise AssertionError("a rotor radius at the blade root was accepted")
