"""windIO outer shape, polars and control → the aerodynamics block (1.x and 2.x)."""

from pathlib import Path

import numpy as np
import pytest

from wtvib.errors import SpecError
from wtvib.importers import ReadOptions, load


def _examples() -> Path:
    import windIO

    return Path(windIO.__file__).parent / "examples/turbine"


def test_windio2_iea15_aerodynamics():
    spec = load(_examples() / "IEA-15-240-RWT.yaml")
    aero = spec.aerodynamics
    assert aero is not None and spec.turbine.rotor_diameter_m is not None
    st = aero.stations
    assert st.radius_m[-1] <= spec.turbine.rotor_diameter_m / 2 + 1e-9  # projected span
    # the file's own outer shape: maximum chord 5.77 m; root twist 15.59 (degrees in 2.x)
    assert max(st.chord_m) == pytest.approx(5.77, abs=0.1)
    assert 10 < st.twist_deg[0] < 20
    blends = [n for n in aero.airfoils if "|" in n]
    assert blends  # stations between two named aerofoils carry a blended polar
    assert aero.control.tip_speed_ratio == pytest.approx(9.0)
    assert any("tip-speed ratio is control.optimal_tsr (9)" in a for a in spec.assumptions)
    assert aero.control.min_pitch is not None  # control.min_pitch_table (peak shaving)


def test_windio1_twist_is_converted_from_radians(shared: Path):
    spec = load(shared / "reference/IEA15/IEA-15-240-RWT.yaml", ReadOptions(head_mass=1.0e6))
    aero = spec.aerodynamics
    assert aero is not None
    assert np.degrees(0.2722) == pytest.approx(aero.stations.twist_deg[0], abs=0.05)
    assert aero.control.cut_in_wind_m_s == 3.0 and aero.control.cut_out_wind_m_s == 25.0


def test_a_blade_naming_a_missing_aerofoil_is_one_line(tmp_path: Path):
    text = (_examples() / "IEA-15-240-RWT.yaml").read_text()
    broken = tmp_path / "IEA-15-broken.yaml"
    broken.write_text(text.replace("name: FFA-W3-241", "name: FFA-W3-241x", 1))
    with pytest.raises(SpecError, match="not in 'airfoils'"):
        load(broken)
