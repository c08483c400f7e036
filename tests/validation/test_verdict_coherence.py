"""Every verdict coherent with its own numbers and with every other line of the
same report, over the whole catalogue and the reference decks (the property test).

* no check passes whose own ``margin`` is below its ``required_margin``;
* no mode id carries two frequencies anywhere in the report (modes list, coupling table);
* every check's governing mode is judged, and exists in the regime the check names;
* nothing superseded or locked is judged.
"""

import json
from pathlib import Path

import pytest

from tests.conftest import TURBINES
from wtvib import audit, importers, spec
from wtvib.outputs.report import to_json

DECKS = [
    ("NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat", (6.9, 12.1)),
    ("NREL5MW/NREL-5MW.fst", None),
    ("IEA3.4/IEA-3.4-130-RWT_ElastoDyn.dat", (3.8, 11.75)),
    ("WindPACT1.5/Test13.fst", (11.0, 20.5)),
    ("AWT27/Test01.fst", None),
    ("AOC15-50/Test08.fst", None),
]


def coherent(report: audit.Report) -> None:
    doc = json.loads(to_json(report))  # strict JSON too
    modes = {m["id"]: m for m in doc["modes"]}
    assert len(modes) == len(doc["modes"]), "a mode id appears twice"
    judged = {m.id: m for m in report.modes if m.judged}
    for c in doc["checks"]:
        margin, need = c.get("margin"), c.get("required_margin")
        if c["status"] == "pass" and margin is not None and need is not None:
            assert margin >= need * (1 - 1e-6), (c["id"], margin, need)
        gov = c.get("mode")
        if gov and ".resonance." in c["id"]:
            assert gov in judged, (c["id"], gov)
            regime = c.get("regime")
            exists = judged[gov].regimes
            assert regime is None or exists is None or regime in exists, (c["id"], regime)
        if c["id"] == "system.coupling":
            for row in c["modes"]:
                if row["id"] in modes:
                    assert row["coupled_hz"] == pytest.approx(
                        modes[row["id"]]["frequency_hz"], rel=1e-5, abs=1e-6
                    ), row["id"]
    for f in report.findings:
        assert f.mode.judged, f.mode.id


@pytest.mark.parametrize("path", sorted(TURBINES.glob("*.yaml")), ids=lambda p: p.stem)
def test_catalogue_verdicts_are_coherent(path: Path):
    coherent(audit.run(spec.load(path)))


@pytest.mark.parametrize(("deck", "rpm"), DECKS, ids=[d for d, _ in DECKS])
def test_reference_deck_verdicts_are_coherent(shared, deck, rpm):
    coherent(audit.run(importers.load(shared / "reference" / deck, importers.ReadOptions(rpm=rpm))))
