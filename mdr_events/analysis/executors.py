"""Where a sweep's chunks run: one :class:`concurrent.futures.Executor` for every engine.

:func:`open_executor` turns what a user names into an executor and closes what it opened itself:

==========================================  ===============================================================
``scheduler``                               the executor
==========================================  ===============================================================
``"serial"``                                a :class:`~concurrent.futures.ThreadPoolExecutor` of one thread: here,
                                            one chunk after another (the caller records each as it completes)
``"local"``                                 a new ``distributed.LocalCluster`` of ``workers`` processes on
                                            loopback, through ``Client.get_executor()``
an address (``"tcp://host:8786"``)          a ``distributed.Client`` of that scheduler, through its executor
a ``distributed.Client``                    its executor (the client stays open: it is the caller's)
a ``concurrent.futures.Executor``           itself (not shut down: it is the caller's)
``None``                                    the active dask client if there is one, else ``"local"`` where
                                            ``distributed`` is installed, else ``"serial"``
==========================================  ===============================================================

Every engine runs the same function on the same chunks, so that the numbers are identical on each.
"""

from __future__ import annotations

import concurrent.futures
import importlib.util
import logging
import os
import signal
import sys
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any, Callable

from mdr_events.validation import check_count, shown

__all__ = ["Engine", "open_executor", "default_scheduler", "check_workers", "LOOPBACK_DASHBOARD", "SCHEDULER_ALLOWED",
           "DEFAULT_CHUNK"]

#: Runs per chunk (one task) by default: enough that the engine's overhead per run is far below a run's cost.
DEFAULT_CHUNK = 50

#: The local cluster's dashboard: on loopback, on a free port (None would take the default :8787).
LOOPBACK_DASHBOARD = "127.0.0.1:0"
#: The protocols of a scheduler's address that need no setup of their own.
ADDRESS_PROTOCOLS = ("tcp",)
#: Protocols of dask's schedulers that need a setup of their own (certificates, UCX), refused with that reason.
SETUP_PROTOCOLS = ("tls", "ucx", "ws", "wss")
#: The ports a scheduler's address may name (0 is no port to connect to; 65535 is TCP's largest).
ADDRESS_PORTS = (1, 65535)
#: How long a client that failed to reach its scheduler is given to close (it holds no connection: it closes at once).
FAILED_CLIENT_CLOSE_TIMEOUT = 5.0
#: What ``scheduler`` may be, for messages.
SCHEDULER_ALLOWED = ("'serial', 'local', a dask scheduler's address such as 'tcp://host:8786', a "
                     "distributed.Client, a concurrent.futures.Executor, or None")


def default_scheduler() -> str:
    """``"local"`` where ``dask.distributed`` is installed (the extra ``mdr_events[scale]``), else ``"serial"``."""
    return "local" if importlib.util.find_spec("distributed") is not None else "serial"


def check_workers(workers) -> int:
    """A local cluster's worker count: one process per core at most (each run is single-threaded and CPU-bound,
    so more processes than cores only compete for them, each holding its own interpreter and libraries)."""
    cores = os.cpu_count() or 1
    workers = check_count("workers", workers, 1)
    if workers > cores:
        raise ValueError(f"workers={workers} is not allowed; allowed: 1 to {cores} (this machine's cores: a run is "
                         "single-threaded, more processes only compete for them)")
    return workers


def _active_client():
    """The dask client this process made current (``distributed.default_client``), or ``None``."""
    if importlib.util.find_spec("distributed") is None:
        return None
    from distributed import default_client
    try:
        return default_client()
    except ValueError:  # no client
        return None


def _is_client(scheduler) -> bool:
    if importlib.util.find_spec("distributed") is None:
        return False
    from distributed import Client
    return isinstance(scheduler, Client)


def check_scheduler(scheduler, workers: int | None) -> None:
    """Refuse a ``scheduler`` that names no engine, and ``workers`` beside anything but ``"local"``."""
    named = isinstance(scheduler, str) and (scheduler in ("serial", "local") or "://" in scheduler)
    if not (named or scheduler is None or _is_client(scheduler)
            or isinstance(scheduler, concurrent.futures.Executor)):
        raise ValueError(f"scheduler={shown(scheduler)} is not allowed; allowed: {SCHEDULER_ALLOWED}")
    protocol = scheduler.partition("://")[0] if isinstance(scheduler, str) and "://" in scheduler else None
    if protocol is not None and protocol not in ADDRESS_PROTOCOLS:
        why = ("its protocol needs a setup of its own (certificates for tls://, UCX for ucx://)"
               if protocol in SETUP_PROTOCOLS else f"{protocol}:// is no protocol of a dask scheduler")
        raise ValueError(f"scheduler={scheduler!r} is not allowed: {why}; allowed: an address of " + " or ".join(
            f"{name}://" for name in ADDRESS_PROTOCOLS))
    if protocol is not None:
        check_address(scheduler)
    if workers is not None and scheduler not in ("local", None):
        raise ValueError(f"workers={workers} is not allowed with scheduler={shown(scheduler)}; allowed: with "
                         "scheduler='local' (any other engine has its own workers)")


