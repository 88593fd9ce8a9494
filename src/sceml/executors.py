"""Where batch work runs: in this process, in a local process pool, or on a Dask cluster.

Every executor runs the same two functions over a list of items:

- `setup(payload)` once per worker (process, or Dask worker thread): it turns the payload
  (everything a worker needs, picklable, e.g. the input files as bytes) into working state;
- `task(state, item)` once per item; its return value is the item's result.

`map_unordered` yields an `Outcome` per item as items finish, in no fixed order. The items may
be `Deferred`: made by a function that the executor calls once its workers have started, so that
making them (e.g. drawing a batch's sample values) overlaps the workers' setup. An item whose
task raised, or whose worker was lost (after Dask's own retries), comes back with `error` set;
the other items carry on. Closing the iterator (e.g. on Ctrl-C in the consumer) cancels the
items not yet started. Both functions must be importable module-level functions, because the
process pool and Dask send them by name.

Dask is optional (`pip install 'sceml[dask]'`) and imported only when its executor opens.
"""

from __future__ import annotations

import gc
import importlib
import multiprocessing
import multiprocessing.util
import signal
import threading
import uuid
from abc import ABC, abstractmethod
from collections.abc import Callable, Generator, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from dataclasses import dataclass
from types import TracebackType
from typing import Any, Generic, TypeVar

from .errors import ArgumentError, SceMLError
from .processors import processors

EXECUTORS = ("local", "processes", "dask")
INSTALL_HINT = "pip install 'sceml[dask]'"

P = TypeVar("P")
S = TypeVar("S")
T = TypeVar("T")
R = TypeVar("R")

Setup = Callable[[P], S]
Task = Callable[[S, T], R]


class ExecutorUnavailable(ArgumentError):
    """An executor whose engine is not installed (exit 2, with how to install it)."""


class SchedulerError(SceMLError):
    """A Dask scheduler that cannot be reached."""


@dataclass(frozen=True)
class Deferred(Generic[T]):
    """`count` items that `make` makes once the workers have started."""

    count: int
    make: Callable[[], Sequence[T]]

    def __len__(self) -> int:
        return self.count


def _made(items: Sequence[T] | Deferred[T]) -> Sequence[T]:
    made = items.make() if isinstance(items, Deferred) else items
    if len(made) != len(items):
        raise ValueError(f"{len(made)} items were made, not the {len(items)} announced")
    return made


@dataclass(frozen=True)
class Outcome(Generic[R]):
    """What became of one item: its result, or why there is none."""

    item: int
    result: R | None = None
    error: str | None = None


class Executor(ABC):
    """Runs `task` over items on some set of workers; see the module docstring."""

    name: str = ""
    #: The largest useful chunk of work per task (samples per chunk in a batch).
    max_chunk: int = 64
    #: Whether tasks run in other processes of this machine, which see its file system: then
    #: a task may write its output files itself, in parallel, instead of returning their bytes.
    #: False in-process (the caller writes as fast) and on Dask (workers may be elsewhere).
    shares_files: bool = False
    #: Whether workers start as copies of the caller (fork): what the caller imported and
    #: compiled before `map_unordered` they have without paying for it again.
    inherits_imports: bool = False

    @property
    @abstractmethod
    def parallelism(self) -> int:
        """How many items can run at once."""

    @abstractmethod
    def map_unordered(
        self, setup: Setup[P, S], task: Task[S, T, R], payload: P, items: Sequence[T] | Deferred[T]
    ) -> Generator[Outcome[R], None, None]:
        """Each item's outcome, as items finish."""

    def close(self) -> None:  # noqa: B027  # only some executors hold workers between runs
        """Release the workers."""

    def __enter__(self) -> Executor:
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        error: BaseException | None,
        trace: TracebackType | None,
    ) -> None:
        self.close()


def require(kind: str) -> None:
    """Refuse an unknown executor, or one whose engine is not installed (ArgumentError, exit 2)."""
    if kind not in EXECUTORS:
        raise ArgumentError(f"unknown executor {kind!r}; use one of {', '.join(EXECUTORS)}")
    if kind == "dask":
        try:
            import dask  # noqa: F401
            import distributed  # noqa: F401
        except ImportError:
            raise ExecutorUnavailable(
                f"the dask executor needs dask.distributed, which is not installed: {INSTALL_HINT}"
            ) from None


