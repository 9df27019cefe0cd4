# SPDX-License-Identifier: EPL-2.0
"""The room editor's HTTP server: the built page and the ``/api/`` of one editing session, on loopback only.

The page may change a file on the user's disk, so every ``/api/`` request must carry the session's token (the
page has it from its URL) and come from the editor's own origin: another page open in the same browser (or one
that rebinds a name to 127.0.0.1) can neither read nor write through it. Static files carry no secret and are
served to anyone on loopback, as the live view's are.
"""

from __future__ import annotations

import hmac
import json
import secrets
from collections.abc import Mapping
from http import HTTPStatus
from http.server import BaseHTTPRequestHandler
from pathlib import Path
from typing import Any
from urllib.parse import urlsplit

from rei.edit.engine import INTERNAL, EngineError, EngineFailure
from rei.edit.session import EditSession, SessionConflict
from rei.view import STATIC_DIR
from rei.view.loopback import LoopbackServer, content_type, send, static_file

PAGE = "edit.html"
TOKEN_HEADER = "X-REI-Token"
#: The page's requests (docs/room-editor.md) and the ``EditSession`` method that answers each.
ROUTES: Mapping[tuple[str, str], str] = {
    ("GET", "/api/state"): "state", ("GET", "/api/status"): "status", ("POST", "/api/apply"): "apply",
    ("POST", "/api/undo"): "undo", ("POST", "/api/redo"): "redo", ("POST", "/api/save"): "save",
    ("POST", "/api/reload"): "reload", ("POST", "/api/keep"): "keep",
}
#: How the page is told that the engine failed inside: the edit may well be fine.
INTERNAL_FAILURE = "Internal failure of the room editor, not a fault of your edit (nothing was changed)"
#: A room's text is small; a bigger body is a mistake or an attack.
MAX_BODY = 4 * 1024 * 1024


class EditServerError(RuntimeError):
    """The page is not built or the server cannot start."""


class EditServer(LoopbackServer):
    """Serves one ``EditSession`` on ``http://127.0.0.1:<port>/edit.html?token=...`` (a free port unless given)."""

    error = EditServerError
    thread_name = "rei-edit-http"

    def __init__(self, session: EditSession, *, host: str = "127.0.0.1", port: int = 0,
                 static_dir: Path = STATIC_DIR, token: str | None = None) -> None:
        if not (static_dir / PAGE).is_file():
            raise EditServerError(f"the room editor's page is not built ({static_dir / PAGE} is missing): "
                                  "run `npm ci && npm run build` in viewer/")
        super().__init__(host, port)
        self.session = session
        self.token = token or secrets.token_urlsafe(24)
        self._static = static_dir.resolve()

    @property
    def port(self) -> int:
        return self.address[1]

    @property
    def url(self) -> str:
        host, port = self.address
        return f"http://{host}:{port}/{PAGE}?token={self.token}"

    # -- requests -----------------------------------------------------------------------------------------------

    def _answer(self, name: str, body: dict[str, Any]) -> dict[str, Any]:
        if name == "apply":
            operations = body.get("operations")
            if not isinstance(operations, list) or not operations:
                raise _BadRequest('expected {"operations": [ ... ]} with at least one operation')
            return self.session.apply(operations)
        answer: dict[str, Any] = getattr(self.session, name)()
        return answer

    def _allowed(self, headers: Any) -> str | None:
        """Why a request to ``/api/`` is refused, or None."""
        port = self.port
        host = headers.get("Host", "")
        if host not in (f"127.0.0.1:{port}", f"localhost:{port}", f"[::1]:{port}"):
            return f"refused: Host {host!r} is not this editor"
        origin = headers.get("Origin")
        if origin is not None and origin not in (f"http://127.0.0.1:{port}", f"http://localhost:{port}"):
            return f"refused: origin {origin!r} is not this editor"
        if not hmac.compare_digest(headers.get(TOKEN_HEADER, "").encode(), self.token.encode()):
            return f"refused: missing or wrong {TOKEN_HEADER} (open the address rei edit printed)"
        return None

    def _handler_class(self) -> type[BaseHTTPRequestHandler]:
        editor = self

        class Handler(BaseHTTPRequestHandler):
            server_version = "rei-edit"

            def do_GET(self) -> None:
                path = urlsplit(self.path).path
                if path.startswith("/api/"):
                    self._api("GET", path)
                    return
                if path == "/":
                    send(self, HTTPStatus.FOUND, "text/plain", b"", {"Location": f"/{PAGE}"})
                    return
                file = static_file(editor._static, path)
                if file is None:
                    self._send(HTTPStatus.NOT_FOUND, {"error": "not found"})
                    return
                self._raw(HTTPStatus.OK, content_type(file), file.read_bytes())

            def do_POST(self) -> None:
                self._api("POST", urlsplit(self.path).path)

            def _api(self, method: str, path: str) -> None:
                refusal = editor._allowed(self.headers)
                if refusal is not None:
                    self._send(HTTPStatus.FORBIDDEN, {"error": refusal})
                    return
                route = ROUTES.get((method, path))
                if route is None:
                    self._send(HTTPStatus.NOT_FOUND, {"error": f"no {method} {path}"})
                    return
                try:
                    body = self._body() if method == "POST" else {}
                    self._send(HTTPStatus.OK, editor._answer(route, body))
                except _BadRequest as error:
                    self._send(error.status, {"error": str(error)})
                except SessionConflict as error:
                    self._send(HTTPStatus.CONFLICT, {"error": str(error)})
                except EngineFailure as error:
                    # the engine's own failure, not the edit's: the page's message says so (nothing was changed)
                    self._send(HTTPStatus.INTERNAL_SERVER_ERROR,
                               {"error": f"{INTERNAL_FAILURE}: {error}", "kind": INTERNAL})
                except EngineError as error:
                    status = HTTPStatus.UNPROCESSABLE_ENTITY if error.refused else HTTPStatus.INTERNAL_SERVER_ERROR
                    self._send(status, {"error": str(error)})
                except OSError as error:  # the save could not be written
                    self._send(HTTPStatus.INTERNAL_SERVER_ERROR, {"error": f"cannot write the file: {error}"})

            def _body(self) -> dict[str, Any]:
                try:
                    length = int(self.headers.get("Content-Length", "0"))
                except ValueError:
                    raise _BadRequest("bad Content-Length") from None
                if length > MAX_BODY:
                    raise _BadRequest(f"body over {MAX_BODY} bytes", HTTPStatus.REQUEST_ENTITY_TOO_LARGE)
                raw = self.rfile.read(length) if length > 0 else b"{}"
                try:
                    body = json.loads(raw)
                except (json.JSONDecodeError, UnicodeDecodeError) as error:
                    raise _BadRequest(f"the body is not JSON: {error}") from None
                if not isinstance(body, dict):
                    raise _BadRequest("the body must be a JSON object")
                return body

            def _send(self, status: HTTPStatus, answer: dict[str, Any]) -> None:
                self._raw(status, "application/json", json.dumps(answer, allow_nan=False).encode())

            def _raw(self, status: HTTPStatus, kind: str, body: bytes) -> None:
                # No sniffing, and no Referer: the token is in the page's URL.
                send(self, status, kind, body, {"X-Content-Type-Options": "nosniff", "Referrer-Policy": "no-referrer"})

            def log_message(self, format: str, *args: Any) -> None:
                pass  # every poll would be a line

        return Handler


class _BadRequest(ValueError):
    def __init__(self, message: str, status: HTTPStatus = HTTPStatus.BAD_REQUEST) -> None:
        super().__init__(message)
        self.status = status