def check_address(scheduler: str) -> None:
    """Refuse a ``tcp://`` address that names no host and port (``"tcp://"``, ``"tcp://host"``, a port out of
    range), in dask's own reading of it (``distributed.comm.addressing``), before any client is made: a
    ``distributed.Client`` of such an address made itself the process's default client before it failed, and stayed
    so, "connecting" to nothing, while anything held its error (every later ``to_netcdf`` of the process then asked
    it for a lock, and failed). Without ``distributed`` the address is left to :func:`open_executor` to refuse."""
    if importlib.util.find_spec("distributed") is None:
        return
    from distributed.comm.addressing import parse_address, parse_host_port

    allowed = (f"allowed: an address tcp://host:port of a running dask scheduler, a port from {ADDRESS_PORTS[0]} "
               f"to {ADDRESS_PORTS[1]} (such as 'tcp://127.0.0.1:8786')")
    try:
        protocol, location = parse_address(scheduler, strict=True)
        host, port = parse_host_port(location)
    except ValueError as error:
        raise ValueError(f"scheduler={scheduler!r} is not allowed: {error}; {allowed}") from None
    if protocol not in ADDRESS_PROTOCOLS:
        raise ValueError(f"scheduler={scheduler!r} is not allowed: it names the protocol {protocol!r}; {allowed}")
    if not host or any(character.isspace() for character in scheduler):
        raise ValueError(f"scheduler={scheduler!r} is not allowed: it names no host (or has blanks); {allowed}")
    if not ADDRESS_PORTS[0] <= port <= ADDRESS_PORTS[1]:
        raise ValueError(f"scheduler={scheduler!r} is not allowed: port {port} is out of range; {allowed}")


def _close_failed_client(distributed, before) -> None:
    """Close the client that a failed ``distributed.Client(address)`` left as the process's default (it registers
    itself before it connects, and only some failures close it), so that nothing is left "connecting": later
    computations and ``to_netcdf`` of the process would use it; ``before`` is the default client before (the
    caller's, left alone)."""
    try:
        leftover = distributed.default_client()
    except ValueError:  # (none)
        return
    if leftover is not before:
        try:
            leftover.close(timeout=FAILED_CLIENT_CLOSE_TIMEOUT)
        except Exception:  # (closing what never connected: a failure here is no news to the user)  # noqa: BLE001
            logging.getLogger(__name__).debug("a failed client did not close", exc_info=True)


def _distributed(scheduler):
    try:
        import distributed
    except ModuleNotFoundError:
        raise ValueError(f"scheduler={scheduler!r} needs dask.distributed; allowed: scheduler='serial', or install "
                         "the extra: pip install 'mdr_events[scale]'") from None
    return distributed


def _restore_dask_scheduler(before) -> None:
    """Put dask's ``scheduler`` setting back as it was (a ``Client`` sets it when made, even if it then fails)."""
    import dask

    if before is None:
        dask.config.config.pop("scheduler", None)
    else:
        dask.config.set(scheduler=before)


#: What a script that starts a local cluster needs: each worker process imports the script (Python's "spawn").
MAIN_GUARD = "if __name__ == '__main__':"


def _importing_the_script() -> bool:
    """Whether this process is a worker that "spawn" started and that is still importing the user's script (run
    again as ``__mp_main__`` while the process bootstraps, multiprocessing's ``_inheriting``, in which it refuses
    to start processes): a sweep there is the script's own, run again by its workers."""
    import multiprocessing

    return "__mp_main__" in sys.modules and bool(getattr(multiprocessing.current_process(), "_inheriting", False))


def _local_cluster(distributed, workers: int | None):
    """A new ``LocalCluster`` of ``workers`` processes on loopback. A script without :data:`MAIN_GUARD` started one
    again in each worker, which multiprocessing refused with a traceback per worker, and the script ended on
    "RuntimeError: Nanny failed to start."; such a worker now ends quietly and the script's process says why, in
    one line (``ValueError``), as for any cluster that does not start."""
    if _importing_the_script():
        raise SystemExit(1)
    try:
        with _workers_deaf_to_ctrl_c():
            return distributed.LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                                            processes=True, host="127.0.0.1", dashboard_address=LOOPBACK_DASHBOARD,
                                            silence_logs=logging.CRITICAL)  # (a run's error is its own result)
    except Exception as error:  # (the workers' failure, in distributed's words)
        reason = " ".join(f"{type(error).__name__}: {error}".split())
        raise ValueError(f"scheduler='local' did not start its workers ({reason}); allowed: a script that starts a "
                         f"local cluster with its code under `{MAIN_GUARD}` (each worker imports the script), or "
                         "scheduler='serial'") from None


