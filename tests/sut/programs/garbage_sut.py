# SPDX-License-Identifier: EPL-2.0
"""The reference navigation over the raw protocol (no kit), sending malformed messages around every answer.

Per tick: five malformed commands and one malformed status (rejected), then the real status and command (the
first five ticks' command is an absurd 100 m/s, clamped), then the same command again (stale). docs/sut.md says
what becomes of each; tests/sut/test_external_sut.py counts them.
"""

import math
import os
import queue

from rei.sut.external import protocol
from rei.sut.nav import NavController
from rei.wamp.auth import load_credentials
from rei.wamp.client import WampClient

MALFORMED_COMMANDS = 5
ABSURD_TICKS = 5

run_id = os.environ["REI_RUN_ID"]
client = WampClient(os.environ["REI_ROUTER_URL"], auth=load_credentials(os.environ["REI_AUTH_FILE"])).start()
inbox: queue.SimpleQueue = queue.SimpleQueue()
for name in ("tick", "goal", "cancel", "end"):
    client.subscribe(protocol.uri(run_id, name), lambda payload, name=name: inbox.put((name, payload)))
hello = client.call(protocol.uri(run_id, "hello"), {"name": "garbage"})
nav = NavController()
nav.reset(protocol.read_static_map(hello), protocol.read_pose(hello["start"]))
command_uri, status_uri = protocol.uri(run_id, "command"), protocol.uri(run_id, "status")
goal_id, published, scan = None, None, None
while True:
    name, message = inbox.get()
    if name == "end":
        break
    if name == "goal":
        goal_id = message["goal_id"]
        nav.set_goal(protocol.read_goal(message))
    elif name == "cancel":
        nav.cancel()
    elif name == "tick":
        k = message["tick"]
        observation = protocol.read_observation(message, scan)
        scan = observation.scan
        twist = nav.step(observation)
        for bad in ("go", {"tick": k, "v": math.nan, "w": 0.0}, {"tick": k, "v": 0.0, "w": 0.0, "vx": 1.0},
                    {"tick": str(k), "v": 0.0, "w": 0.0}, {"tick": k + 5, "v": 0.0, "w": 0.0}):
            client.publish(command_uri, bad)
        client.publish(status_uri, {"goal_id": goal_id, "status": "DONE"})
        status = (goal_id, nav.status.value, nav.status_text)
        if status != published and nav.status.value != "IDLE":
            published = status
            client.publish(status_uri, {"goal_id": goal_id, "status": nav.status.value, "text": nav.status_text})
        v = 100.0 if k < ABSURD_TICKS else twist.v
        client.publish(command_uri, {"tick": k, "v": v, "w": twist.w})
        client.publish(command_uri, {"tick": k, "v": v, "w": twist.w})  # a repeat: stale
client.close()
