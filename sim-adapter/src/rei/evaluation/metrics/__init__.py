# SPDX-License-Identifier: EPL-2.0
"""Navigation metrics of one run (docs/metrics.md), computed from its recorded streams and its case.

``compute_metrics(run_dir)`` reads ``OUT/streams/state.msgpack`` and ``mission.msgpack``, the case's world.json,
monitor.json and mission.xml (or the run's ``mission_info.json``), and returns ``{name: value}`` with every name
of :data:`METRICS` (None where a metric does not apply) plus ``task_times``. ``rei run``, ``rei evaluate``,
campaigns and ``rei import`` + ``rei evaluate`` all get them in ``summary.json``'s ``metrics``.
"""

from rei.evaluation.metrics.compute import Measured, MetricsError, compute_metrics, measure
from rei.evaluation.metrics.definitions import BY_NAME, LIST_KEYS, METRICS, NAMES, Better, Kind, Metric

__all__ = ["BY_NAME", "LIST_KEYS", "METRICS", "NAMES", "Better", "Kind", "Measured", "Metric", "MetricsError",
           "compute_metrics", "measure"]
