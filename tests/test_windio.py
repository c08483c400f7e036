"""windIO at unit level: 6×6 section matrices, floating turbines, speeds from control."""

import math
from pathlib import Path

import numpy as np
import pytest

from wtvib.errors import SpecError
from wtvib.importers import windio


def test_symmetric_fills_both_triangles():
    upper = np.arange(1.0, 22.0)[None, :]  # K11, K12, …, K66
    full = windio._symmetric(upper)[0]
    assert full[0, 1] == full[1, 0] == 2.0 and full[5, 5] == 21.0
    assert np.allclose(full, full.T)


def test_condensation_removes_the_offset_term_of_the_diagonal():
    """A section with EA at an offset e from the reference axis: K55 = EI + EA·e² on the
    diagonal, coupled by K35 = EA·e; condensed with the extension free it is EI again."""
    ea, ei, e = 1.0e9, 2.0e8, 0.3
    k = np.diag([1e9, 1e9, ea, 5e8, ei + ea * e * e, 1e8])
    k[2, 4] = k[4, 2] = ea * e
    _, k55, k66, _ = windio._condensed(k[None])
    assert k55[0] == pytest.approx(ei) and k66[0] == pytest.approx(1e8)


@pytest.mark.parametrize("theta", [-30.0, -12.0, 0.0, 7.5, 40.0])
def test_condensation_finds_the_principal_axes_of_a_turned_section(theta):
    """A section whose principal bending axes are turned by θ from the matrix's axes (axis 1
    towards axis 2): its 2×2 bending block R·diag(EI₁, EI₂)·Rᵀ has K45 = (EI₁ − EI₂)·sin θ
    cos θ; the condensation gives EI₁, EI₂ and θ back — the cross term once dropped, the
    diagonal (EI₁ cos²θ + EI₂ sin²θ) taken for the principal stiffness."""
    ei_1, ei_2 = 4.0e10, 1.5e10
    t = np.radians(theta)
    r = np.array([[np.cos(t), -np.sin(t)], [np.sin(t), np.cos(t)]])
    k = np.diag([1e9, 1e9, 5e9, 1.0, 1.0, 2e9])
    k[3:5, 3:5] = r @ np.diag([ei_1, ei_2]) @ r.T
    k44, k55, k66, turned = windio._condensed(k[None])
    assert (k44[0], k55[0]) == pytest.approx((ei_1, ei_2), rel=1e-12)
    assert turned[0] == pytest.approx(theta, abs=1e-9)
    assert k66[0] == pytest.approx(2e9)
    # the same section with its axes named the other way round: the same turn
    swapped = k[:, [0, 1, 2, 4, 3, 5]][[0, 1, 2, 4, 3, 5], :]
    k44, k55, _, turned = windio._condensed(swapped[None])
    assert (k44[0], k55[0]) == pytest.approx((ei_2, ei_1), rel=1e-12)
    assert turned[0] == pytest.approx(-theta, abs=1e-9)


def test_a_floating_platform_without_its_parts_is_one_line_naming_them(tmp_path):
    """A floating_platform is read (wtvib.importers.windio_platform); one without joints is
    one line naming the missing field, and moorings with no platform are refused."""
    from wtvib.importers.windio_platform import platform

    doc = windio._paths({"components": {"floating_platform": {}}}, (), "f.yaml")
    with pytest.raises(SpecError, match=r"components\.floating_platform\.joints is missing"):
        platform(doc, tmp_path / "f.yaml", 1e6, 15.0)
    text = "components:\n  mooring: {}\n  tower: {}\nassembly: {number_of_blades: 3}\n"
    with pytest.raises(SpecError, match=r"moorings but no components\.floating_platform") as err:
        windio.to_spec_data(tmp_path / "f.yaml", text)
    assert err.value.path == "components.mooring"


def iea15() -> dict:  # type: ignore[type-arg]
    windio_pkg = pytest.importorskip("windIO", reason="the windio package (dev extra) is needed")
    from pathlib import Path

    from wtvib.spec.yamlio import parse_plain

    path = Path(windio_pkg.__file__).parent / "examples" / "turbine" / "IEA-15-240-RWT.yaml"
    return parse_plain(path.read_text()).data  # type: ignore[no-any-return]


