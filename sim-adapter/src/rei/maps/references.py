# SPDX-License-Identifier: EPL-2.0
"""Where a test case's text names an occupancy map: ``room NAME occupancy "FILE.yaml"`` (docs/language.md), the
path relative to the ``.rei`` file. For the tools that read or move a test case without its model: the room
editor draws the map, campaigns notice a changed map, searches write edited cases elsewhere.
"""

from __future__ import annotations

import re
from pathlib import Path

#: The room form's keyword and its string; group 1 is the path as written between the quotes.
OCCUPANCY = re.compile(r'\broom\s+\^?\w+\s+occupancy\s+"((?:[^"\\\n]|\\.)*)"')


def unquoted(path: str) -> str:
    """A path as written between a ``.rei`` string's quotes, unescaped."""
    return path.replace('\\"', '"').replace("\\\\", "\\")


def map_path(text: str, folder: Path) -> Path | None:
    """The YAML file the text's occupancy room names, resolved against ``folder`` (the ``.rei`` file's); None for
    another room. Comments are skipped, so a commented-out room is not read."""
    found = OCCUPANCY.search(_without_comments(text))
    if found is None:
        return None
    path = Path(unquoted(found.group(1)))
    return path if path.is_absolute() else folder / path


def _without_comments(text: str) -> str:
    """The text with its ``//`` and ``/* */`` comments blanked (strings kept, offsets unchanged)."""
    return re.sub(r'"(?:[^"\\\n]|\\.)*"|//[^\n]*|/\*.*?\*/',
                  lambda m: m.group(0) if m.group(0).startswith('"') else " " * len(m.group(0)), text,
                  flags=re.DOTALL)
