"""Scale-out on a Dask distributed cluster (the optional extra ``distributed``).

``batch`` and ``check --uncertainty`` take ``--scheduler ADDRESS``: the batch's audits go to
the cluster's workers through the ``concurrent.futures`` interface the local process pool
has (``Client.get_executor``), the Monte Carlo chunks through ``Client.map`` with the same
seeds — the results are those of a local run. Dask's nannies start workers with one BLAS
thread (``distributed.nanny.pre-spawn-environ``: OPENBLAS/OMP/MKL_NUM_THREADS = 1), as the
CLI pins its own processes.
"""

from typing import Any

from ..errors import WtvibError

#: how long to wait for the scheduler before saying it cannot be reached
CONNECT_TIMEOUT_S = 10


class ClusterError(WtvibError):
    """The scheduler cannot be used: the extra is missing or the address does not answer."""


#: how long a run waits for a cluster that has no worker before failing what is left
WORKERLESS_S = 60
#: how often a run waiting on the cluster looks whether it still has workers
POLL_S = 2.0


def connect(address: str) -> Any:
    """A ``distributed.Client`` on the scheduler at ``address`` (``tcp://host:8786``), with
    at least one worker: every failure — no Dask, a malformed address, another transport
    (``ucx://``, ``tls://``, ``inproc://``), a port that accepts and never answers, a
    scheduler without workers — one :class:`ClusterError` within
    :data:`CONNECT_TIMEOUT_S` (twice that at most), Dask's own noise kept off stderr."""
    try:
        from distributed import Client
    except ImportError:
        raise ClusterError(
            "--scheduler needs Dask distributed: pip install 'wtvib[distributed]'"
        ) from None
    from distributed.comm.addressing import parse_address, parse_host_port

    try:  # the address's form first: a Client made on a malformed one hangs as it is freed
        scheme, location = parse_address(address, strict=True)
        parse_host_port(location)
    except ValueError as exc:
        raise ClusterError(
            f"--scheduler {address}: not a scheduler address (tcp://host:8786): {exc}"
        ) from None
    if scheme != "tcp":
        raise ClusterError(
            f"--scheduler {address}: wtvib connects over tcp:// only (a {scheme}:// "
            "transport needs its own security or network setup); give tcp://host:port"
        )
    client = _within(
        lambda: Client(  # type: ignore[no-untyped-call]  # distributed has no annotations
            address, timeout=CONNECT_TIMEOUT_S - 2, set_as_default=False
        ),
        f"--scheduler {address}: no Dask scheduler answers there",
    )
    try:
        client.wait_for_workers(1, timeout=CONNECT_TIMEOUT_S)
    except Exception:  # distributed raises its own TimeoutError
        _quietly(client.close)
        raise ClusterError(
            f"--scheduler {address}: the scheduler answers but has no worker (start one "
            f"with `dask worker {address}`)"
        ) from None
    return client


def _within(make: Any, failure: str) -> Any:
    """``make()`` in a thread, given at most :data:`CONNECT_TIMEOUT_S`: a listener that
    accepts and never speaks Dask would otherwise hold the connection open forever. Dask's
    own complaints about a failed client (logged, or printed as it is freed) are kept off
    stderr: the one line said is ours."""
    import logging
    import sys
    import threading

    for name in ("distributed", "tornado"):  # their tracebacks on shutdown are not ours
        logging.getLogger(name).setLevel(logging.CRITICAL)
    box: dict[str, Any] = {}

    def run() -> None:
        try:
            box["client"] = make()
        except BaseException as exc:  # reported below, in one line; only the words kept,
            # so that the half-made client is freed here, in this thread, not at exit
            text = str(exc).splitlines()[0] if str(exc) else ""
            box["error"] = f"{type(exc).__name__}: {text}" if text else type(exc).__name__

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    thread.join(CONNECT_TIMEOUT_S)
    if "client" in box:
        return box["client"]
    _abandon()
    default = sys.unraisablehook

    def quiet(info: Any) -> None:  # a half-made Client's __del__ on the way out
        if "distributed" not in str(getattr(info.object, "__module__", "")):
            default(info)

    sys.unraisablehook = quiet
    why = box.get("error") or f"no answer within {CONNECT_TIMEOUT_S} s"
    raise ClusterError(f"{failure} ({why})")


def _abandon() -> None:
    """Mark every half-made client closed: freed at exit, its __del__ would otherwise wait
    out Dask's close timeout (16 s) on a connection that never opened (a client whose
    start failed is in no registry: found among the live objects)."""
    import gc

    from distributed import Client

    for obj in gc.get_objects():
        if isinstance(obj, Client) and obj.status != "running":
            obj.status = "closed"


def _quietly(action: Any) -> None:
    import contextlib

    with contextlib.suppress(Exception):
        action()


def has_workers(client: Any) -> bool:
    """Whether the cluster has a worker now (a scheduler that does not answer has none)."""
    try:
        return bool(client.scheduler_info().get("workers"))
    except Exception:  # a lost scheduler is a cluster without workers
        return False


def close(client: Any) -> None:
    """Close the client without Dask's shutdown noise on stderr."""
    _quietly(client.close)


def gather(client: Any, futures: list[Any]) -> list[Any]:
    """The futures' results, waiting while the cluster has a worker: a cluster whose
    workers are all gone for :data:`WORKERLESS_S` is a ClusterError, not a hang."""
    import contextlib
    import time

    from distributed import wait

    since = None
    pending = list(futures)
    while True:
        with contextlib.suppress(Exception):  # distributed's TimeoutError: look again
            wait(pending, timeout=POLL_S)  # type: ignore[no-untyped-call]
        not_done = [f for f in pending if not f.done()]
        if not not_done:
            return list(client.gather(futures))
        if has_workers(client):
            since = None
        else:
            since = since or time.monotonic()
            if time.monotonic() - since > WORKERLESS_S:
                raise ClusterError(
                    f"the cluster has had no worker for {WORKERLESS_S} s with "
                    f"{len(not_done)} tasks left; restart its workers and run again"
                )
        pending = list(not_done)
