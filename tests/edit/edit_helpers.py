# SPDX-License-Identifier: EPL-2.0
"""Helpers of the room editor's tests: HTTP calls to an editor's /api/ as the page makes them."""

from __future__ import annotations

import json
import os
import urllib.error
import urllib.request
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rei.edit import TOKEN_HEADER, EditEngine, EditServer, EditSession

#: Screenshots the page tests leave for people (target/ is build output, git-ignored); README's come from here.
SHOTS = Path(__file__).resolve().parents[2] / "target" / "edit"


@dataclass
class Editor:
    case: Path
    session: EditSession
    server: EditServer
    engine: EditEngine

    @property
    def base(self) -> str:
        return f"http://127.0.0.1:{self.server.port}"

    def call(self, method: str, path: str, body: Any = None, *, headers: dict[str, str] | None = None,
             raw: bytes | None = None) -> tuple[int, dict[str, Any]]:
        """(status, JSON answer) of one request with the page's token unless ``headers`` replace it."""
        sent = {TOKEN_HEADER: self.server.token, "Content-Type": "application/json"} if headers is None else headers
        data = raw if raw is not None else (json.dumps(body).encode() if body is not None else None)
        request = urllib.request.Request(self.base + path, data=data, method=method, headers=sent)
        try:
            with urllib.request.urlopen(request, timeout=180) as answer:
                return answer.status, json.loads(answer.read())
        except urllib.error.HTTPError as error:
            return error.code, json.loads(error.read() or b"{}")

    def ok(self, method: str, path: str, body: Any = None) -> dict[str, Any]:
        status, answer = self.call(method, path, body)
        assert status == 200, answer
        return answer

    def apply(self, *operations: dict[str, Any]) -> dict[str, Any]:
        return self.ok("POST", "/api/apply", {"operations": list(operations)})


def write_as_another_program(path: Path, text: str) -> None:
    """Writes ``text`` with a modification time the editor has not seen (a write in the same clock tick as the
    last one would otherwise keep it)."""
    stamp = path.stat().st_mtime_ns
    path.write_text(text, encoding="utf-8")
    if path.stat().st_mtime_ns == stamp:
        os.utime(path, ns=(stamp + 1_000_000, stamp + 1_000_000))
