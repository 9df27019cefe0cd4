# SPDX-License-Identifier: EPL-2.0
"""JuPedSim's wheel links GPL-3.0-or-later parts of CGAL: only the people server may import it, never REI's
package (docs/people.md#licence-where-jupedsim-runs)."""

from __future__ import annotations

import ast
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
SERVER = REPO / "pedestrians" / "jupedsim_server.py"


def _imports(path: Path) -> set[str]:
    names = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            names |= {a.name.split(".")[0] for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module:
            names.add(node.module.split(".")[0])
    return names


def test_no_module_of_the_python_package_imports_jupedsim() -> None:
    offenders = [str(p.relative_to(REPO)) for p in (REPO / "sim-adapter" / "src").rglob("*.py")
                 if "jupedsim" in _imports(p)]
    assert offenders == []


def test_the_people_server_is_the_one_that_does_and_says_under_which_licence() -> None:
    assert "jupedsim" in _imports(SERVER)
    head = SERVER.read_text(encoding="utf-8").splitlines()[0]
    assert head == "# SPDX-License-Identifier: EPL-2.0 OR GPL-2.0-or-later"
    assert "Secondary Licenses" in SERVER.read_text(encoding="utf-8")[:600]