@contextmanager
def _workers_deaf_to_ctrl_c() -> Iterator[None]:
    """While a local cluster starts, Ctrl-C (SIGINT) is ignored, so that the worker processes it starts inherit the
    disposition: a Ctrl-C at the terminal reaches every process of its group, and each worker printed its own
    traceback; this process alone hears it, and closes the cluster. (Only in the main thread, where a handler can
    be set; a Ctrl-C while the cluster starts waits until it has.)"""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)


@contextmanager
def open_executor(scheduler=None, workers: int | None = None) -> Iterator[concurrent.futures.Executor]:
    """The executor of ``scheduler`` (see the module's table); what this opened is closed on leaving, and futures
    still pending are the caller's to cancel.

    Raises
    ------
    ValueError
        Naming ``scheduler`` (no engine, or ``distributed`` not installed) or ``workers`` (not with ``"local"``).
    """
    check_scheduler(scheduler, workers)
    if workers is not None:
        workers = check_workers(workers)
    if scheduler is None:
        scheduler = "local" if workers is not None else _active_client() or default_scheduler()
    if isinstance(scheduler, concurrent.futures.Executor):
        yield scheduler
    elif scheduler == "serial":
        with concurrent.futures.ThreadPoolExecutor(max_workers=1) as executor:
            yield executor
    elif _is_client(scheduler):
        yield scheduler.get_executor(pure=False)
    elif scheduler == "local":
        distributed = _distributed(scheduler)
        with _local_cluster(distributed, workers) as cluster, distributed.Client(cluster) as client:
            yield client.get_executor(pure=False)
    else:
        distributed = _distributed(scheduler)
        import dask

        before, client_before = dask.config.get("scheduler", None), _active_client()
        try:
            client = distributed.Client(scheduler)
        except (OSError, ValueError, TypeError) as error:  # (no scheduler there)
            _close_failed_client(distributed, client_before)  # (a client that failed left itself the default,
            _restore_dask_scheduler(before)  # and dask's scheduler)
            raise ValueError(f"scheduler={scheduler!r} cannot be reached ({type(error).__name__}: {error}); allowed: the "
                             "address of a running dask scheduler, or 'local' / 'serial'") from None
        with client:
            yield client.get_executor(pure=False)


@dataclass(frozen=True)
class Engine:
    """Where a sweep's runs are carried out, in chunks, and who hears of their progress.

    Parameters
    ----------
    scheduler : "serial", "local", str, distributed.Client or concurrent.futures.Executor, optional
        Where the chunks run (the module's table; default: the active dask client if there is one, else
        ``"local"`` where ``distributed`` is installed, else ``"serial"``).
    workers : int, optional
        With ``"local"``: the cluster's processes (default the machine's cores; at most that many).
    chunk_size : int, default 50
        Runs per task (and per Zarr chunk of a store).
    progress : callable, optional
        Called with (runs done, runs in all) after each chunk.

    Raises
    ------
    TypeError
        A ``progress`` that is not callable.
    ValueError
        An unknown scheduler, ``workers`` not with ``"local"`` or not a count >= 1, ``chunk_size`` < 1.
    """

    scheduler: Any = None
    workers: int | None = None
    chunk_size: int = DEFAULT_CHUNK
    progress: Callable[[int, int], None] | None = None

    def __post_init__(self) -> None:
        check_scheduler(self.scheduler, self.workers)
        if self.workers is not None:
            object.__setattr__(self, "workers", check_workers(self.workers))
        object.__setattr__(self, "chunk_size", check_count("chunk_size", self.chunk_size, 1))
        if self.progress is not None and not callable(self.progress):
            raise TypeError(f"progress={shown(self.progress)} ({type(self.progress).__name__}) is not allowed; "
                            "allowed: None or a function called with (runs done, runs in all)")

    def open(self):
        """The executor of :attr:`scheduler` (:func:`open_executor`), a context manager.

        Returns
        -------
        contextlib.AbstractContextManager of concurrent.futures.Executor
            Entered, it yields the executor; what it opened (a local cluster, a client) is closed on leaving.
        """
        return open_executor(self.scheduler, self.workers)
