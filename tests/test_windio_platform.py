"""windIO floating platforms a user can get wrong: each one line naming the field, never a
traceback (wtvib.importers.windio_platform on WISDEM's OC4 description)."""

import math
from pathlib import Path

import pytest
import yaml

from wtvib.errors import SpecError
from wtvib.importers import windio
from wtvib.importers.windio_platform import platform

OC4 = Path(__file__).parent / "data" / "windio_floating" / "oc4_semi.yaml"


def read(edit) -> object:  # type: ignore[no-untyped-def]
    doc = yaml.safe_load(OC4.read_text())
    edit(doc)
    return platform(windio._paths(doc, (), str(OC4)), OC4, 6e5, 10.0)


def members(doc):  # type: ignore[no-untyped-def]
    return doc["components"]["floating_platform"]["members"]


def joints(doc):  # type: ignore[no-untyped-def]
    return doc["components"]["floating_platform"]["joints"]


CASES = [
    (
        "rectangular",
        lambda d: members(d)[0]["outer_shape"].update(shape="rectangular"),
        "members[0].outer_shape.shape",
        "circular members only",
    ),
    (
        "unknown joint",
        lambda d: members(d)[1].update(joint2="nowhere"),
        "members[1].joint2",
        "'nowhere' is not defined",
    ),
    (
        "unknown material",
        lambda d: members(d)[0]["structure"]["layers"][0].update(material="x"),
        "members[0].structure.layers[0]",
        "material 'x' is not in the file's materials",
    ),
    (
        "negative diameter",
        lambda d: members(d)[0]["outer_shape"]["outer_diameter"].update(values=[-6.5, 6.5]),
        "outer_diameter.values",
        "must be > 0 m",
    ),
    (
        "tower off axis",
        lambda d: joints(d)[1].update(location=[3.0, 0.0, 10.0]),
        None,
        "wtvib's platform has the tower on its vertical axis",
    ),
    (
        "two transitions",
        lambda d: joints(d)[0].update(transition=True),
        None,
        "exactly one joint must be the transition",
    ),
    (
        "relative cycle",
        lambda d: (
            joints(d)[0].update(relative="main_freeboard")
            or joints(d)[1].update(relative="main_keel")
        ),
        None,
        "never resolve",
    ),
    (
        "line of nylon-ish custom",
        lambda d: d["components"]["mooring"]["line_types"][0].update(type="polypropylene"),
        "components.mooring.line_types[0]",
        "no mass_density and stiffness",
    ),
    (
        "line to nowhere",
        lambda d: d["components"]["mooring"]["lines"][0].update(node1="x"),
        "components.mooring.lines[0]",
        "names a node or line type",
    ),
    (
        "line too short",
        lambda d: d["components"]["mooring"]["lines"][0].update(unstretched_length=50.0),
        None,
        "too short for them",
    ),
    (
        "no water",
        lambda d: [
            j.update(location=[j["location"][0], j["location"][1], 50.0 + i])
            for i, j in enumerate(joints(d))
        ],
        None,
        "must meet|displace no water|below the water line",
    ),
]


@pytest.mark.parametrize(("label", "edit", "where", "message"), CASES, ids=[c[0] for c in CASES])
def test_a_mistake_is_one_line_naming_it(label, edit, where, message):
    with pytest.raises(SpecError) as err:
        read(edit)
    text = str(err.value)
    assert "\n" not in text
    assert any(part in text for part in message.split("|")), text
    if where:
        assert where in (err.value.path or "") or where in text


def test_windio_2_radians_in_a_stiffener_spacing_are_read_and_said():
    """windIO's own 1.x → 2.x converter reads a longitudinal spacing under π/2 as radians;
    so does wtvib, says so once for all the members that share it, and builds the same
    steel as from degrees (12 stiffeners round each column, not 688)."""
    from wtvib.importers.windio_platform import _Platform
    from wtvib.numerics import hull

    def stiffened(spacing: float) -> tuple[float, list[str]]:
        doc = yaml.safe_load(OC4.read_text())
        for m in members(doc)[1:4]:
            m["structure"]["longitudinal_stiffeners"] = {
                "material": "steel", "flange_thickness": 0.1, "flange_width": 0.2,
                "web_height": 0.2, "web_thickness": 0.1, "spacing": spacing}  # fmt: skip
        reader = _Platform(windio._paths(doc, (), str(OC4)), OC4)
        steel = sum(hull.structure(m)[0, 0] for m in reader.members(reader.joints()))
        said = platform(windio._paths(doc, (), str(OC4)), OC4, 6e5, 10.0).warnings
        return steel, [w for w in said if "read as radians" in w]

    steel_rad, radians = stiffened(0.5236)
    steel_deg, none = stiffened(30.0)
    assert len(radians) == 1 and "(and 2 more)" in radians[0] and not none
    assert steel_rad == pytest.approx(steel_deg, rel=1e-9)
    bare, _ = stiffened(360.0)  # one stiffener a column
    rho = next(
        m["rho"] for m in yaml.safe_load(OC4.read_text())["materials"] if m["name"] == "steel"
    )
    # 11 more stiffeners of 0.04 m² on three 32 m columns
    assert steel_deg - bare == pytest.approx(11 * 0.04 * rho * 32.0 * 3, rel=1e-6)


def test_a_line_type_with_its_own_mass_and_stiffness_is_taken_as_given():
    """``mass_density`` and ``stiffness`` given: MoorPy's library is not consulted; OC4's
    published line (113.35 kg/m, EA 753.6 MN, Robertson et al. 2014) pulls harder
    than the library chain the file's 0.0766 m volume-equivalent diameter gives (40 kg/m)."""
    from wtvib.importers.windio_platform import _Platform

    def pull(edit) -> float:  # type: ignore[no-untyped-def]
        doc = yaml.safe_load(OC4.read_text())
        edit(doc)
        reader = _Platform(windio._paths(doc, (), str(OC4)), OC4)
        joints = reader.joints()
        reader.members(joints)
        k, down, _ = reader.moorings(joints)
        assert k[0, 0] > 0
        return down

    library = pull(lambda d: None)
    given = pull(
        lambda d: d["components"]["mooring"]["line_types"][0].update(
            type="custom", mass_density=113.35, stiffness=7.536e8
        )
    )
    assert given > 2 * library


def test_a_joint_s_axial_added_mass_coefficient_is_read():
    """windIO's ``axial_coeffs.Ca`` at a member's end joint sets its end term
    ρ·C_a,end·πD³/12 (else RAFT's 0.6): OC4's main column (6.5 m) on a keel joint with Ca 1.0
    gains ρ·0.4·π·6.5³/12 in heave."""
    from wtvib.importers.windio_platform import _Platform
    from wtvib.numerics import hull

    def heave(edit) -> float:  # type: ignore[no-untyped-def]
        doc = yaml.safe_load(OC4.read_text())
        edit(doc)
        reader = _Platform(windio._paths(doc, (), str(OC4)), OC4)
        return float(hull.added_mass(reader.members(reader.joints()), 1025.0)[2, 2])

    base = heave(lambda d: None)
    keel = heave(lambda d: joints(d)[0].update(axial_coeffs={"Ca": 1.0}))
    assert keel - base == pytest.approx(1025.0 * 0.4 * math.pi * 6.5**3 / 12, rel=1e-9)
