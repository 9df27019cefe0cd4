# SPDX-License-Identifier: EPL-2.0
"""The one error every artifact reader raises.

Generated files come from another toolchain (the Java generators), so a reader's error must tell the user which
file is wrong and where inside it, without a stack trace through the reader.
"""

from __future__ import annotations

from pathlib import Path


class ArtifactError(ValueError):
    """A generated file is missing, malformed or inconsistent with its siblings.

    ``str(error)`` starts with the file's path, then the location inside it (``objects[3].size``), then what is
    wrong.
    """

    def __init__(self, path: Path | str, message: str) -> None:
        self.path = Path(path)
        self.detail = message
        super().__init__(f"{self.path}: {message}")
