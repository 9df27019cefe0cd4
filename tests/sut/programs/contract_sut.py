# SPDX-License-Identifier: EPL-2.0
"""A SUT on the bare protocol that records every payload the simulation sends, exactly as decoded from msgpack.

    contract_sut.py EXAMPLES OUT

EXAMPLES is a JSON file made of docs/sut.md's own examples (tests/sut/test_sut_contract.py extracts them):
``hello_call``, ``command`` (a list, used in turn), ``status`` (goal id -> the status sent when that goal arrives)
and ``cancelled`` (sent on ``cancel``). They are sent with ``tick``/``goal_id`` set to the current ones, so the
documented shapes cross the real router into a real run. Per tick, the first command example goes first with the
tick as a float, which the document says is rejected. OUT receives ``contract.msgpack``: ``[[name, payload],
...]`` in arrival order, ``hello``'s result first.
"""

import json
import os
import queue
import sys
from pathlib import Path

import msgpack

from rei.sut.external import protocol
from rei.wamp.auth import load_credentials
from rei.wamp.client import WampClient

examples, out = json.loads(Path(sys.argv[1]).read_text()), Path(sys.argv[2])
run_id = os.environ["REI_RUN_ID"]
# WebSocket, the transport every WAMP library has (REI_ROUTER_URL), not the kit's RawSocket
client = WampClient(os.environ["REI_ROUTER_URL"], os.environ["REI_REALM"],
                    auth=load_credentials(os.environ["REI_AUTH_FILE"])).start()
inbox: queue.SimpleQueue = queue.SimpleQueue()
for name in protocol.FROM_SIMULATION:
    client.subscribe(protocol.uri(run_id, name), lambda payload, name=name: inbox.put((name, payload)))
hello = client.call(protocol.uri(run_id, "hello"), examples["hello_call"])
received = [["hello", hello]]
command_uri, status_uri = protocol.uri(run_id, "command"), protocol.uri(run_id, "status")
commands = examples["command"]
while True:
    name, payload = inbox.get()
    received.append([name, payload])
    if name == "end":
        break
    if name == "goal":
        client.publish(status_uri, {**examples["status"][str(payload["goal_id"])], "goal_id": payload["goal_id"]})
    elif name == "cancel":
        client.publish(status_uri, {**examples["cancelled"], "goal_id": payload["goal_id"]})
    elif name == "tick":
        k = payload["tick"]
        client.publish(command_uri, {**commands[0], "tick": float(k)})  # rejected: tick is an integer
        client.publish(command_uri, {**commands[k % len(commands)], "tick": k})
out.joinpath("contract.msgpack").write_bytes(msgpack.packb(received))
client.close()
