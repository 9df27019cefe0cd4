# SPDX-License-Identifier: EPL-2.0
"""The room editor (`rei edit`): a test case's room as a diagram in the browser, saved as `.rei` text.

Three parts (docs/room-editor.md): the page, built from ``viewer/`` into ``rei/view/static/`` beside the live view;
this package's loopback HTTP server, which owns the file; and the edit engine, a Java process holding the Xtext
model (``rei-room-editor.jar``), which applies the page's operations and saves them through the serializer.

The names below are imported when first used: the package also holds plain text edits (rei.edit.gatherings) that
campaigns and searches use, which must not bring in the server and the live view's stack beneath it.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from rei.edit.engine import EditEngine, EngineError, EngineFailure, engine_command
    from rei.edit.server import PAGE, TOKEN_HEADER, EditServer, EditServerError
    from rei.edit.session import EditSession, SessionConflict

_MODULES = {"EditEngine": "engine", "EngineError": "engine", "EngineFailure": "engine", "engine_command": "engine",
            "PAGE": "server", "TOKEN_HEADER": "server", "EditServer": "server", "EditServerError": "server",
            "EditSession": "session", "SessionConflict": "session"}


def __getattr__(name: str) -> Any:
    module = _MODULES.get(name)
    if module is None:
        raise AttributeError(f"module 'rei.edit' has no attribute {name!r}")
    return getattr(importlib.import_module(f"rei.edit.{module}"), name)


__all__ = ["PAGE", "TOKEN_HEADER", "EditEngine", "EditServer", "EditServerError", "EditSession", "EngineError",
           "EngineFailure", "SessionConflict", "engine_command"]