def load_mutated(tmp_path, doc):  # type: ignore[no-untyped-def]
    import yaml

    from wtvib import audit, importers

    p = tmp_path / "m.yaml"
    p.write_text(yaml.safe_dump(doc, sort_keys=False))
    return audit.run(importers.load(p))


@pytest.mark.parametrize(
    ("mutate", "message"),
    [
        (
            lambda d: d["components"]["tower"]["structure"]["layers"][0].pop("thickness"),
            r"components\.tower\.structure\.layers\.0\.thickness is missing",
        ),
        (
            lambda d: d["components"]["blade"]["outer_shape"]["twist"].pop("grid"),
            r"components\.blade\.outer_shape\.twist\.grid is missing",
        ),
        (
            lambda d: d["assembly"].update(number_of_blades=True),
            "number_of_blades must be a whole number",
        ),
        (
            lambda d: d["components"]["tower"].update(outer_shape=-1.0),
            "does not have the shape wtvib reads",
        ),
    ],
)
@pytest.mark.parametrize("schema", [False, True], ids=["own checks", "windIO schema"])
def test_a_hostile_windio_file_is_one_line(tmp_path, mutate, message, schema, monkeypatch):
    """Two thirds of ~750 single-key mutations of the IEA-15 2.x example ended in a
    KeyError, TypeError or IndexError; blades: true was one blade. wtvib's own checks name
    the field where the windIO schema is not at hand; with it (the windio package), the
    schema refuses a value it objects to first, with field and line — and a key it
    requires that the file leaves out is named by wtvib's own check where the audit reads
    it (said, not refused, where it does not: WISDEM's examples leave out hub.cd)."""
    from wtvib.importers import windio_schema

    if not schema:
        monkeypatch.setattr(windio_schema, "available", lambda: False)
    elif not windio_schema.available():
        pytest.skip("the windio package (its schema) is not installed")
    doc = iea15()
    mutate(doc)
    missing = "is missing" in message
    expected = "windIO 2.x schema refuses" if schema and not missing else message
    with pytest.raises(SpecError, match=expected):
        load_mutated(tmp_path, doc)


@pytest.mark.parametrize(
    ("mutate", "message"),
    [
        (  # The drive train's spring is read now
            lambda d: d["components"]["drivetrain"]["elastic_properties"].update(
                spring_constant="stiff"
            ),
            r"drivetrain\.elastic_properties\.spring_constant must be a number",
        ),
        (
            lambda d: d["components"]["drivetrain"]["generator"]["elastic_properties"].update(
                inertia=[-1.0, 1.0, 1.0]
            ),
            r"generator\.elastic_properties\.inertia\[0\] must be positive",
        ),
    ],
)
def test_a_hostile_drive_train_is_one_line(tmp_path, mutate, message):
    """The drive train's spring and the generator's inertia are read now (the
    windIO schema lets a string or a negative inertia through): one line naming the field."""
    doc = iea15()
    mutate(doc)
    with pytest.raises(SpecError, match=message):
        load_mutated(tmp_path, doc)


def test_a_negative_component_mass_is_refused(tmp_path, monkeypatch):
    from wtvib.importers import windio_schema

    monkeypatch.setattr(windio_schema, "available", lambda: False)  # wtvib's own check
    doc = iea15()
    comps = doc["components"]
    part = next(
        (
            comps[k]
            for k in ("nacelle", "drivetrain", "hub")
            if "elastic_properties" in comps.get(k, {})
        ),
        None,
    )
    if part is None:
        pytest.skip("the example has no component mass")
    part["elastic_properties"]["mass"] = -1.0
    with pytest.raises(SpecError, match=r"elastic_properties\.mass must be a mass ≥ 0 kg"):
        load_mutated(tmp_path, doc)


def test_a_part_given_two_different_masses_is_warned_about():
    """The windIO 2.1.1 IEA-22 example gives its generator as 508 t (`mass`) and
    1,269 t (`elastic_properties.mass`); the audit says so with both numbers, in the
    headline's warnings. The IEA-15 example's two generator masses agree (372 / 369 t)."""
    from pathlib import Path

    import windIO

    from wtvib.importers import load

    examples = Path(windIO.__file__).parent / "examples/turbine"
    iea22 = load(examples / "IEA-22-280-RWT.yaml")
    said = [w for w in iea22.warnings if "components.drivetrain.generator" in w]
    assert said and "508,040 kg" in said[0] and "1,269,142 kg" in said[0]
    assert not [w for w in load(examples / "IEA-15-240-RWT.yaml").warnings if "two masses" in w]


