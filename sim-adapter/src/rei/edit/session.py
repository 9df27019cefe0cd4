# SPDX-License-Identifier: EPL-2.0
"""One test case open in the room editor: the engine's model of it and the file on disk.

The engine edits the model; this side owns the file. It writes the engine's text when the user saves (nothing is
written otherwise) and notices when someone else changed the file: without unsaved edits the editor follows the
file at once, with them it asks (reload or keep) and refuses to save over the other version until the user chose.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
import threading
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rei.edit.engine import EditEngine, EngineError
from rei.edit.occupancy import MapPictures
from rei.edit.outlines import RobotOutlines


class SessionConflict(RuntimeError):
    """A request that does not fit the session's state now (nothing to undo, a save over a changed file)."""


@dataclass(frozen=True, slots=True)
class _Disk:
    """What was last seen of the file: its stat fingerprint, and its text (None when it is gone)."""

    stamp: tuple[int, int] | None
    text: str | None

    @staticmethod
    def stamp_of(path: Path) -> tuple[int, int] | None:
        """Modification time and size: a cheap look, before reading the file when it differs."""
        try:
            stat = path.stat()
        except FileNotFoundError:
            return None
        return stat.st_mtime_ns, stat.st_size

    @staticmethod
    def read(path: Path) -> _Disk:
        stamp = _Disk.stamp_of(path)
        try:
            data = path.read_bytes()
        except FileNotFoundError:
            return _Disk(None, None)
        # Bytes decoded as they are: a CRLF file keeps its CRLF through the round trip.
        return _Disk(stamp, data.decode("utf-8", errors="replace"))


class EditSession:
    """The state the page sees (docs/room-editor.md, "Page ⇄ HTTP server"); every method is thread-safe."""

    def __init__(self, path: Path, engine: EditEngine) -> None:
        self.path = path
        self._engine = engine
        self._lock = threading.RLock()
        self._version = 1
        self._notice: str | None = None
        self._disk = _Disk.read(path)
        if self._disk.text is None:
            raise FileNotFoundError(f"{path}: no such file")
        self._disk_changed = False
        self._maps = MapPictures()
        self._outlines = RobotOutlines()
        self._answer = engine.request("open", path=str(path.resolve()))

    # -- what the page reads ------------------------------------------------------------------------------------

    def status(self) -> dict[str, Any]:
        with self._lock:
            self._look_at_disk()
            return self._status()

    def state(self) -> dict[str, Any]:
        with self._lock:
            self._look_at_disk()
            notice, self._notice = self._notice, None
            answer = self._answer
            folder = self.path.resolve().parent
            diagram = self._outlines.of_diagram(_relative_map(answer.get("diagram"), folder), folder)
            return {**self._status(), "file": str(self.path), "text": answer["text"],
                    "diagram": diagram,
                    "issues": answer.get("issues", []),
                    "palette": answer.get("palette", []), "notice": notice,
                    "occupancy": self._maps.of_diagram(answer.get("diagram"))}

    # No lock for these two: `rei edit` asks them when it stops, and a request may hold the lock for as long as a
    # hung engine takes to be stopped. Each reads references that are replaced whole, never changed in place.
    @property
    def text(self) -> str:
        return str(self._answer["text"])

    @property
    def dirty(self) -> bool:
        return self._answer["text"] != self._disk.text

    # -- what the page does -------------------------------------------------------------------------------------

    def apply(self, operations: list[Any]) -> dict[str, Any]:
        """One undo step; ``EngineError`` (refused) leaves everything as it was."""
        return self._change("apply", operations=operations)

    def undo(self) -> dict[str, Any]:
        with self._lock:
            if not self._answer.get("canUndo"):
                raise SessionConflict("nothing to undo")
            return self._change("undo")

    def redo(self) -> dict[str, Any]:
        with self._lock:
            if not self._answer.get("canRedo"):
                raise SessionConflict("nothing to redo")
            return self._change("redo")

    def save(self) -> dict[str, Any]:
        with self._lock:
            self._look_at_disk()
            if self._disk_changed:
                raise SessionConflict(f"{self.path} changed on disk since it was opened: choose to reload it or "
                                      "to keep your version before saving")
            text = str(self._answer["text"])
            _write_atomically(self.path, text)
            self._disk = _Disk.read(self.path)
            self._version += 1
            return self.state()

    def reload(self) -> dict[str, Any]:
        """Takes the file as it is on disk now; the editor's unsaved edits and history go (the user chose so)."""
        with self._lock:
            disk = _Disk.read(self.path)
            if disk.text is None:
                raise SessionConflict(f"{self.path} is gone from disk: keep your version and save to write it again")
            self._answer = self._engine.request("reset", text=disk.text)
            self._disk, self._disk_changed = disk, False
            self._version += 1
            return self.state()

    def keep(self) -> dict[str, Any]:
        """Keeps the editor's version: the disk's change is acknowledged and the next save overwrites it."""
        with self._lock:
            self._disk, self._disk_changed = _Disk.read(self.path), False
            self._version += 1
            return self.state()

    def close(self) -> None:
        self._engine.close()

    # -- inside ---------------------------------------------------------------------------------------------------

    def _status(self) -> dict[str, Any]:
        return {"version": self._version, "dirty": self.dirty,
                "diskChanged": self._disk_changed, "canUndo": bool(self._answer.get("canUndo")),
                "canRedo": bool(self._answer.get("canRedo"))}

    def _change(self, command: str, **fields: Any) -> dict[str, Any]:
        with self._lock:
            try:
                self._answer = self._engine.request(command, **fields)
            finally:
                if self._engine.take_restart():
                    self._notice = "the edit engine had stopped and was started again: the undo history is gone"
                    self._version += 1
            self._version += 1
            return self.state()

    def _look_at_disk(self) -> None:
        """Follows a change of the file on disk: at once without unsaved edits, else flags it for the user."""
        if self._disk_changed:
            return
        if _Disk.stamp_of(self.path) == self._disk.stamp:
            return
        disk = _Disk.read(self.path)
        if disk.text == self._disk.text:
            self._disk = disk  # touched, same text
            return
        self._version += 1
        if disk.text is None or self.dirty:
            self._disk_changed = True
            return
        try:
            self._answer = self._engine.request("reset", text=disk.text)
        except EngineError as error:
            self._disk_changed = True
            self._notice = f"{self.path} changed on disk and could not be reloaded: {error}"
            return
        self._disk = disk
        self._notice = f"reloaded {self.path.name}: it changed on disk (you had no unsaved edits)"


def _write_atomically(path: Path, text: str) -> None:
    """Writes ``text`` so that a reader sees the old file or the new one, never half of it; keeps the mode."""
    try:
        mode = path.stat().st_mode & 0o7777
    except FileNotFoundError:
        mode = 0o644
    handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".saving", dir=path.parent)
    try:
        with os.fdopen(handle, "wb") as out:
            out.write(text.encode("utf-8"))
            out.flush()
            os.fsync(out.fileno())
        os.chmod(temporary, mode)
        os.replace(temporary, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(temporary)
        raise


def _relative_map(diagram: dict[str, Any] | None, folder: Path) -> dict[str, Any] | None:
    """The diagram for the page: a map room's files named relative to the case's folder (the engine resolves them;
    the browser needs no path of this machine)."""
    room = (diagram or {}).get("room") or {}
    occupancy = room.get("map")
    if diagram is None or not occupancy:
        return diagram
    relative = {key: Path(os.path.relpath(occupancy[key], folder)).as_posix() for key in ("yaml", "image")}
    return {**diagram, "room": {**room, "map": {**occupancy, **relative}}}
