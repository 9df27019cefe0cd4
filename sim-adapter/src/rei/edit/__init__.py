# SPDX-License-Identifier: EPL-2.0
"""The room editor (`rei edit`): a test case's room as a diagram in the browser, saved as `.rei` text.

Three parts (docs/room-editor.md): the page, built from ``viewer/`` into ``rei/view/static/`` beside the live view;
this package's loopback HTTP server, which owns the file; and the edit engine, a Java process holding the Xtext
model (``rei-room-editor.jar``), which applies the page's operations and saves them through the serializer.
"""

from rei.edit.engine import EditEngine, EngineError, EngineFailure, engine_command
from rei.edit.server import PAGE, TOKEN_HEADER, EditServer, EditServerError
from rei.edit.session import EditSession, SessionConflict

__all__ = ["PAGE", "TOKEN_HEADER", "EditEngine", "EditServer", "EditServerError", "EditSession", "EngineError",
           "EngineFailure", "SessionConflict", "engine_command"]