@pytest.mark.parametrize(
    ("edit", "where", "message"),
    [
        (
            lambda d: d["assembly"].update(number_of_blades=True),
            "assembly.number_of_blades",
            "not of type 'integer'",
        ),
        (
            lambda d: d["components"]["drivetrain"]["generator"].update(mass=-1.0),
            "components.drivetrain.generator.mass",
            "less than the minimum of 0",
        ),
    ],
)
def test_a_windio_file_is_checked_against_the_windio_schema_first(tmp_path, edit, where, message):
    """`number_of_blades: true` was one blade and a −1 kg generator was taken
    silently; the windIO 2.x schema (the windio package's, checked without importing windIO)
    refuses both, one line with file, line and field, exit 2."""
    windio = pytest.importorskip("windIO", reason="the windio package (dev extra) is needed")
    from pathlib import Path

    import yaml
    from typer.testing import CliRunner

    from wtvib.cli import app

    src = Path(windio.__file__).parent / "examples" / "turbine" / "IEA-15-240-RWT.yaml"
    d = yaml.load(src.read_text(), Loader=yaml.CSafeLoader)
    edit(d)
    bad = tmp_path / "bad.yaml"
    bad.write_text(yaml.safe_dump(d, sort_keys=False))
    result = CliRunner().invoke(app, ["check", str(bad), "--no-plot"])
    assert result.exit_code == 2
    line = result.output.strip().splitlines()[-1]
    assert "bad.yaml:" in line and where in line and message in line and "schema" in line


def _as_windio_2_0(doc: dict) -> dict:  # type: ignore[type-arg]
    """The IEA-15 2.1 example with its control block as windIO 2.0 has it: the converter
    that takes 2.0 to 2.1 (windIO/converters/windIO2windIO.py, v2p0_to_v2p1) moves
    torque.VS_minspd/VS_maxspd (rpm) to min/max_rotor_speed and drops the torque, pitch and
    supervisory blocks — undone here, as WISDEM's 2.0 examples carry them."""
    ctl = doc["control"]
    doc["windIO_version"] = "2.0"
    doc["control"] = {
        "supervisory": {"Vin": 3.0, "Vout": 25.0},
        "pitch": {"min_pitch": 1.5, "max_pitch": ctl["max_pitch_limit"]},  # degrees in 2.0
        "torque": {
            "tsr": ctl["optimal_tsr"],
            "VS_minspd": ctl["min_rotor_speed"],
            "VS_maxspd": ctl["rated_rotor_speed"],
        },
    }
    for key in ("cut_in_wind_speed", "cut_out_wind_speed"):
        doc["assembly"].pop(key)
    return doc


def test_a_windio_2_0_control_block_is_read_in_rpm_and_degrees(tmp_path):
    """windIO 2.0 (WISDEM's examples: the NREL 5-MW with VS_maxspd 12.1) gives its speeds
    in rpm and its pitch in degrees in 1.x's blocks; read as 1.x's rad/s, the IEA-15's
    5–7.56 rpm became 48–72 rpm (the NREL 5-MW's 115.5, flagged only as suspicious)."""
    import yaml

    from wtvib import importers

    p = tmp_path / "v20.yaml"
    p.write_text(yaml.safe_dump(_as_windio_2_0(iea15()), sort_keys=False))
    spec = importers.load(p)
    speed = spec.rotor.speed
    assert speed.min_rpm == pytest.approx(5.0, rel=1e-5)
    assert speed.max_rpm == pytest.approx(7.56, rel=1e-5)
    aero = spec.aerodynamics
    assert aero is not None
    assert aero.control.fine_pitch_deg == pytest.approx(1.5)
    assert aero.control.tip_speed_ratio == pytest.approx(9.0)
    assert aero.control.cut_in_wind_m_s == 3.0 and aero.control.cut_out_wind_m_s == 25.0
    assert speed.source == "control.torque.VS_minspd/VS_maxspd (rpm) of v20.yaml"


