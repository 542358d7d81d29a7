"""The runner's engine: Dask distributed, on a local cluster or an existing one.

:func:`cluster` yields a :class:`distributed.Client`: by default on a ``LocalCluster`` with one
single-threaded worker process per job, or on the scheduler at ``--scheduler ADDRESS`` (a
``dask scheduler`` with ``dask worker`` processes anywhere, or dask-jobqueue on a batch system).
Every unit of work (a chapter's notebook, a sweep's point) is one task: a function of its inputs
that returns its results; only the client writes the output folder.

Guarantees kept from the process pool it replaces:

* leaving the ``with`` block (success, a failed chapter, Ctrl-C, SIGTERM) stops every task: the
  local cluster's workers are closed and each kills its kernels on the way out
  (:class:`KillKernels`); on an existing cluster the kernels this run started are killed;
* a worker that dies mid-task is survived: the scheduler runs the task again on another worker,
  and the runner says so (each task announces its start; a second start of one key is a re-run).
"""

from __future__ import annotations

import contextlib
import logging
import threading
import time
from collections.abc import Callable, Iterator

try:
    from distributed.diagnostics.plugin import WorkerPlugin
except ModuleNotFoundError:  # pragma: no cover - the pinned environment has it; cluster() says what to install
    WorkerPlugin = object

#: Topic of the events a task logs when it starts (read by the client to report re-runs).
TOPIC = "vibration-task"
#: Seconds the client waits for a scheduler named by --scheduler.
CONNECT_TIMEOUT_S = 20


class MissingEngine(RuntimeError):
    """Dask distributed is not installed (the optional extra ``scale``)."""


def _require():
    try:
        import distributed
    except ModuleNotFoundError:  # pragma: no cover - the pinned environment has it
        raise MissingEngine(
            "the runner needs Dask distributed: pip install 'vibration[scale]' (or make setup)"
        ) from None
    return distributed


def kill_kernels() -> int:
    """Kill the Jupyter kernels (and what they started) below this process; returns how many were killed."""
    import psutil

    me = psutil.Process()
    victims = []
    for child in me.children(recursive=True):
        try:
            if "ipykernel" in " ".join(child.cmdline()):
                victims += [child, *child.children(recursive=True)]
        except (psutil.NoSuchProcess, psutil.AccessDenied):
            continue
    for proc in victims:
        try:
            proc.kill()
        except psutil.NoSuchProcess:
            pass
    psutil.wait_procs(victims, timeout=5)
    return len(victims)


class KillKernels(WorkerPlugin):
    """Worker plugin: when its worker closes (the cluster shuts down, SIGTERM), the kernels it runs die too.

    Jupyter starts each kernel in a session of its own, where a closed worker would leave it computing.
    """

    name = "vibration-kill-kernels"

    def setup(self, worker) -> None:
        pass

    def teardown(self, worker) -> None:
        kill_kernels()


def announce(label: str) -> None:
    """Log the start of the running task, shown as ``label``, to the scheduler (no-op outside a worker).

    Starts are counted by the task's own key, unique per submission: the same point or chapter submitted again
    (a second sweep on the same client) is not a re-run.
    """
    try:
        from distributed import get_worker

        worker = get_worker()
    except (ImportError, ValueError):
        return
    try:
        key = str(worker.get_current_task())
    except Exception:  # outside a task (never in this project's tasks): the label stands for the key
        key = label
    worker.log_event(TOPIC, {"key": key, "label": label, "worker": worker.address})


class Restarts:
    """The client's record of task starts: a key that starts twice was re-run after its worker was lost."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._starts: dict[str, int] = {}
        self._labels: dict[str, int] = {}
        self._pending: list[str] = []

    def __call__(self, event) -> None:
        _, msg = event
        key, worker = msg.get("key", "?"), msg.get("worker", "?")
        label = msg.get("label", key)
        with self._lock:
            n = self._starts.get(key, 0) + 1
            self._starts[key] = n
            self._labels[label] = self._labels.get(label, 0) + 1
            if n > 1:
                self._pending.append(
                    f"[rerun] {label}: the worker running it was lost; running it again on {worker} (attempt {n})"
                )

    def drain(self) -> list[str]:
        """Messages about re-runs since the last call."""
        with self._lock:
            out, self._pending = self._pending, []
        return out

    def count(self, label: str) -> int:
        """How many times the task shown as ``label`` started (over every submission of it)."""
        with self._lock:
            return self._labels.get(label, 0)


@contextlib.contextmanager
def cluster(jobs: int = 2, scheduler: str | None = None, log: Callable[[str], None] = print) -> Iterator:
    """A Dask client on a local cluster of ``jobs`` single-threaded worker processes, or on ``scheduler``.

    The client carries ``client.restarts`` (a :class:`Restarts`); leaving the block closes what it opened.
    """
    distributed = _require()
    for name in ("distributed", "tornado", "asyncio"):
        logging.getLogger(name).setLevel(logging.CRITICAL)
    import dask

    local = None
    with dask.config.set(
        {
            "distributed.scheduler.allowed-failures": 3,  # a task whose workers die 4 times fails for good
            "distributed.worker.daemon": False,  # a worker may start processes (the kernels)
            "distributed.admin.tick.limit": "1h",
            "distributed.worker.memory.terminate": False,
            "distributed.logging.distributed": "critical",
        }
    ):
        if scheduler:
            client = distributed.Client(scheduler, timeout=CONNECT_TIMEOUT_S)
        else:
            local = distributed.LocalCluster(
                n_workers=max(1, jobs),
                threads_per_worker=1,
                processes=True,
                dashboard_address=None,
                # no dashboard; the scheduler's small HTTP server on a free port, not 8787 (another run may hold it)
                scheduler_kwargs={"dashboard_address": "127.0.0.1:0"},
                silence_logs=logging.CRITICAL,
                host="127.0.0.1",
            )
            client = distributed.Client(local)
        restarts = Restarts()
        client.restarts = restarts
        try:
            client.register_plugin(KillKernels(), name=KillKernels.name)
            client.subscribe_topic(TOPIC, restarts)
            yield client
        finally:
            t0 = time.perf_counter()
            if local is None:  # an existing cluster stays up: stop this run's work and kernels only
                with contextlib.suppress(Exception):
                    client.cancel(list(client.futures.values()), force=True)
                with contextlib.suppress(Exception):
                    client.run(kill_kernels, wait=True)
            with contextlib.suppress(Exception):
                client.close(timeout=10)
            if local is not None:
                with contextlib.suppress(Exception):
                    local.close(timeout=10)
            elapsed = time.perf_counter() - t0
            if elapsed > 5:
                log(f"engine: the cluster took {elapsed:.1f} s to stop")
