# SPDX-License-Identifier: EPL-2.0
"""A SUT that joins the run and then never answers a tick (a hung navigation stack)."""

import os
import time

from rei.wamp.auth import load_credentials
from rei.wamp.client import WampClient

run_id = os.environ["REI_RUN_ID"]
client = WampClient(os.environ["REI_ROUTER_URL"], auth=load_credentials(os.environ["REI_AUTH_FILE"])).start()
for name in ("tick", "goal", "cancel", "end"):
    client.subscribe(f"rei.run.{run_id}.sut.{name}", lambda *args, **kwargs: None)
client.call(f"rei.run.{run_id}.sut.hello", {"name": "silent"})
print("joined; not answering", flush=True)
time.sleep(3600)  # ignores `end`: REI must stop it
