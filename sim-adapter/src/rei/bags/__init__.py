# SPDX-License-Identifier: EPL-2.0
"""Recorded robot runs into REI: a ROS bag (ROS 1 ``.bag``, ROS 2 sqlite3 or MCAP) becomes a run folder the monitor
and evaluator judge like a simulated one (``rei import``, docs/ros.md).

Modules: ``reader`` (the bag's topics as time-ordered, checked samples, with ``rosbags``), ``importer`` (samples
into REI's recorded streams).
"""