def test_a_windio_file_without_a_hub_mass_says_the_head_lacks_it(tmp_path):
    """WISDEM's 2.0 NREL 5-MW gives the nacelle (240 t) and no hub: the head was assembled
    without the hub's 56.8 t (16 %) without a word."""
    doc = iea15()
    doc["components"]["hub"].pop("elastic_properties")
    report = load_mutated(tmp_path, doc)
    assert any(w.startswith("components.hub: no elastic_properties.mass") for w in report.warnings)
    assert not any("components.hub" in w for w in load_mutated(tmp_path, iea15()).warnings)


def test_a_windio_file_without_a_speed_range_takes_the_command_lines(tmp_path):
    """WISDEM's IEA-3.4 and BAR examples give no usable range (VS_minspd 0): the error asks
    for --rpm, and with --rpm the file was refused all the same, by the same line."""
    import yaml

    from wtvib import importers

    doc = iea15()
    for key in ("min_rotor_speed", "rated_rotor_speed", "max_rotor_speed"):
        doc["control"].pop(key)
    p = tmp_path / "nospeed.yaml"
    p.write_text(yaml.safe_dump(doc, sort_keys=False))
    with pytest.raises(SpecError, match="give --rpm MIN:MAX"):
        importers.load(p)
    spec = importers.load(p, importers.ReadOptions(rpm=(5.0, 7.56)))
    assert spec.rotor.speed.steady_rpm == [(5.0, 7.56)]
    assert spec.rotor.speed.source == "the command line (--rpm/--rated)"


def test_the_schema_checks_long_number_lists_as_samples_with_the_same_verdicts():
    """The windIO schema's check of the IEA-22 file cost 0.45 s, its long number
    lists one validator call per entry; they are checked as samples that keep the smallest,
    the largest and a repeated entry. Planted faults in such lists — out of a minimum or
    maximum, a repeat in a list whose entries must be unique — give the full check's
    objections, at the entries' own indices (random positions, fixed seed)."""
    import copy
    import random

    from wtvib.importers import windio_schema

    if not windio_schema.available():
        pytest.skip("the windio package (its schema) is not installed")
    full = windio_schema._validator()
    doc = iea15()
    lists = []

    def walk(v, path):  # type: ignore[no-untyped-def]
        if isinstance(v, dict):
            for k, x in v.items():
                walk(x, (*path, k))
        elif isinstance(v, list):
            if len(v) > windio_schema.SAMPLE_ABOVE and all(type(x) in (int, float) for x in v):
                lists.append(path)
            else:
                for i, x in enumerate(v):
                    walk(x, (*path, i))

    walk(doc, ())
    assert len(lists) > 50
    rng = random.Random(7)
    seen = 0
    for path in rng.sample(lists, 10):
        for fault in (-1.0e9, 1.0e9, 1.5, "repeat"):
            d = copy.deepcopy(doc)
            target = d
            for k in path:
                target = target[k]
            i = rng.randrange(1, len(target))
            target[i] = target[i - 1] if fault == "repeat" else fault
            expected = sorted((tuple(e.absolute_path), e.message) for e in full.iter_errors(d))
            assert sorted(windio_schema.problems(d)) == expected, (path, fault)
            seen += bool(expected)
    assert seen > 5  # the faults were objections, not all harmless


def test_a_sample_keeps_the_extremes_a_repeat_and_the_first_entries():
    """The sample of a long number list (wtvib.importers.windio_schema._sampled): its
    smallest and largest entry, both entries of the first repeated value, the first six —
    each at its own index in the map back."""
    from wtvib.importers import windio_schema

    values = [float(i) for i in range(30)]
    values[20], values[25], values[27] = -5.0, 99.0, 11.0  # 27 repeats 11
    index: dict = {}  # type: ignore[type-arg]
    sample = windio_schema._sampled({"a": values}, (), index)["a"]
    order = index[("a",)]
    assert order == [0, 1, 2, 3, 4, 5, 11, 20, 25, 27]
    assert sample == [values[i] for i in order]
    assert windio_schema._original(("a", 7, "x"), index) == ("a", 20, "x")
    short = [1.0] * windio_schema.SAMPLE_ABOVE  # not longer than the limit: whole
    assert windio_schema._sampled(short, (), index) == short


