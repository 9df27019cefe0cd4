# SPDX-License-Identifier: EPL-2.0
"""The edit engine: the Java process that holds a test case as an Xtext model (``rei-room-editor.jar``).

It answers one JSON line per request line (docs/room-editor.md, "HTTP server ⇄ edit engine"). Everything here
runs on one long-lived thread of its own: the engine is started with ``die_with_parent``, whose signal follows
the thread that started it, and the HTTP server's request threads come and go. One thread also keeps requests in
order without a lock around a pipe. An engine that hangs is killed after ``timeout`` seconds and one that dies is
started again with the last text it held, so neither hangs nor ends the editor.
"""

from __future__ import annotations

import contextlib
import json
import queue
import subprocess
import threading
from collections import deque
from collections.abc import Callable, Sequence
from concurrent.futures import Future
from pathlib import Path
from typing import Any

from rei.lifetime import die_with_parent

#: Seconds one request may take. A move in a 10,000-floor room answers in about a second on two cores.
REQUEST_TIMEOUT = 120.0
_STDERR_LINES = 40


#: The ``kind`` of an ``ok: false`` answer (org.rei.dsl.edit.server.Protocol, contract/vocabulary.json): the
#: request's fault, or the engine's own.
REFUSED, INTERNAL = "refused", "internal"


class EngineError(RuntimeError):
    """The engine refused a request (``refused``) or broke (it died, hung, or said something unreadable)."""

    def __init__(self, message: str, *, refused: bool = False, ended: bool = False) -> None:
        super().__init__(message)
        self.refused = refused
        self.ended = ended  # the engine was gone before it could answer: the request may be tried again


class EngineFailure(EngineError):
    """The engine answered that it failed inside (an exception in it, such as its jar replaced under it): nothing
    was changed, and nothing is known about the request; asking again may fail the same way."""


