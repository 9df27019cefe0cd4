# SPDX-License-Identifier: EPL-2.0
"""Generate every test case of a campaign once, before its runs: ``OUT/cases/<case>/`` (world.json, ...).

Generated rooms are first written to ``OUT/rooms/<case>.rei``. A case folder records the SHA-256 of the
``.rei`` text it came from and of the catalogues it imports; on resume an unchanged case is not generated again
(one generation less per case). The cases to generate go through one warm generator JVM (rei.run.jvm.JarServer):
one JVM start for the campaign instead of one per case.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import re
from dataclasses import dataclass
from pathlib import Path

from rei.campaign.plan import CaseSource
from rei.maps import MapError, load_map
from rei.maps.references import map_path, map_reference, unescaped
from rei.run.jvm import run_jar

STAMP = ".source.sha256"
#: The files a described robot was read from, written by the generator into the case folder (docs/artifacts.md).
SOURCES = "robot.sources"


@dataclass(frozen=True, slots=True)
class Prepared:
    key: str
    error: str | None
    cpu: float
    generated: bool


def needs_generation(source: CaseSource, out: Path) -> bool:
    """Whether ``prepare_case`` would run the generator for this case (it is new or its source changed)."""
    rei = source.rei_file(out)
    if rei is None:
        return False
    if _text_changed(source, rei):
        return True
    try:
        return not _current(source.case_dir(out), source_digest(rei, source.case_dir(out)))
    except OSError:
        return False  # prepare_case reports the unreadable file


def prepare_case(source: CaseSource, out: Path, *, server: Path | None = None) -> Prepared:
    """Generate the case unless it is current; ``server``: a warm generator JVM's socket (rei.run.jvm)."""
    rei = source.rei_file(out)
    if rei is None:  # an already generated folder
        return Prepared(source.key, None, 0.0, False)
    if _text_changed(source, rei):
        assert source.text is not None
        rei.parent.mkdir(parents=True, exist_ok=True)
        rei.write_text(source.text, encoding="utf-8")
    target = source.case_dir(out)
    try:
        if _current(target, source_digest(rei, target)):
            return Prepared(source.key, None, 0.0, False)
    except OSError as error:
        return Prepared(source.key, f"cannot read {error.filename}: {error.strerror or error}", 0.0, False)
    target.mkdir(parents=True, exist_ok=True)
    (target / STAMP).unlink(missing_ok=True)
    (target / SOURCES).unlink(missing_ok=True)  # the generator writes it again for a described robot
    result = run_jar("cli", ["generate", str(rei), "-o", str(target), "--quiet"], target.parent / f"{source.key}.log",
                     server=server)
    if result.code != 0:
        return Prepared(source.key, f"{rei} could not be generated (exit {result.code}): {result.log_tail}",
                        result.cpu, True)
    try:  # with the description's files, known now
        digest = source_digest(rei, target)
    except OSError as error:
        return Prepared(source.key, f"cannot read {error.filename}: {error.strerror or error}", result.cpu, True)
    (target / STAMP).write_text(digest + "\n", encoding="utf-8")
    return Prepared(source.key, None, result.cpu, True)


def _text_changed(source: CaseSource, rei: Path) -> bool:
    """A generated room whose ``.rei`` text is not (yet) the one on disk."""
    return source.text is not None and (not rei.is_file() or rei.read_text(encoding="utf-8") != source.text)


def _current(target: Path, digest: str) -> bool:
    stamp = target / STAMP
    return stamp.is_file() and stamp.read_text(encoding="utf-8").strip() == digest and (target / "world.json").is_file()


#: A test case's catalogue imports (docs/language.md): read to notice a changed catalogue on resume, rewritten by
#: relocated_imports.
_IMPORT = re.compile(r'^\s*import\s+"((?:[^"\\]|\\.)*)"', re.MULTILINE)


def source_digest(rei: Path, case_dir: Path | None = None) -> str:
    """SHA-256 of the test case's text, of every catalogue it imports, of an occupancy room's map (its YAML and
    image) and of the files its robot's description was read from when ``case_dir`` was generated (its
    ``robot.sources``: the description, its xacro includes, its collision meshes): a case is generated again when
    one of them changed."""
    text = rei.read_bytes()
    digest = hashlib.sha256(text)
    decoded = text.decode("utf-8", errors="replace")
    used = [rei.parent / unescaped(path) for path in _IMPORT.findall(decoded)]
    yaml = map_path(decoded, rei.parent)
    if yaml is not None:
        used.append(yaml)
        with contextlib.suppress(MapError):
            used.append(load_map(yaml).image)
    for path in used:
        if path.is_file():  # a missing one fails the generation with the validator's message
            digest.update(b"\0" + path.read_bytes())
    listed = case_dir / SOURCES if case_dir is not None else None
    if listed is not None and listed.is_file():
        for line in listed.read_text(encoding="utf-8").splitlines():
            path = Path(line)
            # one gone since: generated again, which then says what is missing
            digest.update(b"\0" + path.read_bytes() if path.is_file() else b"\0gone " + line.encode())
    return digest.hexdigest()


def relocated_imports(text: str, origin: Path, folder: Path) -> str:
    """``text``, written in ``origin``, with each catalogue import's path and an occupancy room's map path made
    relative to ``folder``, where it is written instead (rei.search: a candidate or shrunk case imports the base
    case's catalogues and stands in its building)."""

    def moved(path: str) -> str:
        return json.dumps(Path(os.path.relpath((origin / path).resolve(), folder.resolve())).as_posix())

    def relocate(match: re.Match[str]) -> str:
        return match.group(0)[:match.start(1) - match.start(0) - 1] + moved(unescaped(match.group(1)))

    occupancy = map_reference(text)
    if occupancy is not None:  # first: its offsets are those of the text before the imports are rewritten
        text = text[:occupancy.start] + moved(occupancy.path) + text[occupancy.end:]
    return _IMPORT.sub(relocate, text)

