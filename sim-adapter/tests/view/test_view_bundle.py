# SPDX-License-Identifier: EPL-2.0
"""The shipped page (rei/view/static) is exactly what `npm run build` makes of the current viewer/ sources.

The build writes build-info.json with a digest of its sources and of every file it wrote (viewer/build-info.ts);
recomputing both here catches a page that was not rebuilt after a source change, and a hand-edited one, without
needing Node.js.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

from rei.view import STATIC_DIR

VIEWER = Path(__file__).resolve().parents[3] / "viewer"
#: Keep in step with SOURCES in viewer/build-info.ts.
SOURCES = ("index.html", "edit.html", "package.json", "package-lock.json", "tsconfig.json", "vite.config.ts",
           "build-info.ts", "src")


def sources_digest(root: Path) -> str:
    paths = []
    for entry in SOURCES:
        path = root / entry
        paths += [p.relative_to(root).as_posix() for p in path.rglob("*") if p.is_file()] if path.is_dir() \
            else [entry]
    digest = hashlib.sha256()
    for relative in sorted(paths):
        digest.update(relative.encode() + b"\0")
        digest.update((root / relative).read_bytes())
        digest.update(b"\0")
    return digest.hexdigest()


def build_info() -> dict[str, object]:
    return json.loads((STATIC_DIR / "build-info.json").read_text())


def test_the_shipped_page_was_built_from_the_current_sources() -> None:
    info = build_info()
    assert info["format"] == "rei-view-build/1"
    assert info["sources"] == sources_digest(VIEWER), (
        "viewer/ changed since sim-adapter/src/rei/view/static was built: run `npm ci && npm run build` in viewer/")


def test_every_shipped_file_is_as_the_build_wrote_it() -> None:
    outputs = build_info()["outputs"]
    assert isinstance(outputs, dict)
    shipped = {p.relative_to(STATIC_DIR).as_posix() for p in STATIC_DIR.rglob("*") if p.is_file()}
    assert shipped - {"build-info.json"} == set(outputs), "files in static/ that the build did not write"
    for name, digest in outputs.items():
        assert hashlib.sha256((STATIC_DIR / name).read_bytes()).hexdigest() == digest, f"{name} was edited"


def test_the_digest_notices_a_changed_source(tmp_path: Path) -> None:
    for entry in SOURCES:
        source = VIEWER / entry
        target = tmp_path / entry
        if source.is_dir():
            for file in source.rglob("*"):
                if file.is_file():
                    (tmp_path / file.relative_to(VIEWER)).parent.mkdir(parents=True, exist_ok=True)
                    (tmp_path / file.relative_to(VIEWER)).write_bytes(file.read_bytes())
        else:
            target.write_bytes(source.read_bytes())
    assert sources_digest(tmp_path) == sources_digest(VIEWER)
    (tmp_path / "src" / "main.ts").write_text((VIEWER / "src" / "main.ts").read_text() + "\n")
    assert sources_digest(tmp_path) != sources_digest(VIEWER)