def check(kind: str, scheduler: str | None = None) -> None:
    """Refuse what `open_executor` would refuse, before any work is done (ArgumentError)."""
    require(kind)
    if scheduler is not None and kind != "dask":
        raise ArgumentError("a scheduler address (--scheduler) needs the dask executor")


def open_executor(
    kind: str, *, workers: int | None = None, scheduler: str | None = None
) -> Executor:
    """An executor by name: `local`, `processes` (`workers` processes; one runs in-process) or
    `dask` (the scheduler at `scheduler`, else a LocalCluster of `workers` processes)."""
    check(kind, scheduler)
    if kind == "dask":
        return DaskExecutor(scheduler=scheduler, workers=workers)
    count = workers or processors()
    if kind == "local" or count == 1:
        return LocalExecutor()
    return ProcessExecutor(count)


def _describe(error: BaseException) -> str:
    text = str(error)
    return f"{type(error).__name__}: {text}" if text else type(error).__name__


class LocalExecutor(Executor):
    """Everything in this process, one item after the other."""

    name = "local"

    @property
    def parallelism(self) -> int:
        return 1

    def map_unordered(
        self, setup: Setup[P, S], task: Task[S, T, R], payload: P, items: Sequence[T] | Deferred[T]
    ) -> Generator[Outcome[R], None, None]:
        state = setup(payload)
        for number, item in enumerate(_made(items)):
            try:
                result = task(state, item)
            except Exception as error:  # reported per item, as the other executors do
                yield Outcome(number, error=_describe(error))
            else:
                yield Outcome(number, result)


# The state of this process's worker: (token, state), built on first use from what the pool's
# initializer left here. fork hands the payload over without pickling it.
_PROCESS: dict[str, Any] = {}


def _process_initialise(setup: Setup[Any, Any], payload: Any) -> None:
    # Ctrl-C is for the parent, which cancels; a worker hit by it would break the pool.
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    _PROCESS.clear()
    _PROCESS.update(setup=setup, payload=payload)
    # A pool worker ends without running atexit; this lets the state go (and clean up) first.
    multiprocessing.util.Finalize(None, _PROCESS.clear, exitpriority=10)


def _process_call(task: Task[Any, T, R], item: T) -> R:
    if "state" not in _PROCESS:
        _PROCESS["state"] = _PROCESS["setup"](_PROCESS["payload"])
    return task(_PROCESS["state"], item)


def _ready(state: Any, item: None) -> None:
    """A task that does nothing: calling it sets a worker up."""


class ProcessExecutor(Executor):
    """A pool of worker processes on this machine (fork where the platform has it)."""

    name = "processes"
    shares_files = True

    def __init__(self, workers: int) -> None:
        self.workers = workers
        self.inherits_imports = self._start_method() == "fork"

    @staticmethod
    def _start_method() -> str:
        # fork shares the parent's imported modules, so a worker starts in milliseconds.
        return "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"

    @property
    def parallelism(self) -> int:
        return self.workers

    def map_unordered(
        self, setup: Setup[P, S], task: Task[S, T, R], payload: P, items: Sequence[T] | Deferred[T]
    ) -> Generator[Outcome[R], None, None]:
        method = self._start_method()
        processes = min(self.workers, len(items) or 1)
        frozen = method == "fork" and not gc.get_freeze_count()
        if frozen:
            # Each worker is a copy of this process. Its collector's first full pass would walk
            # every object it inherited, writing to each, so the system copies the whole heap
            # page by page: 0.1-0.5 s per worker, before its first file. Frozen objects are not
            # walked (Python's gc docs: freeze right before fork).
            gc.freeze()
        pool = ProcessPoolExecutor(
            max_workers=processes,
            mp_context=multiprocessing.get_context(method),
            initializer=_process_initialise,
            initargs=(setup, payload),
        )
        try:
            if isinstance(items, Deferred):
                # One call per process starts them all and their setup (an error there comes
                # back with each item, as setup runs again for it); meanwhile the items are made.
                for _ in range(min(processes, len(items))):
                    pool.submit(_process_call, _ready, None)
            futures: dict[Future[R], int] = {
                pool.submit(_process_call, task, item): number
                for number, item in enumerate(_made(items))
            }
            pending = set(futures)
            while pending:
                done, pending = wait(pending, return_when=FIRST_COMPLETED)
                for future in done:
                    yield _outcome_of(futures[future], future)
        finally:
            # A lost worker breaks the pool: every unfinished item then reports that error.
            pool.shutdown(wait=True, cancel_futures=True)
            if frozen:
                gc.unfreeze()  # this process's own objects are collectable again


