"""windIO at unit level: 6×6 section matrices, floating turbines, speeds from control."""

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
    _, k55, k66 = windio._condensed(k[None])
    assert k55[0] == pytest.approx(ei) and k66[0] == pytest.approx(1e8)


def test_a_floating_turbine_is_refused_naming_the_component(tmp_path):
    text = "components:\n  floating_platform: {}\n  tower: {}\nassembly: {number_of_blades: 3}\n"
    with pytest.raises(SpecError) as err:
        windio.to_spec_data(tmp_path / "f.yaml", text)
    assert err.value.path == "components.floating_platform"
    assert "--clamped-base" in str(err.value)
