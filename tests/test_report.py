"""Rendering: the JSON is exactly Report.to_dict() (strict, no NaN); the terminal report
leads with the verdict and shows the headline warnings."""

import io
import json

from rich.console import Console

from tests.conftest import TURBINES
from wtvib import audit, spec
from wtvib.report import terminal, to_json


def strict(text: str) -> object:
    def refuse(name: str) -> None:
        raise ValueError(f"{name} is not JSON")

    return json.loads(text, parse_constant=refuse)


def test_json_is_the_report_dict_and_strict():
    r = audit.run(spec.load(TURBINES / "wka-60.yaml"))
    assert strict(to_json(r)) == json.loads(json.dumps(r.to_dict()))


def test_terminal_leads_with_the_verdict_and_warnings(write_spec):
    text = (
        write_spec().read_text()
        + "tower_head: {mass_kg: 3.0e5, cm_downwind_m: 0.5}\nyaw:\n"
        + "  drive_stiffness_nm_rad: 2.0e9\n"
    )
    r = audit.run(spec.load(write_spec(text, name="w.yaml")))
    out = io.StringIO()
    terminal(r, Console(file=out, width=100), written=[])
    head = out.getvalue().split("Natural frequencies")[0]
    assert "Verdict" in head and "Warning" in head and "inertia_yaw_kgm2" in head
