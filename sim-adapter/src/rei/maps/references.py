# SPDX-License-Identifier: EPL-2.0
"""Where a test case's text names an occupancy map: the ``occupancy "FILE.yaml"`` of a room's header
(docs/language.md), the path relative to the ``.rei`` file. For the tools that read or move a test case without
its model: campaigns notice a changed map, searches write edited cases elsewhere.

The text is read as the grammar's lexer reads it (org.eclipse.xtext.common.Terminals: IDs, strings in either
quote, comments), not by a pattern of the room's words: the header's parts are an unordered group
(``room R floorSize 0.5 occupancy "m.yaml"`` as well as ``room R occupancy "m.yaml" floorSize 0.5``), and
comments or strings may stand anywhere.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

_TOKEN = re.compile(r"""
    (?P<ws>\s+)
  | (?P<comment>//[^\r\n]*|/\*.*?(?:\*/|\Z))
  | (?P<string>"(?:[^"\\]|\\.)*"|'(?:[^'\\]|\\.)*')
  | (?P<id>\^?[A-Za-z_][A-Za-z_0-9]*)
  | (?P<other>.)
""", re.VERBOSE | re.DOTALL)
_ESCAPES = {"b": "\b", "t": "\t", "n": "\n", "f": "\f", "r": "\r", '"': '"', "'": "'", "\\": "\\"}


@dataclass(frozen=True, slots=True)
class MapReference:
    """The string naming a room's map: ``text[start:end]`` is the string with its quotes, ``path`` its value."""

    start: int
    end: int
    path: str


def unescaped(body: str) -> str:
    """A string's text between its quotes, unescaped as Xtext's STRING converter does (``\\n``, ``\\"``, ``\\u00e9``...)."""
    return re.sub(r"\\(u[0-9a-fA-F]{4}|.)", _unescape, body, flags=re.DOTALL)


def _unescape(escape: re.Match[str]) -> str:
    code = escape.group(1)
    return chr(int(code[1:], 16)) if len(code) == 5 else _ESCAPES.get(code, code)


def map_reference(text: str) -> MapReference | None:
    """The ``occupancy`` string of the first room header that has one (between ``room NAME`` and its ``{``)."""
    tokens = [(m.lastgroup, m.start(), m.end()) for m in _TOKEN.finditer(text)
              if m.lastgroup not in ("ws", "comment")]
    for i, (kind, start, end) in enumerate(tokens):
        if kind != "id" or text[start:end] != "room" or i + 1 >= len(tokens) or tokens[i + 1][0] != "id":
            continue
        j = i + 2
        while j < len(tokens) and text[tokens[j][1]:tokens[j][2]] not in ("{", "}"):
            kind, start, end = tokens[j]
            if kind == "id" and text[start:end] == "occupancy" and j + 1 < len(tokens) and tokens[j + 1][0] == "string":
                _, s, e = tokens[j + 1]
                return MapReference(s, e, unescaped(text[s + 1:e - 1]))
            j += 1
    return None


def map_path(text: str, folder: Path) -> Path | None:
    """The YAML file the text's occupancy room names, resolved against ``folder`` (the ``.rei`` file's); None for
    another room. Comments are skipped, so a commented-out room is not read."""
    found = map_reference(text)
    if found is None:
        return None
    path = Path(found.path)
    return path if path.is_absolute() else folder / path
