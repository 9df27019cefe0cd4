# SPDX-License-Identifier: EPL-2.0
"""The connect-time check of a Ray cluster's nodes (rei.campaign.nodes), on a real local Ray instance whose tasks
run in the runtime environment ``$REI_RAY_RUNTIME_ENV`` names: one that points ``JAVA_HOME`` at a folder without
Java makes the node unfit, named with what it lacks, before any run; a runtime environment that is not JSON is
refused saying so. (A node whose PATH has no java, on a multi-node cluster: tests/campaign/test_campaign_ray_cluster.)"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from rei.campaign.backends import RUNTIME_ENV_ENV, RayUnavailableError, connect_ray


def test_a_node_the_runtime_env_leaves_without_java_is_named_at_connect_time(tmp_path: Path,
                                                                               monkeypatch: pytest.MonkeyPatch) -> None:
    settings = tmp_path / "runtime_env.json"  # as a user names one: a file
    settings.write_text(json.dumps({"env_vars": {"JAVA_HOME": str(tmp_path)}}), encoding="utf-8")
    monkeypatch.setenv(RUNTIME_ENV_ENV, str(settings))
    with pytest.raises(RayUnavailableError) as raised:
        connect_ray("local", 1)
    lines = str(raised.value).splitlines()
    assert lines[0] == "1 of 1 Ray node(s) cannot run REI's runs:", lines
    assert len(lines) == 2 and re.fullmatch(
        rf"node \S+ \([0-9a-f]{{12}}\): JAVA_HOME={re.escape(str(tmp_path))} has no bin/java; fix JAVA_HOME or "
        r"unset it", lines[1]), lines


def test_a_runtime_env_that_is_not_json_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(RUNTIME_ENV_ENV, "{py_modules: [rei.whl]}")
    with pytest.raises(RayUnavailableError, match=r"cannot connect to Ray at local: \$REI_RAY_RUNTIME_ENV: not a "
                                                  r"JSON object nor a JSON file"):
        connect_ray("local", 1)
