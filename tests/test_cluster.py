"""Scale-out on Dask: batch and check --uncertainty on a scheduler give the
results of a local run; an unreachable scheduler or a missing extra is one line, exit 2."""

import json

import pytest
from typer.testing import CliRunner

from wtvib.cli import app
from wtvib.workflows import batch

from .conftest import TURBINES

distributed = pytest.importorskip(
    "distributed", reason="the 'distributed' extra (a dev dependency) is not installed"
)


@pytest.fixture(scope="module")
def scheduler():  # type: ignore[no-untyped-def]
    """A local cluster (two worker threads in this process, on tcp://127.0.0.1: wtvib
    connects over tcp only) and its scheduler's address."""
    with distributed.LocalCluster(
        n_workers=1,
        threads_per_worker=2,
        processes=False,
        dashboard_address=None,
        protocol="tcp",
        host="127.0.0.1",
    ) as cluster:
        yield cluster.scheduler_address


def _without_identity(report: dict) -> dict:  # type: ignore[type-arg]
    return {k: v for k, v in report.items() if k != "produced_by"}


def test_a_batch_on_a_cluster_matches_the_local_run(scheduler):
    paths = sorted(TURBINES.glob("*.yaml"))[:5]
    local = batch.run(paths, jobs=1, plots=False)
    with distributed.Client(scheduler) as client:
        remote = batch.run(paths, plots=False, executor=client.get_executor())
    assert [i.path for i in remote] == [i.path for i in local]
    for a, b in zip(local, remote, strict=True):
        assert a.report is not None and b.report is not None
        assert _without_identity(a.report) == _without_identity(b.report)


def test_batch_scheduler_option_runs_on_the_cluster(scheduler, tmp_path):
    paths = [str(p) for p in sorted(TURBINES.glob("*.yaml"))[:3]]
    args = ["batch", *paths, "--no-plots", "-f", "json"]
    local = CliRunner().invoke(app, args)
    remote = CliRunner().invoke(app, [*args, "--scheduler", scheduler])
    assert remote.exit_code == local.exit_code, remote.output
    rows = [json.loads(r.stdout)["results"] for r in (local, remote)]
    assert [_without_identity(i["report"]) for i in rows[0]] == [
        _without_identity(i["report"]) for i in rows[1]
    ]


def test_check_uncertainty_on_a_cluster_draws_the_same_samples(scheduler):
    args = ["check", str(TURBINES / "wka-60.yaml"), "--no-plot", "-f", "json", "--uncertainty"]
    args += ["--samples", "3000"]
    local = json.loads(CliRunner().invoke(app, args).stdout)
    remote = json.loads(CliRunner().invoke(app, [*args, "--scheduler", scheduler]).stdout)
    assert local["uncertainty"] == remote["uncertainty"]


def test_an_unreachable_scheduler_is_one_line(monkeypatch):
    from wtvib.studies import cluster

    monkeypatch.setattr(cluster, "CONNECT_TIMEOUT_S", 1)
    result = CliRunner().invoke(
        app,
        ["batch", str(TURBINES / "mod-2.yaml"), "--no-plots", "--scheduler", "tcp://127.0.0.1:9"],
    )
    assert result.exit_code == 2
    assert result.stderr.count("\n") == 1 and "no Dask scheduler answers" in result.stderr


def test_scheduler_without_uncertainty_is_a_usage_error():
    result = CliRunner().invoke(
        app, ["check", str(TURBINES / "mod-2.yaml"), "--no-plot", "--scheduler", "tcp://x:1"]
    )
    assert result.exit_code == 2 and "--uncertainty" in result.output