def test_a_head_mass_given_on_the_command_line_keeps_the_files_blades(shared):
    """With --head-mass, the file's blades stand on the hub with their own inertia (the
    rotor's is most of the head's: without it the IEA-15's tower modes came out 10–30 %
    high), the rest of the mass half-way to the hub; the head's pitch inertia about its own
    CM is at least the rotor's J/2 less its share of the parallel-axis term, and the coupled
    model stands on it. A head lighter than the blades is refused."""
    from wtvib import importers
    from wtvib.errors import SpecError

    path = shared / "reference/IEA15/IEA-15-240-RWT.yaml"
    s = importers.load(path, importers.ReadOptions(head_mass=1.017e6))
    h = s.tower_head
    assert h is not None and h.mass_kg == pytest.approx(1.017e6)
    assert s.blade.structure is not None
    span = np.asarray(s.blade.structure.span_m)
    per_m = np.asarray(s.blade.structure.mass_per_length_kg_m)
    j_rotor = 3 * float(np.trapezoid(per_m * (s.blade.structure.hub_radius_m + span) ** 2, span))
    # about the head's own CM: the rotor's J and the parts' parallel-axis terms (0.4 %)
    assert j_rotor < h.inertia_roll_kgm2 < 1.01 * j_rotor
    assert h.inertia_pitch_kgm2 > 0.45 * j_rotor
    assert s.coupled is not None
    with pytest.raises(SpecError, match="not more than the blades"):
        importers.load(path, importers.ReadOptions(head_mass=1.0e5))


@pytest.mark.parametrize(
    ("density", "words"),
    [(5.0, "environment.water_density 5 kg/m³ is no water's"), ("salty", "water_density")],
)
def test_a_monopile_in_water_no_water_has_is_one_line(tmp_path, density, words, monkeypatch):
    """The monopile's water is ρ_w from environment.water_density: a density no water has,
    or no number, is one line naming the field, never a traceback."""
    from wtvib.importers import windio_schema

    monkeypatch.setattr(windio_schema, "available", lambda: False)
    doc = iea15()
    doc.setdefault("environment", {})["water_density"] = density
    with pytest.raises(SpecError, match=words):
        load_mutated(tmp_path, doc)


def test_a_blade_written_in_the_schema_s_axes_reads_as_the_same_blade(tmp_path):
    """The published IEA files give their 6×6 sections in BeamDyn's axes (K44 edgewise);
    windIO's schema names the axes the other way round (x to the trailing edge, y to the
    suction side: K44 flapwise). The same blade written both ways — axes 1 and 2 swapped
    in every matrix — is one blade: the same principal stiffnesses and the same principal
    axes' twist (the turn the cross term K45 gives runs the other way in swapped axes)."""
    windio_pkg = pytest.importorskip("windIO", reason="the windio package (dev extra) is needed")
    from pathlib import Path

    import yaml

    from wtvib import importers

    source = Path(windio_pkg.__file__).parent / "examples" / "turbine" / "IEA-15-240-RWT.yaml"
    data = yaml.safe_load(source.read_text())
    k = data["components"]["blade"]["structure"]["elastic_properties"]["stiffness_matrix"]
    swap = {1: 2, 2: 1, 3: 3, 4: 5, 5: 4, 6: 6}
    old = {key: value for key, value in k.items() if key.startswith("K")}
    for a in range(1, 7):
        for b in range(a, 7):
            i, j = sorted((swap[a], swap[b]))
            if f"K{i}{j}" in old:
                k[f"K{a}{b}"] = old[f"K{i}{j}"]
            else:
                k.pop(f"K{a}{b}", None)
    written = tmp_path / "schema_axes.yaml"
    written.write_text(yaml.safe_dump(data, sort_keys=False))
    published = importers.load(source).blade.structure
    schema = importers.load(written).blade.structure
    assert published is not None and schema is not None
    for field in ("ei_flap_nm2", "ei_edge_nm2", "twist_deg", "gj_nm2", "ga_flap_n", "ga_edge_n"):
        np.testing.assert_allclose(getattr(schema, field), getattr(published, field),
                                   rtol=1e-12, atol=1e-9, err_msg=field)  # fmt: skip


