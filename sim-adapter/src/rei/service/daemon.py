# SPDX-License-Identifier: EPL-2.0
"""The service process: ``python -m rei.service [--idle SECONDS]`` (started by ``rei.service.client``).

Control protocol, one request per connection on ``service.sock`` (a JSON object per line each way):

    {"op": "hello"}                       -> {"pid": P, "fingerprint": F, "monitor": SOCKET, "cli": SOCKET,
                                              "idle": SECONDS (it stops after that long without a request)}
    {"op": "router", "owner": PID, "wait": S}
                                          -> {"router": Router.describe()} or {"router": null} (none within S)
    {"op": "status"}                      -> {"pid", "monitor", "cli", "spare": RUN_ID|null, "spares": N, "handed": N,
                                              "idle_left": SECONDS}  (not a request that keeps it alive)
    {"op": "stop"}                        -> {"stopping": true}

A router handed to a run belongs to it: the run stops it. Should the run die first, the service stops the router
once it sees the owner's pid gone. The main loop replaces a warm JVM that died and keeps SPARE_ROUTERS spare routers. A
service that stops (idle, `rei service stop`, replaced by a newer build) hands nothing out any more and gives its
folder to a new service at once, but stays until the runs holding its routers have ended: those routers, and the
live monitors in its JVM, go with it.
"""

from __future__ import annotations

import argparse
import contextlib
import fcntl
import json
import os
import secrets
import shutil
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path
from typing import Any

from rei.lifetime import alive
from rei.private_dirs import private_dir
from rei.run.jvm import JarServer, JarServerError, run_served
from rei.service import IDLE_SECONDS, LOG_NAME, PID_NAME, SOCKET_NAME, fingerprint, service_dir
from rei.service.warm import SOCKET_NAME as WARM_SOCKET
from rei.toolchain import ToolchainError
from rei.wamp.router import Router, RouterError

_TICK = 0.2
#: Spare routers kept ready, each slot refilled by a thread of its own as soon as it is taken: runs back to back (a
#: campaign of warm runs, a script) come faster than a router starts (~3.5 s, more at load). With one spare every
#: other run waited for the next (0.87 s of a 4 s run); with two refilled one at a time, warm runs forked from the
#: warm Python (~3.5 s) waited 1.2 s each from the third on (load 7).
SPARE_ROUTERS = 3
#: Seconds before a warm Python that failed is started again, doubling up to the most.
WARM_RETRY_MIN, WARM_RETRY_MAX = 1.0, 300.0
#: Seconds a stopping service waits for the runs that hold its routers (they stop them at their end).
RUNS_DRAIN = 1800.0


