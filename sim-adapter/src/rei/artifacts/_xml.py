# SPDX-License-Identifier: EPL-2.0
"""Reading an XML artifact's root element, with errors that name the file and where it broke."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

from rei.artifacts.errors import ArtifactError


def read_root(path: Path, tag: str) -> ET.Element:
    """The root element of ``path``, which must exist, be well-formed and be a ``<tag>``."""
    if not path.is_file():
        raise ArtifactError(path, "file is missing")
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as exc:
        line, column = exc.position
        raise ArtifactError(path, f"not well-formed XML at line {line} column {column}") from None
    if root.tag != tag:
        raise ArtifactError(path, f"root element must be <{tag}>, got <{root.tag}>")
    return root