class EditEngine:
    """Runs ``command`` (``java -jar rei-room-editor.jar``) and talks to it from one thread of its own."""

    def __init__(self, command: Sequence[str], *, timeout: float = REQUEST_TIMEOUT) -> None:
        self._command = list(command)
        self._timeout = timeout
        self._restarted = False  # since the last take_restart()
        self._jobs: queue.Queue[tuple[dict[str, Any], Future[dict[str, Any]]] | None] = queue.Queue()
        self._process: subprocess.Popen[str] | None = None
        self._answers: queue.Queue[str | None] = queue.Queue()
        self._stderr: deque[str] = deque(maxlen=_STDERR_LINES)
        self._next_id = 0
        self._opened: str | None = None  # the path of the last successful open
        self._text: str | None = None  # the last text the engine answered with: restored after a crash
        self._thread = threading.Thread(target=self._serve, name="rei-edit-engine", daemon=True)
        self._thread.start()

    def request(self, command: str, **fields: Any) -> dict[str, Any]:
        """The engine's answer to ``command``; ``EngineError`` when it refused it or broke."""
        future: Future[dict[str, Any]] = Future()
        self._jobs.put(({"command": command, **fields}, future))
        return future.result()

    def take_restart(self) -> bool:
        """Whether the engine had to be started again (it died) since the last call: its undo history is gone."""
        restarted, self._restarted = self._restarted, False
        return restarted

    @property
    def pid(self) -> int | None:
        """The engine's process id, None before the first request."""
        process = self._process
        return None if process is None else process.pid

    @property
    def alive(self) -> bool:
        process = self._process
        return process is not None and process.poll() is None

    def close(self) -> None:
        """Closes the engine's stdin (it exits then) and waits for it; kills it after a few seconds."""
        self._jobs.put(None)
        self._thread.join(timeout=15)

    # -- the engine's own thread -------------------------------------------------------------------------------

    def _serve(self) -> None:
        try:
            while (job := self._jobs.get()) is not None:
                message, future = job
                try:
                    future.set_result(self._call(message))
                except EngineError as error:
                    future.set_exception(error)
                except Exception as error:  # noqa: BLE001 - a bug here must reach the caller, not end the thread
                    future.set_exception(EngineError(f"edit engine: {error}"))
        finally:
            self._stop()

    def _call(self, message: dict[str, Any]) -> dict[str, Any]:
        restarted = False
        if self._process is None or self._process.poll() is not None:
            restarted = self._process is not None
            self._start()
        try:
            answer = self._exchange(message)
        except EngineError as error:
            if not error.ended or restarted or message["command"] == "open":
                raise
            # One more try with a new engine: the old one may have died after its last answer.
            self._start()
            answer = self._exchange(message)
            restarted = True
        if restarted:
            self._restarted = True
        return answer

    def _start(self) -> None:
        """(Re)starts the engine; after a crash it opens the same file and is given back the last text."""
        crashed = self._process is not None
        self._stop()
        self._answers = queue.Queue()
        try:
            process = subprocess.Popen(die_with_parent(self._command), stdin=subprocess.PIPE,
                                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                       encoding="utf-8", bufsize=1, start_new_session=True)
        except OSError as error:
            raise EngineError(f"cannot start the edit engine ({self._command[0]}): {error}") from error
        self._process = process
        answers = self._answers
        threading.Thread(target=_pump, args=(process.stdout, answers.put), name="rei-edit-engine-out",
                         daemon=True).start()
        threading.Thread(target=_pump, args=(process.stderr, self._log), name="rei-edit-engine-err",
                         daemon=True).start()
        if crashed and self._opened is not None:
            text = self._text  # the open below answers with the file's text
            self._exchange({"command": "open", "path": self._opened})
            if text is not None:
                self._exchange({"command": "reset", "text": text})

    def _exchange(self, message: dict[str, Any]) -> dict[str, Any]:
        process = self._process
        assert process is not None and process.stdin is not None
        self._next_id += 1
        ident = self._next_id
        line = json.dumps({"id": ident, **message}, ensure_ascii=False, allow_nan=False)
        try:
            process.stdin.write(line + "\n")
            process.stdin.flush()
        except OSError:
            raise self._broken("the edit engine stopped reading", ended=True) from None
        try:
            raw = self._answers.get(timeout=self._timeout)
        except queue.Empty:
            self._kill()
            raise self._broken(f"the edit engine did not answer {message['command']!r} within "
                               f"{self._timeout:.0f} s and was stopped") from None
        if raw is None:
            raise self._broken("the edit engine ended", ended=True)
        try:
            answer = json.loads(raw)
        except json.JSONDecodeError:
            self._kill()
            raise self._broken(f"the edit engine answered something that is not JSON: {raw[:200]!r}") from None
        if not isinstance(answer, dict) or answer.get("id") != ident:
            self._kill()
            raise self._broken(f"the edit engine answered out of turn: {raw[:200]!r}")
        if not answer.get("ok"):
            reason = str(answer.get("error") or "refused without a reason")
            if answer.get("kind") == INTERNAL:
                raise EngineFailure(reason)
            raise EngineError(reason, refused=True)
        if message["command"] == "open":
            self._opened = message["path"]
        if isinstance(answer.get("text"), str):
            self._text = answer["text"]
        return answer

    def _log(self, line: str | None) -> None:
        if line is not None:
            self._stderr.append(line)

    def _broken(self, what: str, *, ended: bool = False) -> EngineError:
        tail = "\n".join(self._stderr)
        return EngineError(f"{what}" + (f"; its last output:\n{tail}" if tail else ""), ended=ended)

    def _kill(self) -> None:
        if self._process is not None:
            with contextlib.suppress(OSError):
                self._process.kill()
            self._process.wait()

    def _stop(self) -> None:
        process, self._process = self._process, None
        if process is None:
            return
        with contextlib.suppress(OSError):
            if process.stdin is not None:
                process.stdin.close()
        try:
            process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()


def _pump(stream: Any, put: Callable[[Any], None]) -> None:
    """Hands each line of ``stream`` to ``put`` without its line break, then None at the end."""
    with contextlib.suppress(ValueError, OSError):
        for line in stream:
            put(line.rstrip("\n"))
    put(None)


def engine_command(jar: Path, java: Path) -> list[str]:
    """The engine's argument vector."""
    return [str(java), "-jar", str(jar)]