def _outcome_of(number: int, future: Future[R]) -> Outcome[R]:
    error = future.exception()
    if error is not None:
        return Outcome(number, error=_describe(error))
    return Outcome(number, future.result())


def _distributed() -> Any:
    """The dask.distributed module (untyped; require() has checked that it is installed)."""
    return importlib.import_module("distributed")


def _local_cluster(distributed: Any, workers: int) -> Any:
    """A LocalCluster of single-threaded worker processes that leave Ctrl-C to this process.

    A terminal sends Ctrl-C to every process in its foreground group; the workers would each
    print a traceback while this process cancels their tasks and closes them in order. They
    inherit an ignored SIGINT from the moment they are started.
    """
    in_main = threading.current_thread() is threading.main_thread()
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN) if in_main else None
    try:
        # The scheduler's HTTP server (dashboard, metrics) on a free port: the default 8787 may be
        # taken by another cluster, which distributed only warns about.
        return distributed.LocalCluster(
            n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=":0"
        )
    finally:
        if in_main:
            signal.signal(signal.SIGINT, previous)


# Per Dask worker thread: (token, state) of the run in progress. A worker thread serves one
# run's tasks with one state; a new run (new token) replaces it. Kept in a module dict, not
# thread-local storage, so that the process can let every state go (and clean up) as it ends.
_DASK: dict[int, tuple[str, Any]] = {}


def _dask_call(
    setup: Setup[Any, Any], task: Task[Any, T, R], payload: Any, token: str, item: T
) -> R:
    thread = threading.get_ident()
    held = _DASK.get(thread)
    if held is None or held[0] != token:
        if not _DASK:
            # A worker process ends without running atexit; this runs at its end all the same.
            multiprocessing.util.Finalize(None, _DASK.clear, exitpriority=10)
        _DASK.pop(thread, None)  # let the previous run's state go before building the next
        held = _DASK[thread] = (token, setup(payload))
    return task(held[1], item)


class DaskExecutor(Executor):
    """A `dask.distributed` cluster: a running scheduler, or a LocalCluster started here."""

    name = "dask"
    # A task costs the scheduler about a millisecond; bigger chunks keep that small.
    max_chunk = 256

    def __init__(self, *, scheduler: str | None = None, workers: int | None = None) -> None:
        distributed = _distributed()
        self.cluster: Any = None
        try:
            if scheduler is None:
                self.cluster = _local_cluster(distributed, workers or processors())
                self.client: Any = distributed.Client(self.cluster)
            else:
                self.client = distributed.Client(scheduler, timeout="10s")
        except OSError as error:
            self.close()
            where = scheduler or "a local cluster"
            raise SchedulerError(f"cannot reach the Dask scheduler at {where}: {error}") from None

    @property
    def parallelism(self) -> int:
        threads: dict[str, int] = self.client.nthreads()
        return max(1, sum(threads.values()))

    def map_unordered(
        self, setup: Setup[P, S], task: Task[S, T, R], payload: P, items: Sequence[T] | Deferred[T]
    ) -> Generator[Outcome[R], None, None]:
        as_completed = _distributed().as_completed
        token = uuid.uuid4().hex
        # Sent once to every worker; tasks refer to it instead of carrying it.
        shared = self.client.scatter(payload, broadcast=True, hash=False)
        futures = {
            self.client.submit(
                _dask_call, setup, task, shared, token, item, key=f"sceml-{token}-{number}"
            ): number
            for number, item in enumerate(_made(items))
        }
        try:
            for future, result in as_completed(futures, with_results=True, raise_errors=False):
                number = futures[future]
                if future.status == "error":  # `result` is then (type, error, traceback)
                    yield Outcome(number, error=_describe(future.exception()))
                elif future.status == "cancelled":
                    yield Outcome(number, error=_describe(result))
                else:
                    yield Outcome(number, result)
        finally:
            self.client.cancel(list(futures))
            self.client.cancel([shared])

    def close(self) -> None:
        client = getattr(self, "client", None)
        if client is not None:
            client.close()
        if self.cluster is not None:
            self.cluster.close()
