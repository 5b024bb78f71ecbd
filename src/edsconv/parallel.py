"""Running one function over many files: in worker processes when there are enough, with a progress
bar on a terminal, and stopped within a second by SIGINT, SIGTERM or SIGHUP.

``edsconv lint`` and ``edsconv fmt`` call :func:`run_all`. With :mod:`edsconv.signals`, it keeps
the signal rule for workers: while the command waits for its workers it looks at least every
:data:`POLL_SECONDS` (so a signal delivered to another thread is seen); on
:class:`~edsconv.signals.Interrupted` it cancels the files not started, ends every worker (SIGTERM,
then SIGKILL after :data:`GRACE_SECONDS`) and lets the signal go on: the command exits with 128 +
its number within a second.

Heavy imports (concurrent.futures, rich) happen inside the functions that need them.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Collection, Iterable, Iterator, Sequence
from typing import Any, TypeVar

from edsconv.signals import in_worker, worker_signals

Result = TypeVar("Result")

#: Below this many tasks the work stays in this process: starting workers costs more than it saves.
PARALLEL_THRESHOLD = 8
#: From this many tasks on, a progress bar is shown (on a terminal only).
PROGRESS_THRESHOLD = 20
#: The longest the command waits for a worker without looking for a signal.
POLL_SECONDS = 0.2
#: How long an ended worker may take to clean up before it is killed.
GRACE_SECONDS = 0.5


def run_all(function: Callable[..., Result], tasks: Sequence[tuple], jobs: int, label: str, *,
            died: Callable[[tuple, str], Result], sizes: Sequence[int] | None = None) -> list[Result]:
    """``function(*task)`` for every task, in task order.

    In ``jobs`` worker processes when there are more than :data:`PARALLEL_THRESHOLD` tasks, biggest
    (``sizes``) first; ``died(task, message)`` stands for the result of a task whose worker died.
    """
    if jobs <= 1 or len(tasks) <= PARALLEL_THRESHOLD:
        return [function(*task) for task in progress(tasks, len(tasks), label)]
    return _in_workers(function, tasks, jobs, label, died, sizes)


def _in_workers(function: Callable[..., Result], tasks: Sequence[tuple], jobs: int, label: str,
                died: Callable[[tuple, str], Result], sizes: Sequence[int] | None) -> list[Result]:
    from concurrent.futures import ProcessPoolExecutor
    from concurrent.futures.process import BrokenProcessPool

    results: list[Any] = [None] * len(tasks)
    done = [False] * len(tasks)
    # Largest first, one file a task: sizes differ a hundredfold, and the last big file must not start alone.
    order = sorted(range(len(tasks)), key=lambda i: -(sizes[i] if sizes else 0))
    pool = ProcessPoolExecutor(max_workers=min(jobs, len(tasks)), initializer=worker_signals)
    try:
        futures = {pool.submit(in_worker, function, tasks[i]): i for i in order}
        for future in progress(_completed(futures), len(tasks), label):
            results[futures[future]], done[futures[future]] = future.result(), True
    except BrokenProcessPool as error:
        # A worker died (killed, out of memory): every task not answered for is reported, the rest kept.
        message = f"the worker process checking this file died ({error}); please report it"
        results = [result if finished else died(task, message)
                   for task, result, finished in zip(tasks, results, done, strict=True)]
    except BaseException:  # a signal (Interrupted), or an error of this process: end the workers now
        _end_workers(pool)
        raise
    pool.shutdown(wait=True)
    return results


def _completed(futures: Collection) -> Iterator:
    """The futures as they complete, waking every :data:`POLL_SECONDS` so that a signal handler runs
    (``as_completed`` waits without a timeout; ``wait`` in a loop costs the number of futures each time)."""
    import queue

    finished: queue.SimpleQueue = queue.SimpleQueue()
    for future in futures:
        future.add_done_callback(finished.put)
    for _ in range(len(futures)):
        while True:
            try:
                yield finished.get(timeout=POLL_SECONDS)
                break
            except queue.Empty:
                continue


def _end_workers(pool: Any) -> None:
    """Cancel what has not started and end every worker: SIGTERM, then SIGKILL for one that lingers."""
    # the executor has no public way to do this before Python 3.14
    processes, manager = list((pool._processes or {}).values()), pool._executor_manager_thread
    pool.shutdown(wait=False, cancel_futures=True)
    for process in processes:
        if process.is_alive():
            process.terminate()
    for process in processes:
        process.join(GRACE_SECONDS)
        if process.is_alive():
            process.kill()
            process.join(GRACE_SECONDS)
    if manager is not None:  # it closes its wake-up pipe as it ends; at exit, Python would write to it
        manager.join(GRACE_SECONDS)


def file_size(path: str) -> int:
    """The size of a file, for :func:`run_all`'s ``sizes`` (0 when it cannot be read: it fails fast)."""
    try:
        return os.stat(path).st_size
    except OSError:
        return 0


def progress(items: Iterable, total: int, label: str) -> Iterator:
    """``items``, with a progress bar on stderr when it is a terminal and there are many."""
    if total < PROGRESS_THRESHOLD or not sys.stderr.isatty():
        yield from items
        return
    from rich.console import Console
    from rich.progress import Progress

    with Progress(console=Console(stderr=True), transient=True) as progress_bar:
        task = progress_bar.add_task(label, total=total)
        for item in items:
            yield item
            progress_bar.advance(task)
