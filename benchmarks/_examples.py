# SPDX-License-Identifier: EPL-2.0
"""What several benchmarks share: an example test case generated into a folder by the CLI jar."""

from __future__ import annotations

from pathlib import Path

from rei import toolchain

REPO = Path(__file__).resolve().parents[1]


def generate_example(name: str, case: Path) -> Path:
    """``examples/NAME.rei`` generated into ``case``; ends the benchmark if generation fails."""
    code = toolchain.run_jar(toolchain.find_jar("cli"), ["generate", str(REPO / "examples" / f"{name}.rei"),
                                                         "-o", str(case), "--quiet"], java=toolchain.find_java())
    if code != 0:
        raise SystemExit(f"generation of examples/{name}.rei failed with exit code {code}")
    return case
