"""Scale-out on a Dask distributed cluster (the optional extra ``distributed``).

``batch`` and ``check --uncertainty`` take ``--scheduler ADDRESS``: the batch's audits go to
the cluster's workers through the ``concurrent.futures`` interface the local process pool
has (``Client.get_executor``), the Monte Carlo chunks through ``Client.map`` with the same
seeds — the results are those of a local run. Dask's nannies start workers with one BLAS
thread (``distributed.nanny.pre-spawn-environ``: OPENBLAS/OMP/MKL_NUM_THREADS = 1), as the
CLI pins its own processes.
"""

from typing import Any

from .errors import WtvibError

#: how long to wait for the scheduler before saying it cannot be reached
CONNECT_TIMEOUT_S = 10


class ClusterError(WtvibError):
    """The scheduler cannot be used: the extra is missing or the address does not answer."""


def connect(address: str) -> Any:
    """A ``distributed.Client`` on the scheduler at ``address`` (``tcp://host:8786``)."""
    try:
        from distributed import Client
    except ImportError:
        raise ClusterError(
            "--scheduler needs Dask distributed: pip install 'wtvib[distributed]'"
        ) from None
    from distributed.comm.addressing import parse_address, parse_host_port

    try:  # the address's form first: a Client made on a malformed one hangs as it is freed
        scheme, location = parse_address(address, strict=True)
        if scheme != "inproc":
            parse_host_port(location)
    except ValueError as exc:
        raise ClusterError(
            f"--scheduler {address}: not a scheduler address (tcp://host:8786): {exc}"
        ) from None
    try:
        return Client(address, timeout=CONNECT_TIMEOUT_S, set_as_default=False)
    except (OSError, TimeoutError, ValueError) as exc:
        raise ClusterError(
            f"--scheduler {address}: no Dask scheduler answers there "
            f"({type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else 'timed out'})"
        ) from None
