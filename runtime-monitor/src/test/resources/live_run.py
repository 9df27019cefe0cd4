# SPDX-License-Identifier: EPL-2.0
"""Live check of the monitor jar against a real Crossbar router (rei.wamp.router), publishing a recorded run.

Usage: python live_run.py JAR CASE_DIR STREAMS_DIR OUT_DIR
Starts a private router, the monitor (--until-end, recording what it receives), subscribes to the signal topic,
publishes the recorded state and mission messages in replay order (mission first at equal times), waits for the
monitor to exit and writes OUT_DIR/live-signals.txt (the signals as received over WAMP) and OUT_DIR/monitor.err.
"""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

from rei.wamp.client import WampClient
from rei.wamp.recording import read_recording
from rei.wamp.router import Router

RUN = "live1"


def main(jar: str, case_dir: str, streams: Path, out: Path) -> int:
    out.mkdir(parents=True, exist_ok=True)
    states = read_recording(streams / "state.msgpack")
    missions = read_recording(streams / "mission.msgpack")
    received: list[dict] = []
    with Router() as router:
        err = open(out / "monitor.err", "w")
        java = subprocess.Popen(["java", "-jar", jar, "--router", router.ws_url, "--run", RUN, "--case", case_dir,
                                 "--record", str(out / "received"), "--until-end", "--timeout", "60", "--quiet",
                                 "--snapshot-out", str(out / "snapshot.xmi")], stderr=err)
        with WampClient(router.rs_url) as client:
            client.subscribe(f"rei.run.{RUN}.signal", lambda s: received.append(s))
            deadline = time.monotonic() + 60
            while "monitoring" not in (out / "monitor.err").read_text():
                if time.monotonic() > deadline or java.poll() is not None:
                    raise SystemExit("monitor did not start: " + (out / "monitor.err").read_text())
                time.sleep(0.2)
            started = time.monotonic()
            m = 0
            for s in states:
                while m < len(missions) and missions[m]["t"] <= s["t"]:
                    client.publish(f"rei.run.{RUN}.mission", missions[m])
                    m += 1
                client.publish(f"rei.run.{RUN}.state", s)
                time.sleep(0.002)  # one pipeline per topic: keep the two topics in replay order
            for rest in missions[m:]:
                client.publish(f"rei.run.{RUN}.mission", rest)
            client.flush()
            code = java.wait(timeout=90)
            time.sleep(0.5)
            elapsed = time.monotonic() - started
    lines = [f"{s['seq']} {s['t']:.3f} {s['signal']} {s['subject']} {s['object']} {s['distance']:.4f}" for s in received]
    (out / "live-signals.txt").write_text("\n".join(lines) + "\n")
    print(f"monitor exit {code}, {len(states)} states in {elapsed:.1f} s, {len(received)} signals received")
    return code


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], Path(sys.argv[3]), Path(sys.argv[4])))
