"""Figures draw results: each returns a figure where the report has its data and None
where it has not, and the registry lists what check writes (PNG tagged as wtvib's)."""

import pytest

from tests.conftest import TURBINES
from wtvib import audit, spec
from wtvib.outputs import SOFTWARE_TAG
from wtvib.plots import blade, campbell, diagrams, drivetrain, png_bytes, rotor, system


@pytest.fixture(scope="module")
def reports():
    return {
        name: audit.run(spec.load(TURBINES / f"{name}.yaml"))
        for name in ("mod-0", "stall-rotor-1mw", "wka-60")
    }


def test_each_figure_draws_only_what_its_report_has(reports):
    mod0, stall_rotor, wka = reports["mod-0"], reports["stall-rotor-1mw"], reports["wka-60"]
    assert drivetrain.power_curve_plot(mod0) is not None  # synchronous on the grid
    assert drivetrain.power_curve_plot(wka) is None
    assert rotor.floquet_plot(mod0) is not None and rotor.floquet_plot(wka) is None
    for fig in (blade.flutter_plot, blade.stability_chart_plot, blade.stall_damping_plot):
        assert fig(stall_rotor) is not None and fig(wka) is None
    assert system.coupled_energy_plot(wka) is None  # no coupled block
    assert campbell.campbell_plot(wka).axes  # the tower-and-blade diagram


def test_the_registry_names_every_figure_and_tags_the_png(reports):
    names = set(diagrams(reports["mod-0"]))
    assert {"campbell", "campbell-drivetrain", "drivetrain-power", "floquet"} <= names
    data = png_bytes(campbell.campbell_plot(reports["wka-60"]))
    assert data.startswith(b"\x89PNG") and SOFTWARE_TAG.encode() in data[:4096]
