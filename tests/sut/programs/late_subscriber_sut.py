# SPDX-License-Identifier: EPL-2.0
"""A SUT that calls hello before it subscribes to tick (docs/sut.md asks the other order): the router drops tick 0,
so it never answers."""

import os
import time

from rei.wamp.auth import load_credentials
from rei.wamp.client import WampClient

run_id = os.environ["REI_RUN_ID"]
client = WampClient(os.environ["REI_ROUTER_URL"], auth=load_credentials(os.environ["REI_AUTH_FILE"])).start()
client.call(f"rei.run.{run_id}.sut.hello", {"name": "late subscriber"})
time.sleep(1.0)
client.subscribe(f"rei.run.{run_id}.sut.tick", lambda *args, **kwargs: print("a tick", flush=True))
print("subscribed after hello", flush=True)
time.sleep(3600)  # ignores `end`: REI must stop it
