# SPDX-License-Identifier: EPL-2.0
"""The collector's settings file: every key, and a position in every complaint."""

from __future__ import annotations

from pathlib import Path

import pytest

from rei.wamp import CollectorConfig, LaserMode
from rei.wamp.collector_settings import CollectorSettingsError, load_collector_settings


def test_every_setting_is_read(tmp_path: Path) -> None:
    path = tmp_path / "collector.yaml"
    path.write_text("rate_hz: 10\nlaser: full\ncontacts: false\nodometry: false\nnav_state: false\n"
                    "full_frame_period: 0\nobjects: [walker, DYNAMIC]\n", encoding="utf-8")
    assert load_collector_settings(path) == CollectorConfig(
        rate_hz=10.0, laser=LaserMode.FULL, contacts=False, odometry=False, nav_state=False, full_frame_period=0.0,
        objects=("walker", "DYNAMIC"))
    path.write_text("objects: []\n", encoding="utf-8")
    assert load_collector_settings(path).objects == ()
    path.write_text("", encoding="utf-8")
    assert load_collector_settings(path) == CollectorConfig()


@pytest.mark.parametrize(("text", "where", "message"), [
    ("objects: walker\n", "1:10", ("objects must be a list of object names or categories, e.g. [walker, HUMAN], "
                                  "got 'walker'")),
    ("rate_hz: 20\nobjects: [walker, 3]\n", "2:19", ("objects must list object names or categories (HUMAN, "
                                                    "DYNAMIC), got '3'")),
    ("objects:\n  - {name: walker}\n", "2:5", "objects must list object names"),
    ("object: [walker]\n", "1:1", "unknown setting 'object'"),
])
def test_a_bad_objects_setting_names_file_line_and_column(tmp_path: Path, text: str, where: str,
                                                          message: str) -> None:
    path = tmp_path / "collector.yaml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(CollectorSettingsError) as raised:
        load_collector_settings(path)
    assert str(raised.value).startswith(f"{path}:{where}: {message}"), str(raised.value)
