# SPDX-License-Identifier: EPL-2.0
"""The per-user background service that makes ``rei run`` cost little more than its simulation (docs/performance.md).

A run needs a router (Crossbar: ~4 s to start), a monitor (a JVM compiling its rules: ~4 s) and its case generated
(a JVM: ~2 s). The service keeps them ready between runs:

* three **spare routers** (``daemon.SPARE_ROUTERS``), each started for a run id of its own with fresh secrets, the
  oldest of which the next run takes over whole (``rei.wamp.router.Router.adopt``): every run still has its own
  router, credentials and URIs, and the service starts the next spare at once;
* a **warm monitor JVM** and a **warm generator JVM** (``rei.run.jvm.JarServer``), in which each run's monitor and
  generation run as commands, with their classes loaded and rule bases built;
* a **warm Python** (``rei.service.warm``) that has imported the run, the simulation and the evaluator: a warm
  ``rei run`` and its simulation are forked from it.

It is started on demand by ``rei run`` (``rei.service.client.connect``), stops itself after ``IDLE_SECONDS`` without
a request, and is replaced when it died: the next run notices, says so in one line and starts a new one. Its folder
(``$REI_SERVICE_DIR``, default ``~/.cache/rei/service``, mode 0700) holds the control socket, its log and the
spare routers; only the user can connect. ``REI_SERVICE=off`` (or ``rei run --no-service``) runs everything the
run's own way, as before.
"""

from __future__ import annotations

import os
from pathlib import Path

#: Environment variable naming the service's folder.
DIR_ENV = "REI_SERVICE_DIR"
#: ``off`` (or ``0``, ``no``) disables the service: every run starts its own router and JVMs.
SWITCH_ENV = "REI_SERVICE"
#: Seconds without a request after which the service stops itself.
IDLE_SECONDS = 600.0
SOCKET_NAME = "service.sock"
PID_NAME = "service.pid"
LOG_NAME = "service.log"


def service_dir() -> Path:
    """The service's folder (not created here)."""
    given = os.environ.get(DIR_ENV)
    return Path(given) if given else Path.home() / ".cache" / "rei" / "service"


def fingerprint() -> str:
    """What a service's routers and JVMs were made from: the jars and the router's Python code. A run whose
    fingerprint differs (the user rebuilt or updated REI) replaces the service instead of using stale parts."""
    import hashlib

    from rei import toolchain

    here = Path(__file__).resolve().parents[1]
    files = [here / "wamp" / name for name in ("router.py", "crossbar_config.py", "auth.py", "crossbar_nodelay.py")]
    files += [here / "service" / "daemon.py", here / "run" / "jvm.py"]
    for role in ("monitor", "cli"):
        try:
            files.append(toolchain.find_jar(role))
        except toolchain.ToolchainError:
            pass
    digest = hashlib.sha256()
    for file in files:
        stat = file.stat()
        digest.update(f"{file}|{stat.st_size}|{stat.st_mtime_ns}\n".encode())
    return digest.hexdigest()[:16]


def enabled() -> bool:
    return os.environ.get(SWITCH_ENV, "").strip().lower() not in ("off", "0", "no", "false")


__all__ = ["DIR_ENV", "IDLE_SECONDS", "LOG_NAME", "PID_NAME", "SOCKET_NAME", "SWITCH_ENV", "enabled", "fingerprint", "service_dir"]
