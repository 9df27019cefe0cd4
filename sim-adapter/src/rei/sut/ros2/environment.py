# SPDX-License-Identifier: EPL-2.0
"""Where a run's ROS 2 traffic goes: one DDS domain, loopback only, and a discovery tag of the run's own.

The bridge and the stack it starts get the same Cyclone DDS configuration (``CYCLONEDDS_URI`` for the stack): the
loopback interface with unicast discovery to 127.0.0.1 (no multicast), and ``Discovery/Tag`` set to the run's id,
so two runs on one machine and domain (a campaign's workers) never see each other's /clock, and nothing leaves
the machine. The stack also gets ``ROS_DOMAIN_ID``, ``RMW_IMPLEMENTATION=rmw_cyclonedds_cpp`` and the
localhost-only switches of ROS 2 Humble (``ROS_LOCALHOST_ONLY``) and Jazzy (``ROS_AUTOMATIC_DISCOVERY_RANGE``).
"""

from __future__ import annotations

import os
import re
from collections.abc import Mapping
from pathlib import Path
from xml.sax.saxutils import escape

#: ROS 2's default domain; Cyclone's port mapping allows 0..232.
DEFAULT_DOMAIN = 0
MAX_DOMAIN = 232


def cyclone_config(tag: str, trace: Path | None = None) -> str:
    """Cyclone DDS's XML configuration of a run: loopback only, unicast discovery, ``tag`` as discovery tag;
    ``trace`` (optional) a file for Cyclone's configuration trace, which shows the interface it chose."""
    tracing = (f"<Tracing><Verbosity>config</Verbosity><OutputFile>{escape(str(trace))}</OutputFile></Tracing>"
               if trace is not None else "")
    return ("<CycloneDDS><Domain><General><Interfaces><NetworkInterface name=\"lo\"/></Interfaces>"
            "<AllowMulticast>false</AllowMulticast></General><Discovery><ParticipantIndex>auto</ParticipantIndex>"
            f"<Peers><Peer address=\"127.0.0.1\"/></Peers><Tag>{escape(tag)}</Tag></Discovery>{tracing}"
            "</Domain></CycloneDDS>")


def run_tag(run_id: str) -> str:
    """The discovery tag of a run (its id, in characters any XML and shell take as they are)."""
    return "rei-" + re.sub(r"[^A-Za-z0-9_.-]", "_", run_id)


def ros2_environment(domain: int, config: str, home: Path, base: Mapping[str, str] = os.environ) -> dict[str, str]:
    """The environment of the ROS 2 stack: the run's domain and DDS configuration, logs under ``home``.

    REI's own variables (the router and its credentials) are left out: the stack talks ROS, not WAMP."""
    env = {key: value for key, value in base.items() if not key.startswith("REI_")}
    env.update({"ROS_DOMAIN_ID": str(domain), "RMW_IMPLEMENTATION": "rmw_cyclonedds_cpp", "CYCLONEDDS_URI": config,
                "ROS_LOCALHOST_ONLY": "1", "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST", "ROS_HOME": str(home),
                "ROS_LOG_DIR": str(home / "log"), "PYTHONUNBUFFERED": "1"})
    return env
