# SPDX-License-Identifier: EPL-2.0
"""``OUT/verdicts.xml``: the verdicts as JUnit XML, so any CI server shows the requirements as test results.

One ``testsuite`` (the mission) with one ``testcase`` per requirement of Table 4. A fail is a ``failure``
element, an error an ``error`` element, not-applicable a ``skipped`` element; each carries the verdict's
message as ``message`` and its evidence, one fact per line, as text. A pass lists its evidence in
``system-out``. Properties record the run id, mission and total utility.
"""

from __future__ import annotations

import os
import re
import xml.etree.ElementTree as ET
from collections.abc import Mapping, Sequence
from pathlib import Path

from rei.evaluation.outcome import Status, Verdict
from rei.evaluation.verdicts import REQUIREMENTS

_ELEMENT = {Status.FAIL: "failure", Status.ERROR: "error", Status.NOT_APPLICABLE: "skipped"}
CLASSNAME = "rei.requirements"
#: Characters XML 1.0 can not carry (a reason string from a plug-in controller might contain them).
_NOT_XML = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")


def junit_tree(verdicts: Sequence[Verdict], *, suite: str, properties: Mapping[str, str],
               time: float = 0.0, classname: str = CLASSNAME) -> ET.ElementTree:
    counts = {status: sum(v.status == status for v in verdicts) for status in Status}
    root = ET.Element("testsuite", {
        "name": suite, "tests": str(len(verdicts)), "failures": str(counts[Status.FAIL]),
        "errors": str(counts[Status.ERROR]), "skipped": str(counts[Status.NOT_APPLICABLE]),
        "time": f"{time:.3f}",
    })
    props = ET.SubElement(root, "properties")
    for name, value in properties.items():
        ET.SubElement(props, "property", {"name": _clean(name), "value": _clean(value)})
    for verdict in verdicts:
        case = ET.SubElement(root, "testcase", {"classname": classname, "name": verdict.requirement,
                                                "time": "0"})
        body = _clean("\n".join(e.line() for e in verdict.evidence))
        message = _clean(verdict.message)
        element = _ELEMENT.get(verdict.status)
        if element is None:
            if body:
                ET.SubElement(case, "system-out").text = f"{message}\n{body}"
            continue
        attributes = {"message": message}
        if verdict.status != Status.NOT_APPLICABLE:
            attributes["type"] = str(verdict.status)
        child = ET.SubElement(case, element, attributes)
        child.text = f"{REQUIREMENTS.get(verdict.requirement, verdict.requirement)}\n{message}\n{body}"
    ET.indent(root)
    return ET.ElementTree(root)


def write_junit(path: str | os.PathLike[str], verdicts: Sequence[Verdict], *, suite: str,
                properties: Mapping[str, str], time: float = 0.0, classname: str = CLASSNAME) -> Path:
    """``classname``: the test cases' class (``rei compare`` files its metric verdicts as ``rei.metrics``)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    tree = junit_tree(verdicts, suite=suite, properties=properties, time=time, classname=classname)
    tmp = path.with_name(path.name + ".tmp")
    tree.write(tmp, encoding="utf-8", xml_declaration=True)
    os.replace(tmp, path)
    return path


def _clean(text: str) -> str:
    return _NOT_XML.sub("\ufffd", text)
