# SPDX-License-Identifier: EPL-2.0
"""Recordings of published streams: ``OUT/streams/<name>.msgpack``, a plain msgpack stream.

Why: the monitor can replay a run without the simulator, and the simulator proves determinism (same seed ->
byte-identical recording). The file is the concatenation of the messages' msgpack encodings, nothing else:
msgpack is self-delimiting, so every msgpack library reads it back object by object (Python ``msgpack.Unpacker``,
Java ``MessageUnpacker``), and its bytes are exactly the payload bytes inside the WAMP PUBLISH frames.
"""

from __future__ import annotations

import os
from collections.abc import Iterator, Mapping
from pathlib import Path
from types import TracebackType
from typing import Any, BinaryIO, Self

import msgpack

from rei.wamp.codec import pack


def stream_path(out_dir: str | os.PathLike[str], name: str) -> Path:
    """Where the recording of stream ``name`` (``state``, ``mission``) of a run in ``out_dir`` lives."""
    return Path(out_dir) / "streams" / f"{name}.msgpack"


class RecordingWriter:
    """Appends messages to a recording; creates the folder, truncates an existing file."""

    def __init__(self, path: str | os.PathLike[str]) -> None:
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._file: BinaryIO | None = open(self.path, "wb")  # noqa: SIM115 - closed by close()
        self.count = 0

    def write(self, message: Mapping[str, Any]) -> bytes:
        """Append one message; returns its bytes."""
        if self._file is None:
            raise ValueError(f"recording {self.path} is closed")
        data = pack(message)
        self._file.write(data)
        self.count += 1
        return data

    def flush(self) -> None:
        if self._file is not None:
            self._file.flush()

    def close(self) -> None:
        if self._file is not None:
            self._file.close()
            self._file = None

    def __enter__(self) -> Self:
        return self

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        self.close()


def iter_recording(path: str | os.PathLike[str]) -> Iterator[Any]:
    """The messages of a recording in order; a truncated last message (crashed writer) raises ValueError."""
    path = Path(path)
    size = path.stat().st_size
    with open(path, "rb") as f:
        unpacker = msgpack.Unpacker(f, raw=False)
        yield from unpacker
        if unpacker.tell() != size:
            raise ValueError(f"{path}: truncated message at byte {unpacker.tell()} of {size}")


def read_recording(path: str | os.PathLike[str]) -> list[Any]:
    """All messages of a recording."""
    return list(iter_recording(path))
