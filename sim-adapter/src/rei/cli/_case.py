# SPDX-License-Identifier: EPL-2.0
"""Where a command's case comes from: a generated folder as it is, or a .rei file generated into OUT/case."""

from __future__ import annotations

import os
import shutil
import sys
from pathlib import Path

from rei.cli._java import run_java_cli
from rei.cli.errors import EXIT_OK, EXIT_USAGE, CommandError

#: Free space a run needs at the least: its streams, logs and report take tens of MB; a disk that fills up
#: mid-run would lose results, so refuse before anything starts. REI_MIN_FREE_MB overrides it.
MIN_FREE_MB = 200


def prepare_output(out: Path) -> None:
    """Create the output folder and make sure it is writable and has room before anything starts."""
    try:
        out.mkdir(parents=True, exist_ok=True)
        probe = out / ".rei-write-check"
        probe.write_bytes(b"")
        probe.unlink()
    except OSError as error:
        raise CommandError(f"cannot write to {out}: {error.strerror or error}") from None
    need = int(os.environ.get("REI_MIN_FREE_MB", MIN_FREE_MB))
    free = shutil.disk_usage(out).free // (1024 * 1024)
    if free < need:
        raise CommandError(f"only {free} MB free on the disk of {out}; a run needs at least {need} MB "
                           "(set REI_MIN_FREE_MB to change the limit)")


def case_target(case: Path, out: Path) -> Path:
    """Where ``case_folder`` will find or put the case's generated artifacts."""
    return case.resolve() if case.is_dir() else out / "case"


def case_folder(case: Path, out: Path, server: Path | None = None) -> Path:
    """The folder of generated artifacts to run. ``server``: a warm generator JVM's socket (rei.service)."""
    if case.is_dir():
        return case.resolve()  # children (a warm JVM among them) run in other working directories
    if case.suffix != ".rei" or not case.is_file():
        raise CommandError(f"{case}: expected a .rei file or a folder generated from one", EXIT_USAGE)
    generated = out / "case"
    args = ["generate", str(case.resolve()), "-o", str(generated.resolve()), "--quiet"]
    served = None
    if server is not None:
        from rei.run.jvm import run_served

        served = run_served(server, args, out / "generate.log")
    if served is not None:  # the diagnostics went to the log: show them as the JVM of our own would have
        text = (out / "generate.log").read_text(encoding="utf-8", errors="replace")
        if text:
            print(text, end="", file=sys.stderr, flush=True)
        code = served.code
    else:
        code = run_java_cli(args)
    if code != EXIT_OK:
        raise CommandError(f"{case} could not be generated (see above)", code)
    return generated


def valid_run_id(run_id: str) -> bool:
    """Run ids become part of topic URIs: letters, digits, '_' and '-' only."""
    return bool(run_id) and all(c.isascii() and (c.isalnum() or c in "_-") for c in run_id)
