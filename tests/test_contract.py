"""The JSON contract: every report validates against the published schema
(`wtvib schema --report`), strict JSON, every key described."""

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from tests.conftest import TURBINES
from wtvib import audit, importers, spec
from wtvib.cli import app
from wtvib.workflows.contract import CHECK_NUMBERS, report_schema

jsonschema = pytest.importorskip("jsonschema", reason="jsonschema (dev extra) validates")
DATA = Path(__file__).resolve().parent / "data" / "campbell"


def validate(doc: object) -> None:
    jsonschema.Draft202012Validator(report_schema()).validate(doc)


@pytest.mark.parametrize("name", sorted(p.name for p in TURBINES.glob("*.yaml")))
def test_every_catalogue_report_validates(name):
    validate(json.loads(json.dumps(audit.run(spec.load(TURBINES / name)).to_dict())))


@pytest.mark.parametrize(
    "source",
    [DATA / "openfast", DATA / "hawcstab2" / "steady.cmb", DATA / "hawcstab2" / "blade.cmb"],
)
def test_imported_results_reports_validate(source):
    validate(audit.run(importers.load(source, importers.ReadOptions(blades=3))).to_dict())


def test_a_deck_with_aerodynamics_and_an_uncertainty_run_validate(shared):
    validate(audit.run(importers.load(shared / "reference/NREL5MW/NREL-5MW.fst")).to_dict())
    validate(audit.run(spec.load(TURBINES / "wka-60.yaml"), samples=200).to_dict())


def test_every_check_number_the_catalogue_writes_is_described(shared):
    """A key a check writes and the schema does not describe is an undocumented key: the
    catalogue's and an ElastoDyn deck's (its polynomials' sets)."""
    described = set(CHECK_NUMBERS) | {"id", "subsystem", "status", "message", "rule"}
    seen: set[str] = set()
    specs = [spec.load(p) for p in TURBINES.glob("*.yaml")]
    specs.append(
        importers.load(shared / "reference/NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat")
    )
    for s in specs:
        for c in audit.run(s).to_dict()["checks"]:
            seen |= set(c)
    assert "sets" in seen
    assert seen - described == set()


def test_the_schema_command_prints_the_report_schema():
    result = CliRunner().invoke(app, ["schema", "--report"])
    assert result.exit_code == 0
    assert json.loads(result.stdout)["properties"]["schema"]["const"] == "wtvib-report/1"


def test_the_typed_document_declares_what_the_contract_describes():
    """The typed report (wtvib.document) and the JSON contract (wtvib.workflows.contract)
    name the same keys: the report's and a mode's, required and optional, and a check's
    required ones (a check's numbers the contract reads from the typed document itself) —
    a key added to one and not the other fails here."""
    from typing import get_type_hints

    from wtvib import document
    from wtvib.workflows import contract

    schema = contract.report_schema()
    report = get_type_hints(document.ReportDoc)
    assert set(report) == set(schema["properties"])
    assert document.ReportDoc.__required_keys__ == set(schema["required"])
    assert set(get_type_hints(document.ModeDoc)) == set(contract._MODE["properties"])
    assert document.ModeDoc.__required_keys__ == set(contract._MODE["required"])
    assert document.CheckDoc.__required_keys__ == set(contract._CHECK["required"])
    assert contract.CHECK_NUMBERS["daf"].startswith("Dynamic amplification factor")


def test_a_report_is_its_typed_document():
    """Every key the catalogue's reports write is one the typed document declares, at
    every level a consumer reads (report, turbine, operation, rule, modes, checks,
    Campbell curves)."""
    from typing import get_type_hints

    from wtvib import document

    declared = {name: set(get_type_hints(kind)) for name, kind in (
        ("report", document.ReportDoc), ("turbine", document.TurbineDoc),
        ("operation", document.OperationDoc), ("rule", document.RuleSettingsDoc),
        ("mode", document.ModeDoc), ("check", document.CheckDoc),
        ("campbell", document.CampbellDoc), ("curve", document.CampbellModeDoc),
    )}  # fmt: skip
    for path in sorted(TURBINES.glob("*.yaml")):
        doc = audit.run(spec.load(path)).to_dict()
        assert set(doc) <= declared["report"], path.name
        for key in ("turbine", "operation", "rule", "campbell"):
            assert set(doc[key]) <= declared[key], (path.name, key)
        assert all(set(m) <= declared["mode"] for m in doc["modes"]), path.name
        assert all(set(c) <= declared["check"] for c in doc["checks"]), path.name
        curves = doc["campbell"]["modes"].values()
        assert all(set(c) <= declared["curve"] for c in curves), path.name
