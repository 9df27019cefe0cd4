# SPDX-License-Identifier: EPL-2.0
"""What REI's two pages' servers share (the live view's and the room editor's): an HTTP server on a thread of its
own, bound to loopback, that serves the built page from ``static/`` and never a path outside it."""

from __future__ import annotations

import mimetypes
import threading
from http import HTTPStatus
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from types import TracebackType
from typing import Self


class LoopbackServer:
    """Started once, stopped once (or used as a context manager); ``error`` is the type raised when it cannot."""

    error: type[RuntimeError] = RuntimeError
    thread_name = "rei-http"

    def __init__(self, host: str, port: int) -> None:
        self._host = host
        self._port = port
        self._server: ThreadingHTTPServer | None = None
        self._thread: threading.Thread | None = None

    @property
    def address(self) -> tuple[str, int]:
        if self._server is None:
            raise self.error(f"{type(self).__name__} not started")
        host, port = self._server.server_address[:2]
        return str(host), int(port)

    def start(self) -> Self:
        if self._server is not None:
            raise self.error(f"{type(self).__name__} already started")
        try:
            self._server = ThreadingHTTPServer((self._host, self._port), self._handler_class())
        except OSError as error:
            raise self.error(f"cannot serve on {self._host}:{self._port}: {error}") from error
        self._server.daemon_threads = True
        self._thread = threading.Thread(target=self._server.serve_forever, kwargs={"poll_interval": 0.2},
                                        name=self.thread_name, daemon=True)
        self._thread.start()
        return self

    def stop(self) -> None:
        server, self._server = self._server, None
        if server is None:
            return
        server.shutdown()
        server.server_close()
        if self._thread is not None:
            self._thread.join(timeout=5)

    def __enter__(self) -> Self:
        return self.start()

    def __exit__(self, exc_type: type[BaseException] | None, exc: BaseException | None,
                 tb: TracebackType | None) -> None:
        self.stop()

    def _handler_class(self) -> type[BaseHTTPRequestHandler]:
        raise NotImplementedError


def static_file(root: Path, path: str, index: str | None = None) -> Path | None:
    """The file under ``root`` (resolved) that the URL path names (``index`` for ``/``), None for anything else."""
    relative = path.lstrip("/") or (index or "")
    candidate = (root / relative).resolve()
    if not relative or not candidate.is_relative_to(root) or not candidate.is_file():
        return None
    return candidate


def content_type(file: Path) -> str:
    kind = mimetypes.guess_type(file.name)[0] or "application/octet-stream"
    return kind + "; charset=utf-8" if kind.startswith("text/") or kind.endswith("javascript") else kind


def send(handler: BaseHTTPRequestHandler, status: HTTPStatus, kind: str, body: bytes,
         headers: dict[str, str] | None = None) -> None:
    """One whole answer, never cached: every page and answer belongs to one run or one editing session."""
    handler.send_response(status)
    handler.send_header("Content-Type", kind)
    handler.send_header("Content-Length", str(len(body)))
    handler.send_header("Cache-Control", "no-store")
    for name, value in (headers or {}).items():
        handler.send_header(name, value)
    handler.end_headers()
    if body:
        handler.wfile.write(body)
