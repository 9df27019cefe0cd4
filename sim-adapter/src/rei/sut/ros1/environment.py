# SPDX-License-Identifier: EPL-2.0
"""Where ROS 1 comes from and the environment its processes run in.

ROS 1 is Debian's (``scripts/setup-ros1.sh``): its Python packages live in the system's dist-packages, which REI's
own environment does not see. Both are CPython 3.11, so appending that folder to ``sys.path`` lets REI's interpreter
import rospy; appended, not prepended, so REI's own (newer) numpy, yaml and autobahn still win.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Mapping
from pathlib import Path

DIST_PACKAGES = Path("/usr/lib/python3/dist-packages")
SETUP_HINT = "ROS 1 is not installed: run scripts/setup-ros1.sh (Debian's ros-core, python3-rospy and messages)"


class RosUnavailableError(RuntimeError):
    """ROS 1 cannot be imported or started here; the message says how to install it."""


def import_rospy() -> None:
    """Make ``import rospy`` work (appending Debian's dist-packages once); RosUnavailableError if it cannot."""
    if DIST_PACKAGES.is_dir() and str(DIST_PACKAGES) not in sys.path:
        sys.path.append(str(DIST_PACKAGES))
    try:
        import actionlib  # noqa: F401
        import move_base_msgs.msg  # noqa: F401
        import rospy  # noqa: F401
    except ImportError as error:
        raise RosUnavailableError(f"{SETUP_HINT} ({error})") from None


def ros_environment(master_uri: str, home: Path, base: Mapping[str, str] = os.environ) -> dict[str, str]:
    """The environment of a ROS process of this run: its master, loopback only, logs under ``home``.

    REI's own variables (the router and its credentials) are left out: the stack talks ROS, not WAMP."""
    env = {key: value for key, value in base.items() if not key.startswith("REI_")}
    env.update({"ROS_MASTER_URI": master_uri, "ROS_IP": "127.0.0.1", "ROS_HOME": str(home),
                "ROS_LOG_DIR": str(home / "log"), "PYTHONUNBUFFERED": "1"})
    env.pop("ROS_HOSTNAME", None)  # it would win over ROS_IP
    return env