class Service:
    def __init__(self, folder: Path, idle: float = IDLE_SECONDS) -> None:
        self.folder, self.idle = folder, idle
        self.jvms: dict[str, JarServer | None] = {"monitor": None, "cli": None}
        self.spares: list[Router] = []  # oldest first
        self.starting = 0  # spares being started
        self.handed_any = False
        self.runs_ended = False  # a run that took a router has ended
        self.fillers: list[threading.Thread] = []
        self.gone = threading.Event()  # set only as the process ends: see _fill
        self.handed: list[tuple[Router, int]] = []  # routers runs took over, with the run's pid
        self.lock = threading.Lock()
        self.spare_ready = threading.Condition(self.lock)
        self.last_request = time.monotonic()
        self.stopping = threading.Event()
        self.jvms_up = threading.Event()
        self.fingerprint = fingerprint()
        self.warm: subprocess.Popen[bytes] | None = None  # rei.service.warm: runs forked from a warm Python
        self.warm_serving = False  # its socket has appeared
        self.warm_retry, self.warm_delay = 0.0, WARM_RETRY_MIN  # when the next may start, after a failed one
        self.retired: list[subprocess.Popen[bytes]] = []  # warm Pythons that no longer serve, with runs going on

    def run(self) -> int:
        private_dir(self.folder)
        with open(self.folder / "service.lock", "w") as lock:
            try:
                fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                _say("another service runs in this folder; leaving")
                return 0
            (self.folder / PID_NAME).write_text(f"{os.getpid()}\n", encoding="utf-8")
            control = self._listen()  # a run that connects now waits in the backlog until the JVMs are up

            def open_doors() -> None:  # the JVMs are up in a fraction of a second: the first run uses them
                for role in self.jvms:
                    self._keep_jvm(role)
                self.jvms_up.set()
                self._accept(control)

            threading.Thread(target=open_doors, name="service-accept", daemon=True).start()
            _say(f"started (pid {os.getpid()}) in {self.folder}")
            try:
                self._loop()  # starts the spare router at once, on this thread (it dies with this thread)
            finally:
                self.stopping.set()  # no more hand-overs
                self._await_starts()
                self._discard_spares()
                # a new service may start now; this one stays for the runs that hold its routers
                control.close()
                for name in (SOCKET_NAME, PID_NAME, WARM_SOCKET):
                    (self.folder / name).unlink(missing_ok=True)
                self._release_warm()
                fcntl.flock(lock, fcntl.LOCK_UN)
                self._await_runs()
                self._stop_jvms()
        return 0

    # -- the main loop: keep what runs need ready ----------------------------------------------------------------

    def _loop(self) -> None:
        while not self.stopping.is_set():
            for role in self.jvms if self.jvms_up.is_set() else ():
                self._keep_jvm(role)
            # not while the run that started the service goes on: its imports (~1.5 s of CPU) would slow that run
            if self.jvms_up.is_set() and (self.runs_ended or (self.spares and not self.handed)):
                self._keep_warm()
            self._reap_handed()
            self._drop_dead_spares()
            if not self.fillers:
                self.fillers = [threading.Thread(target=self._fill, name=f"service-spare-{slot}", daemon=True)
                                for slot in range(SPARE_ROUTERS)]
                for filler in self.fillers:
                    filler.start()
            with self.lock:
                idle = time.monotonic() - self.last_request > self.idle and not self.handed
            if idle:
                _say(f"idle for {self.idle:.0f} s; stopping")
                return
            self.stopping.wait(_TICK)

    def _keep_jvm(self, role: str) -> None:
        server = self.jvms[role]
        if server is not None and server.alive():
            return
        if server is not None:
            _say(f"the warm {role} JVM ended; starting a new one")
            server.stop()
        try:
            started = self.jvms[role] = JarServer(role, self.folder / f"{role}-jvm.log").start()
        except (JarServerError, ToolchainError, OSError) as error:
            _say(f"cannot start the warm {role} JVM: {error}")
            self.jvms[role] = None
            return
        if role == "monitor":  # build the default rules now, not in the first run that needs them
            threading.Thread(target=run_served, args=(started.socket, ["--compile-only"],
                                                      self.folder / "monitor-warm-up.log"),
                             name="service-warm-up", daemon=True).start()

    def _keep_warm(self) -> None:
        """The warm Python runs are forked from (rei.service.warm): a new one when it ended, or stopped serving (on a
        request from other code its name goes; it stays until the runs it forked have ended, and a new one serves
        meanwhile). One that failed is started again after a delay that doubles: each start imports for seconds."""
        self.retired = [process for process in self.retired if process.poll() is None]
        warm = self.warm
        if warm is not None:
            if warm.poll() is None:
                if (self.folder / WARM_SOCKET).exists():
                    self.warm_serving, self.warm_delay = True, WARM_RETRY_MIN
                    return
                if not self.warm_serving:
                    return  # still importing
                _say("the warm Python stopped serving (other code); a new one serves while its runs end")
                self.retired.append(warm)
            else:
                _say(f"the warm Python ended (code {warm.returncode})")
                if warm.returncode != 0 or not self.warm_serving:
                    self.warm_retry = time.monotonic() + self.warm_delay
                    self.warm_delay = min(2 * self.warm_delay, WARM_RETRY_MAX)
            self.warm = None
        if time.monotonic() < self.warm_retry:
            return
        self.warm_serving = False
        with open(self.folder / "warm.log", "ab") as log:
            self.warm = subprocess.Popen(
                [sys.executable, "-c", "import sys; from rei.service.warm import main; sys.exit(main())",
                 str(self.folder / WARM_SOCKET)], stdin=subprocess.PIPE, stdout=log, stderr=subprocess.STDOUT,
                start_new_session=True)

    def _release_warm(self) -> None:
        """No more forks; the runs forked already go on (a warm Python exits after its last)."""
        for warm in (self.warm, *self.retired):
            if warm is not None and warm.stdin is not None:
                with contextlib.suppress(OSError):
                    warm.stdin.close()

    def _drop_dead_spares(self) -> None:
        with self.lock:
            dead = [router for router in self.spares if router.poll() is not None]
            self.spares = [router for router in self.spares if router not in dead]
        for router in dead:
            _say("a spare router ended; starting a new one")
            self._discard(router)

    def _fill(self) -> None:
        """A slot's thread: starts a spare whenever fewer are ready or starting than SPARE_ROUTERS. It never returns
        while the process lives: a router dies with the thread that started it (``die_with_parent``), and routers
        handed to runs must outlive a stopping service's main loop."""
        while not self.stopping.is_set():
            with self.lock:
                # all at once when no run goes on, or when runs back to back have used up all spares but one (a
                # start takes longer than a warm run); else one at a time, and so during the run that started the
                # service (it waits for the first spare, and the others' start would slow its simulation)
                idle = self.handed_any and not self.handed
                wanted = len(self.spares) + self.starting < SPARE_ROUTERS and (
                    self.starting == 0 or idle or (self.runs_ended and len(self.spares) < 2))
                if wanted:
                    self.starting += 1
            if not wanted:
                self.stopping.wait(_TICK)
                continue
            try:
                self._start_spare()
            finally:
                with self.lock:
                    self.starting -= 1
        self.gone.wait()

    def _await_starts(self) -> None:
        """Until the spares being started are up (and discarded by their threads: the service stops)."""
        deadline = time.monotonic() + 60.0
        while time.monotonic() < deadline:
            with self.lock:
                if not self.starting:
                    return
            time.sleep(0.05)

    def _start_spare(self) -> None:
        run_id = secrets.token_hex(6)
        # not niced: the run that takes it over could not raise its priority again (measured: nice 10 while a run
        # goes on gave the same warm-run times)
        router = Router(run_dir=self.folder / "routers" / run_id, run_id=run_id, die_with_parent=True)
        try:
            router.start()
        except RouterError as error:
            _say(f"cannot start a spare router: {error}")
            self._discard(router)
            self.stopping.wait(5.0)  # not in a tight loop
            return
        with self.lock:
            if not self.stopping.is_set():
                self.spares.append(router)
                self.spare_ready.notify_all()
                return
        self._discard(router)  # started while the service stopped: nobody will take it

    def _reap_handed(self) -> None:
        with self.lock:
            handed = list(self.handed)
        for router, owner in handed:
            if router.poll() is not None:  # the run stopped it (polling also reaps it)
                self._forget(router)
            elif not alive(owner):  # usually shutting down on the run's SIGTERM; killed if it does not
                self._discard(router)
                self._forget(router)

    def _forget(self, router: Router) -> None:
        with self.lock:
            self.handed = [(r, o) for r, o in self.handed if r is not router]
            self.runs_ended = True
        # still here when the run's folder is on another file system (the run copied it at its end)
        folder = self.folder / "routers" / str(router.run_id)
        if folder.is_dir():
            shutil.rmtree(folder, ignore_errors=True)

    def _discard(self, router: Router) -> None:
        folder = router.run_dir if router.pid is not None else None
        with contextlib.suppress(RouterError):
            router.stop()
        if folder is not None and folder.is_dir() and folder.parent == self.folder / "routers":
            shutil.rmtree(folder, ignore_errors=True)  # only a spare's own folder: a handed one moved to its run

    def _discard_spares(self) -> None:
        with self.lock:
            spares, self.spares = self.spares, []
        for spare in spares:
            self._discard(spare)

    def _await_runs(self) -> None:
        """Until the runs holding routers of this service have ended (their routers die with this thread)."""
        if self.handed:
            _say(f"stopping once the {len(self.handed)} run(s) holding its routers end")
        deadline = time.monotonic() + RUNS_DRAIN
        while self.handed and time.monotonic() < deadline:
            self._reap_handed()
            time.sleep(_TICK)

    def _stop_jvms(self) -> None:
        for server in self.jvms.values():
            if server is not None:
                server.stop()

    # -- requests ---------------------------------------------------------------------------------------------

    def _listen(self) -> socket.socket:
        path = self.folder / SOCKET_NAME
        path.unlink(missing_ok=True)
        control = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        control.bind(str(path))
        control.listen(16)
        return control

    def _accept(self, control: socket.socket) -> None:
        while True:
            try:
                connection, _ = control.accept()
            except OSError:
                return
            threading.Thread(target=self._serve, args=(connection,), name="service-request", daemon=True).start()

    def _serve(self, connection: socket.socket) -> None:
        with connection, connection.makefile("rwb") as stream:
            try:
                request = json.loads(stream.readline() or b"{}")
                answer = self._answer(request)
            except (ValueError, KeyError, TypeError) as error:
                answer = {"error": f"bad request: {error}"}
            with contextlib.suppress(OSError):
                stream.write(json.dumps(answer).encode("utf-8") + b"\n")
                stream.flush()

    def _answer(self, request: dict[str, Any]) -> dict[str, Any]:
        op = request.get("op")
        if op == "status":
            with self.lock:
                ready = [router.run_id for router in self.spares if router.poll() is None]
                return {"pid": os.getpid(), "monitor": self._jvm_socket("monitor"), "cli": self._jvm_socket("cli"),
                        "spare": ready[0] if ready else None, "spares": len(ready), "handed": len(self.handed),
                        "idle_left": max(0.0, self.idle - (time.monotonic() - self.last_request))}
        with self.lock:
            self.last_request = time.monotonic()
        if op == "hello":
            return {"pid": os.getpid(), "fingerprint": self.fingerprint, "idle": self.idle,
                    **{role: self._jvm_socket(role) for role in self.jvms}}
        if op == "router":
            return {"router": self._hand_over(int(request["owner"]), float(request.get("wait", 0.0)))}
        if op == "stop":
            self.stopping.set()
            return {"stopping": True}
        return {"error": f"unknown op {op!r}"}

    def _jvm_socket(self, role: str) -> str | None:
        server = self.jvms[role]
        return str(server.socket) if server is not None and server.alive() else None

    def _hand_over(self, owner: int, wait: float) -> dict[str, Any] | None:
        deadline = time.monotonic() + wait
        with self.lock:
            if self.stopping.is_set():
                return None
            while not (ready := [router for router in self.spares if router.poll() is None]):
                left = deadline - time.monotonic()
                if left <= 0 or self.stopping.is_set():
                    return None
                self.spare_ready.wait(min(left, 0.5))
            router = ready[0]
            self.spares.remove(router)
            self.handed.append((router, owner))
            self.handed_any = True
        return router.describe()


def _say(text: str) -> None:
    print(f"{time.strftime('%Y-%m-%d %H:%M:%S')} rei service: {text}", flush=True)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m rei.service", description=__doc__.splitlines()[0])
    parser.add_argument("--idle", type=float, default=IDLE_SECONDS, help="stop after this many idle seconds")
    args = parser.parse_args(argv)
    folder = service_dir()
    try:
        return Service(folder, idle=args.idle).run()
    except OSError as error:
        print(f"rei service: {folder}: {error}", file=sys.stderr)
        return 2


__all__ = ["LOG_NAME", "Service", "main"]
