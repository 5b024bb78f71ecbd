"""Signals: the one rule for SIGINT, SIGTERM and SIGHUP, in the command's process and in its workers.

- The command's process (:func:`signals_interrupt`, installed by :func:`edsconv.cli.main`) turns
  each into :class:`Interrupted`, a BaseException, so that no handler of ``Exception`` stops it and
  every ``finally`` block runs (temporary files are removed); the command exits with 128 + the
  signal's number (130, 143, 129).
- While a set of files is renamed into place the signals are held back (:func:`signals_held`), so
  that a set is written whole or not at all (:mod:`edsconv.atomic`).
- A worker process (:mod:`edsconv.parallel`) ignores SIGINT and SIGHUP: a Ctrl-C reaches the whole
  process group, and the command decides. The command ends its workers with SIGTERM
  (:func:`edsconv.parallel.run_all`, within a second); a worker then unwinds the task it runs (its
  temporary files are removed) and exits (:func:`in_worker`).
"""

from __future__ import annotations

import os
import signal
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TypeVar

Result = TypeVar("Result")

#: The signals that end a command (and that are held back while a set of files is renamed into place).
HELD_SIGNALS = tuple(getattr(signal, name) for name in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, name))
#: In a worker process: whether a task is running (a SIGTERM then unwinds it, so that it cleans up).
_busy = False


class Interrupted(BaseException):
    """A signal (SIGINT, SIGTERM, SIGHUP) ends the command: a BaseException, so that no handler of
    ``Exception`` stops it and every ``finally`` block runs."""

    def __init__(self, signal_number: int) -> None:
        super().__init__(signal_number)
        self.signal_number = signal_number


@contextmanager
def signals_interrupt() -> Iterator[None]:
    """SIGINT, SIGTERM and SIGHUP raise :class:`Interrupted` inside, so that ``finally`` blocks clean up."""

    def interrupt(signal_number: int, frame: object) -> None:
        raise Interrupted(signal_number)

    previous = {number: signal.signal(number, interrupt) for number in HELD_SIGNALS}
    try:
        yield
    finally:
        for number, handler in previous.items():
            signal.signal(number, handler)


@contextmanager
def signals_held() -> Iterator[None]:
    """Hold :data:`HELD_SIGNALS` back inside the block; they are delivered when it ends.

    Only the main thread can do so (and only on platforms with ``pthread_sigmask``);
    elsewhere the block runs unprotected.
    """
    if not hasattr(signal, "pthread_sigmask") or threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.pthread_sigmask(signal.SIG_BLOCK, HELD_SIGNALS)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)


def worker_signals() -> None:
    """A worker process's start: SIGINT and SIGHUP are the command's to decide; SIGTERM ends the worker."""
    for number in HELD_SIGNALS:
        signal.signal(number, _terminated if number == signal.SIGTERM else signal.SIG_IGN)


def _terminated(signal_number: int, frame: object) -> None:
    if _busy:
        raise Interrupted(signal_number)  # unwinds the task: its temporary files are removed
    os._exit(128 + signal_number)


def in_worker(function: Callable[..., Result], arguments: tuple) -> Result:
    """``function(*arguments)`` in a worker process; after a SIGTERM the worker exits, without a traceback."""
    global _busy
    _busy = True
    try:
        return function(*arguments)
    except Interrupted as stop:
        os._exit(128 + stop.signal_number)
    finally:
        _busy = False
