# SPDX-License-Identifier: EPL-2.0
"""A monitor that exits before the simulation: lost, unless it exited 0 after the mission's END, whose signal the
router delivers to the evaluator a moment after the monitor has gone (a run printed 'the live monitor exited with
code 0 ...' and was judged again from its recording when that signal came a few milliseconds late)."""

from __future__ import annotations

import threading
import time
from pathlib import Path

from rei.evaluation import Evaluator
from rei.run.pipeline import monitor_lost

END = {"seq": 0, "t": 33.5, "signal": "SIG_MISSION_END", "subject": "tb3", "object": "mission", "distance": 0.0}


def test_a_monitor_that_finished_is_not_lost_when_its_end_signal_arrives_after_it_exited(tmp_path: Path) -> None:
    evaluator = Evaluator(tmp_path)
    late = threading.Timer(0.3, evaluator.on_signal, args=(END,))
    late.start()
    started = time.monotonic()
    try:
        assert monitor_lost(0, evaluator, grace=5.0) is False  # before: lost, evaluator.ended was not set yet
    finally:
        late.join()
    assert time.monotonic() - started < 4.0
    assert monitor_lost(None, evaluator) is False  # still running


def test_a_monitor_that_exits_without_the_end_or_with_an_error_is_lost(tmp_path: Path) -> None:
    evaluator = Evaluator(tmp_path)
    assert monitor_lost(0, evaluator, grace=0.2) is True
    assert monitor_lost(1, evaluator, grace=0.2) is True
    evaluator.on_signal(END)
    assert monitor_lost(1, evaluator) is True  # a crash after the END is still a crash