#: WISDEM's IEA-3.4 example (WISDEM/WISDEM examples/02_reference_turbines/IEA-3p4-130-RWT.yaml,
#: windIO 2.0): its assembly's rotor diameter and its control block as the file gives them
IEA34_DIAMETER = 129.82183952
IEA34_CONTROL = {
    "supervisory": {"Vin": 3.0, "Vout": 25.0, "maxTS": 80.0},
    "torque": {"tsr": 8.01754386, "VS_minspd": 0.0, "VS_maxspd": 19.098593171027442},
}


def test_a_wisdem_control_block_gives_the_speeds_wisdem_runs_the_rotor_at():
    """WISDEM's current windIO examples (IEA-3.4, BAR) give VS_minspd 0 (no limit) and a
    VS_maxspd of 2 rad/s that the tip-speed limit undercuts: WISDEM runs the rotor at
    the region-2 tip-speed ratio between them, Ω = clip(tsr·V/R, VS_minspd, min(VS_maxspd,
    maxTS/R)) (wisdem/rotorse/rotor_power.py). The IEA-3.4's: 3.539–11.77 rpm — its
    OpenFAST deck's controller (IEAWindTask37/IEA-3.4-130-RWT, DISCON.IN) has VS_MinOMSpd
    3.539 rpm and VS_RefSpd 11.63 rpm (the rated speed a little below the tip-speed
    limit). Such files were refused for 'no rotor speed range'."""
    d = {"assembly": {"rotor_diameter": IEA34_DIAMETER}, "components": {}, "control": IEA34_CONTROL}
    speed, note = windio._Reader(d, Path("iea34.yaml"), v2=True).speed()
    r = IEA34_DIAMETER / 2
    assert speed["min_rpm"] == pytest.approx(8.01754386 * 3.0 / r * 30 / math.pi, rel=1e-12)
    assert speed["max_rpm"] == pytest.approx(80.0 / r * 30 / math.pi, rel=1e-12)
    assert speed["min_rpm"] == pytest.approx(3.539, abs=1e-3)  # the deck's VS_MinOMSpd
    assert speed["max_rpm"] == pytest.approx(11.63, rel=0.015)  # the deck's VS_RefSpd
    assert "as WISDEM runs the rotor" in note and "maxTS 80" in note
    # a VS_maxspd below the tip-speed limit stands; a VS_minspd given stands
    given = {**IEA34_CONTROL, "torque": {"tsr": 8.0, "VS_minspd": 5.0, "VS_maxspd": 10.0}}
    d["control"] = given
    speed, note = windio._Reader(d, Path("iea34.yaml"), v2=True).speed()
    assert speed == {"min_rpm": 5.0, "max_rpm": 10.0}
    assert note == "Operating range from control.torque.VS_minspd/VS_maxspd (rpm): 5–10 rpm."
    # no tip-speed ratio or cut-in to place the lowest speed: refused, as before
    d["control"] = {"supervisory": {"maxTS": 80.0}, "torque": {"VS_minspd": 0.0, "VS_maxspd": 12.0}}
    with pytest.raises(SpecError, match="no rotor speed range"):
        windio._Reader(d, Path("iea34.yaml"), v2=True).speed()


def test_a_key_the_schema_requires_and_no_audit_reads_is_said_not_refused(tmp_path):
    """WISDEM's own example IEA-15-240-RWT_VolturnUS-S_user_elastic.yaml leaves out the
    hub's drag coefficient cd, which the windIO 2.1 schema requires and no vibration audit
    reads: audited, and the statement that the schema was checked names what the file
    leaves out (it was refused, exit 2). A value the schema objects to is still refused."""
    from wtvib.importers import windio_schema

    if not windio_schema.available():
        pytest.skip("the windio package (its schema) is not installed")
    doc = iea15()
    doc["components"]["hub"].pop("cd")
    report = load_mutated(tmp_path, doc)
    said = [a for a in report.assumptions if "leaves out keys it requires" in a]
    assert said and "components.hub: 'cd'" in said[0]
    doc["components"]["hub"]["cd"] = "high"
    with pytest.raises(SpecError, match=r"windIO 2\.x schema refuses"):
        load_mutated(tmp_path, doc)
