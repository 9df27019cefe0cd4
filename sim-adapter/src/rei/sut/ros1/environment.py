# SPDX-License-Identifier: EPL-2.0
"""Where ROS 1 comes from and the environment its processes run in.

ROS 1 is Debian's (``scripts/setup-ros1.sh``): its Python packages live in the system's dist-packages, which REI's
own environment does not see. Both are CPython 3.11, so REI's interpreter can import them, but not the whole
folder: Debian's other packages there (an old pyOpenSSL, say) would be picked up by REI's own libraries wherever
the environment lacks them, and break them. So only ROS's own top-level packages are importable from there, through
a finder placed after the normal ones: REI's environment still wins for everything it has.
"""

from __future__ import annotations

import importlib.abc
import importlib.machinery
import os
import sys
from collections.abc import Mapping, Sequence
from importlib.machinery import ModuleSpec
from pathlib import Path
from types import ModuleType

DIST_PACKAGES = Path("/usr/lib/python3/dist-packages")
SETUP_HINT = "ROS 1 is not installed: run scripts/setup-ros1.sh (Debian's ros-core, python3-rospy and messages)"
#: What rospy, actionlib and rosbag import from dist-packages (besides every ``*_msgs``/``*_srvs`` package).
ROS_PACKAGES = frozenset({
    "rospy", "rosgraph", "roslib", "rospkg", "rosbag", "roslz4", "genpy", "genmsg", "catkin", "catkin_pkg",
    "actionlib", "message_filters", "roscpp", "gnupg", "Cryptodome", "pyparsing", "distro", "dateutil", "defusedxml",
})


class RosUnavailableError(RuntimeError):
    """ROS 1 cannot be imported or started here; the message says how to install it."""


class _RosPackages(importlib.abc.MetaPathFinder):
    """Finds ROS's top-level packages in Debian's dist-packages, and nothing else there."""

    def find_spec(self, name: str, path: Sequence[str] | None = None,
                  target: ModuleType | None = None) -> ModuleSpec | None:
        if path is not None or not (name in ROS_PACKAGES or name.endswith(("_msgs", "_srvs"))):
            return None  # submodules come through their package's __path__
        return importlib.machinery.PathFinder.find_spec(name, [str(DIST_PACKAGES)])


def import_rospy() -> None:
    """Make ``import rospy`` work (ROS's packages only, see the module docstring); RosUnavailableError if not."""
    if DIST_PACKAGES.is_dir() and not any(isinstance(f, _RosPackages) for f in sys.meta_path):
        sys.meta_path.append(_RosPackages())
    try:
        import actionlib  # noqa: F401
        import move_base_msgs.msg  # noqa: F401
        import rospy  # noqa: F401
    except ImportError as error:
        raise RosUnavailableError(f"{SETUP_HINT} ({error})") from None


def ros_environment(master_uri: str, home: Path, base: Mapping[str, str] = os.environ) -> dict[str, str]:
    """The environment of a ROS process of this run: its master, loopback only, logs under ``home``.

    REI's own variables (the router and its credentials) are left out: the stack talks ROS, not WAMP. ``PATH`` has
    REI's Python environment first, as for any started SUT (docs/sut.md), also when the bridge was started by hand."""
    from rei.sut.external.process import search_path

    env = {key: value for key, value in base.items() if not key.startswith("REI_")}
    env.update({"PATH": search_path(base), "ROS_MASTER_URI": master_uri, "ROS_IP": "127.0.0.1", "ROS_HOME": str(home),
                "ROS_LOG_DIR": str(home / "log"), "PYTHONUNBUFFERED": "1"})
    env.pop("ROS_HOSTNAME", None)  # it would win over ROS_IP
    return env
