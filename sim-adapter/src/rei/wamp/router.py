# SPDX-License-Identifier: EPL-2.0
"""Starting and stopping a private Crossbar.io router for one run (or one test session).

Why a private router per run: runs are independent, ports are chosen free on loopback, and nothing outlives the
run. Crossbar lives in its own venv (``scripts/setup-router.sh`` -> ``<repo>/.venv-router``) because its ~140
pinned dependencies must not leak into the simulation's environment: it is a tool REI starts, not a library it
imports.

Authentication (docs/security.md) is on by default: one WAMP-CRA role per component, scoped to the run's URIs,
secrets generated at start() into ``<run_dir>/auth/<role>.json`` (0600) - ``credentials(role)`` and
``auth_file(role)`` hand them out; anonymous access is off. ``Router(auth=False)`` is the anonymous loopback
router of transport tests and benchmarks.

The router listens on loopback only. ``bind=ADDRESS`` adds one WebSocket transport on another interface, which
requires TLS (``tls_cert``/``tls_key``) and authentication. Every transport uses the
``nodelaytcp:`` endpoint of :mod:`rei.wamp.crossbar_nodelay` by default, which switches Nagle's algorithm off on
the router's side of each connection (Crossbar 26.10.1 + autobahn 26.10.2 never do; see that module).
"""

from __future__ import annotations

import ipaddress
import json
import os
import shutil
import signal
import socket
import subprocess
import tempfile
import time
from collections.abc import Mapping, Sequence
from pathlib import Path
from types import TracebackType
from typing import Any, Self

from rei.lifetime import die_with_parent, stat_fields
from rei.private_dirs import private_dir
from rei.wamp.auth import (
    Credentials,
    load_credentials,
    new_secret,
    write_credentials,
    write_private,
)
from rei.wamp.crossbar_config import (
    ROLE_GRANTS,
    Role,
    Transport,
    TransportKind,
    anonymous_role,
    component_roles,
    node_config,
    wampcra_auth,
)

#: Environment variable naming the crossbar executable; wins over the repository's .venv-router.
CROSSBAR_ENV = "REI_CROSSBAR"
REALM = "rei"
_PLUGIN_SOURCE = Path(__file__).with_name("crossbar_nodelay.py")
_BIND_RETRIES = 3


class RouterError(RuntimeError):
    """The router could not be found, started or stopped; the message says why (with the log tail)."""


def find_crossbar(explicit: str | os.PathLike[str] | None = None) -> Path:
    """The crossbar executable: ``explicit``, else ``$REI_CROSSBAR``, else ``<repo>/.venv-router/bin/crossbar``."""
    if explicit is not None:
        candidates = [("argument", Path(explicit))]
    elif os.environ.get(CROSSBAR_ENV):
        candidates = [(f"${CROSSBAR_ENV}", Path(os.environ[CROSSBAR_ENV]))]
    else:
        roots = [*Path(__file__).resolve().parents, *Path.cwd().resolve().parents, Path.cwd().resolve()]
        candidates = [("repository", root / ".venv-router" / "bin" / "crossbar") for root in roots]
    for _, path in candidates:
        if path.is_file() and os.access(path, os.X_OK):
            return path
    where = ", ".join(f"{origin}: {path}" for origin, path in candidates[:3])
    raise RouterError(
        f"crossbar executable not found ({where}); run scripts/setup-router.sh or set {CROSSBAR_ENV}"
    )


def _is_loopback(host: str) -> bool:
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return host == "localhost"


def _free_ports(host: str, count: int) -> list[int]:
    """Ports the OS considers free now (held open together so they differ). A race remains: see start()."""
    sockets = []
    try:
        for _ in range(count):
            s = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
            s.bind((host, 0))
            sockets.append(s)
        return [s.getsockname()[1] for s in sockets]
    finally:
        for s in sockets:
            s.close()


def _accepts(host: str, port: int) -> bool:
    try:
        with socket.create_connection((host, port), timeout=0.2):
            return True
    except OSError:
        return False


class Router:
    """A Crossbar router process serving realm ``rei`` with msgpack on free loopback ports.

    Use as a context manager (``with Router() as router: ... router.ws_url``) or call start()/stop().
    ``run_dir`` receives the generated configuration, the plug-in and ``crossbar.log``; without it a temporary
    folder is used and removed on stop().
    """

    def __init__(
        self,
        *,
        crossbar: str | os.PathLike[str] | None = None,
        run_dir: str | os.PathLike[str] | None = None,
        realm: str = REALM,
        host: str = "127.0.0.1",
        kinds: Sequence[TransportKind] = ("websocket", "rawsocket"),
        nodelay: bool = True,
        roles: Sequence[Role] | None = None,
        auth: bool = True,
        run_id: str | None = None,
        bind: str | None = None,
        tls_cert: str | os.PathLike[str] | None = None,
        tls_key: str | os.PathLike[str] | None = None,
        startup_timeout: float = 30.0,
        stop_timeout: float = 10.0,
        die_with_parent: bool = False,
    ) -> None:
        if not _is_loopback(host):
            raise ValueError(f"router host {host!r} is not loopback; use bind=ADDRESS (with TLS) to expose it")
        tls = check_bind(bind, tls_cert, tls_key)
        if tls is not None and not auth:
            raise ValueError("a router reachable from other hosts must authenticate (auth=True)")
        if roles is not None and auth:
            raise ValueError("roles are generated from the run id when auth=True; pass auth=False for custom roles")
        if not kinds or len(set(kinds)) != len(kinds):
            raise ValueError(f"transport kinds must be distinct and non-empty: {kinds!r}")
        self._crossbar_arg = crossbar
        # absolute: crossbar runs with the run folder as its working directory, where a relative path breaks
        self._run_dir_arg = Path(run_dir).resolve() if run_dir is not None else None
        self.realm = realm
        self.host = host
        self._kinds = tuple(kinds)
        self.nodelay = nodelay
        self.auth = auth
        self.run_id = run_id
        if auth:
            self._roles = component_roles(run_id)
        else:
            self._roles = tuple(roles) if roles is not None else (anonymous_role(),)
        self._bind = bind if tls is not None else None
        self._tls = tls
        self._exposed: Transport | None = None
        self._secrets: dict[str, str] = {}
        # crossbar gets SIGTERM if the thread that starts it dies (rei.lifetime.die_with_parent): for a
        # router owned by a process's main thread, so a killed `rei run` leaves no router behind
        self._die_with_parent = die_with_parent
        self._startup_timeout = startup_timeout
        self._stop_timeout = stop_timeout
        self._process: subprocess.Popen[bytes] | None = None
        self._transports: dict[TransportKind, Transport] = {}
        self._run_dir: Path | None = None
        self._temporary = False
        self.restarts = 0

    # -- public API ------------------------------------------------------------------------------------------

    @property
    def pid(self) -> int | None:
        return self._process.pid if self._process is not None else None

    @property
    def run_dir(self) -> Path:
        if self._run_dir is None:
            raise RouterError("router not started")
        return self._run_dir

    @property
    def log_path(self) -> Path:
        return self.run_dir / "crossbar.log"

    def url(self, kind: TransportKind) -> str:
        """Client URL of a transport: ``ws://127.0.0.1:P/ws`` or ``rs://127.0.0.1:P``."""
        if kind not in self._transports:
            raise RouterError(f"router has no {kind} transport (started: {sorted(self._transports)})")
        return self._transports[kind].url()

    @property
    def exposed_url(self) -> str | None:
        """``wss://ADDRESS:P/ws`` of the TLS transport on the ``bind`` address, or None without one."""
        return self._exposed.url() if self._exposed is not None else None

    @property
    def roles(self) -> tuple[str, ...]:
        """The authids (= roles) clients can authenticate as; empty for an anonymous router."""
        return tuple(ROLE_GRANTS) if self.auth else ()

    def credentials(self, role: str) -> Credentials | None:
        """Credentials of ``role`` for this run (None on an anonymous router, which needs none)."""
        if not self.auth:
            return None
        if role not in ROLE_GRANTS:
            raise ValueError(f"unknown role {role!r}; roles: {', '.join(ROLE_GRANTS)}")
        if role not in self._secrets:
            raise RouterError("router not started: its secrets are generated by start()")
        return Credentials(role, self._secrets[role])

    def auth_file(self, role: str) -> Path | None:
        """The 0600 file holding ``role``'s credentials, for a child process (``--auth-file``)."""
        if self.credentials(role) is None:
            return None
        return self.run_dir / "auth" / f"{role}.json"

    @property
    def ws_url(self) -> str:
        return self.url("websocket")

    @property
    def rs_url(self) -> str:
        return self.url("rawsocket")

    def describe(self) -> dict[str, object]:
        """What ``adopt`` needs to take this running router over in another process (no secrets: those are in
        ``run_dir/auth``, readable by the user only)."""
        if self._process is None or self._run_dir is None:
            raise RouterError("router not started")
        if self._exposed is not None or not self.auth:
            raise RouterError("only an authenticating loopback router can be handed over")
        return {"run_id": self.run_id, "run_dir": str(self._run_dir), "realm": self.realm, "host": self.host,
                "nodelay": self.nodelay, "ports": {kind: t.port for kind, t in self._transports.items()},
                "pid": self._process.pid}

    @classmethod
    def adopt(cls, description: Mapping[str, Any], run_dir: Path | None = None) -> Router:
        """The running router ``describe()`` described, started by another process (the background service,
        rei.service), as if this process had started it: ``stop()`` stops it, ``restart()`` starts it again as
        this process's child. ``run_dir``: where its folder was moved to, if it was."""
        ports = dict(description["ports"])
        router = cls(run_dir=run_dir or Path(description["run_dir"]), realm=str(description["realm"]),
                     host=str(description["host"]), kinds=tuple(ports), nodelay=bool(description["nodelay"]),
                     run_id=str(description["run_id"]), die_with_parent=True)
        router._run_dir = router._run_dir_arg
        router._secrets = {role: load_credentials(router.run_dir / "auth" / f"{role}.json").secret
                           for role in ROLE_GRANTS}
        auth = wampcra_auth(router._secrets)
        router._transports = {kind: Transport(kind, int(port), interface=router.host, nodelay=router.nodelay,
                                              auth=auth) for kind, port in ports.items()}
        router._process = _Foreign(int(description["pid"]))  # type: ignore[assignment]
        return router

    def start(self) -> Router:
        """Start the router and return once every transport accepts connections (or raise RouterError)."""
        if self._process is not None:
            raise RouterError("router already started")
        executable = find_crossbar(self._crossbar_arg)
        if self._run_dir_arg is not None:
            self._run_dir = self._run_dir_arg
            self._run_dir.mkdir(parents=True, exist_ok=True)
        else:
            self._run_dir = Path(tempfile.mkdtemp(prefix="rei-router-"))
            self._temporary = True
        self._install_plugin()
        if self.auth:
            self._write_secrets()
        last_error: RouterError | None = None
        for _ in range(_BIND_RETRIES):
            try:
                self._launch(executable)
                self._wait_ready()
                return self
            except RouterError as error:
                last_error = error
                bind_race = "already in use" in self.log_tail(200)
                self._terminate()
                if not bind_race:
                    break
        self._cleanup_dir()
        assert last_error is not None
        raise last_error

    def poll(self) -> int | None:
        """The router's exit code if it has died (or was never started), None while it runs."""
        if self._process is None:
            return -1
        return self._process.poll()

    def restart(self) -> Router:
        """Start the router again on the same ports with the same configuration and secrets.

        For a router that died mid-run: clients that reconnect (``WampClient(reconnect=...)``, the monitor)
        find it at the URLs they already have. Whatever is left of the old process group is killed first.
        """
        if self._run_dir is None or not self._transports:
            raise RouterError("router not started: nothing to restart")
        self._terminate()
        self._launch(find_crossbar(self._crossbar_arg), reuse_ports=True)
        try:
            self._wait_ready()
        except RouterError:
            self._terminate()
            raise
        self.restarts += 1
        return self

    def stop(self) -> None:
        """SIGTERM the router's process group, SIGKILL it after ``stop_timeout``; never leaves a process.

        An adopted router still run by the service that started it is only sent SIGTERM: the service reaps it,
        and kills it should it outlive the run (rei.service.daemon), so the run does not wait for its shutdown."""
        if isinstance(self._process, _Foreign) and self._process.poll() is None:
            _signal_group(self._process.pid, signal.SIGTERM)
            self._process = None
            return
        self._terminate()
        self._cleanup_dir()

    def log_tail(self, lines: int = 40) -> str:
        """The last lines of the router's log (empty when there is none yet)."""
        if self._run_dir is None or not self.log_path.exists():
            return ""
        text = self.log_path.read_text(errors="replace").splitlines()
        return "\n".join(text[-lines:])

    def __enter__(self) -> Self:
        return self.start()

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        self.stop()

    # -- internals -------------------------------------------------------------------------------------------

    def _install_plugin(self) -> None:
        # Twisted finds endpoint parsers in every <sys.path entry>/twisted/plugins/ folder without __init__.py.
        plugins = self.run_dir / "plugins" / "twisted" / "plugins"
        plugins.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(_PLUGIN_SOURCE, plugins / _PLUGIN_SOURCE.name)

    def _write_secrets(self) -> None:
        """One fresh secret per role, each in its own 0600 file of a 0700 folder (docs/security.md)."""
        folder = private_dir(self.run_dir / "auth")
        self._secrets = {role: new_secret() for role in ROLE_GRANTS}
        for role, secret in self._secrets.items():
            write_credentials(folder / f"{role}.json", Credentials(role, secret))

    def _launch(self, executable: Path, *, reuse_ports: bool = False) -> None:
        if not reuse_ports:
            ports = _free_ports(self.host, len(self._kinds))
            auth = wampcra_auth(self._secrets) if self.auth else None
            self._transports = {
                kind: Transport(kind, port, interface=self.host, nodelay=self.nodelay, auth=auth)
                for kind, port in zip(self._kinds, ports, strict=True)
            }
            if self._bind is not None:
                (port,) = _free_ports(self._bind, 1)
                self._exposed = Transport("websocket", port, interface=self._bind, auth=auth, tls=self._tls)
        transports = list(self._transports.values())
        if self._exposed is not None:
            transports.append(self._exposed)
        cbdir = private_dir(self.run_dir / ".crossbar")
        config = node_config(self.realm, self._roles, transports)
        # the configuration holds every role's secret: the user's eyes only
        write_private(cbdir / "config.json", json.dumps(config, indent=2))
        env = dict(os.environ)
        env["PYTHONPATH"] = str(self.run_dir / "plugins")
        env.pop("PYTHONHOME", None)
        command = [
            str(executable),
            "start",
            "--cbdir",
            str(cbdir),
            "--color",
            "false",
            "--logformat",
            "standard",
            "--loglevel",
            "info",
        ]
        with open(self.log_path, "ab") as log:
            try:
                # Own session = own process group: stop() signals the node controller and its worker together.
                self._process = subprocess.Popen(
                    die_with_parent(command) if self._die_with_parent else command,
                    cwd=self.run_dir,
                    env=env,
                    stdin=subprocess.DEVNULL,
                    stdout=log,
                    stderr=subprocess.STDOUT,
                    start_new_session=True,
                )
            except OSError as error:
                raise RouterError(f"cannot start {executable}: {error}") from error

    def _wait_ready(self) -> None:
        assert self._process is not None
        deadline = time.monotonic() + self._startup_timeout
        listening = [*self._transports.values(), *([self._exposed] if self._exposed else [])]
        pending = {(t.interface, t.port) for t in listening}
        while pending:
            code = self._process.poll()
            if code is not None:
                raise RouterError(
                    f"crossbar exited with code {code} during start-up; log tail ({self.log_path}):\n"
                    + self.log_tail()
                )
            if time.monotonic() > deadline:
                raise RouterError(
                    f"crossbar did not accept connections on {sorted(pending)} within "
                    f"{self._startup_timeout:.0f} s; log tail ({self.log_path}):\n" + self.log_tail()
                )
            pending = {(host, port) for host, port in pending if not _accepts(host, port)}
            if pending:
                time.sleep(0.05)

    def _terminate(self) -> None:
        process, self._process = self._process, None
        if process is None:
            return
        pgid = process.pid  # start_new_session: the group id is the leader's pid
        _signal_group(pgid, signal.SIGTERM)
        try:
            process.wait(timeout=self._stop_timeout)
        except subprocess.TimeoutExpired:
            _signal_group(pgid, signal.SIGKILL)
            process.wait(timeout=self._stop_timeout)
        # The worker may outlive the controller by a moment; whatever remains in the group is killed.
        deadline = time.monotonic() + self._stop_timeout
        killed = False
        while _group_alive(pgid):
            if time.monotonic() > deadline:
                if killed:
                    raise RouterError(f"router process group {pgid} still alive after SIGKILL")
                _signal_group(pgid, signal.SIGKILL)
                killed = True
                deadline = time.monotonic() + self._stop_timeout
            time.sleep(0.05)

    def _cleanup_dir(self) -> None:
        if self._temporary and self._run_dir is not None:
            shutil.rmtree(self._run_dir, ignore_errors=True)
            self._run_dir = None
            self._temporary = False


#: The exit code of an adopted router whose parent reaped it before this process saw it.
UNKNOWN_EXIT = -255


class _Foreign:
    """A router process this process did not start (``Router.adopt``): watched through /proc, as Popen would be."""

    def __init__(self, pid: int) -> None:
        self.pid = pid
        self.returncode: int | None = None

    def poll(self) -> int | None:
        if self.returncode is None:
            fields = stat_fields(self.pid) or ["gone"]
            if fields[0] == "Z" and len(fields) > 49:  # a zombie's wait status (field 52), until its parent reaps it
                self.returncode = os.waitstatus_to_exitcode(int(fields[49]))
            elif fields[0] in ("Z", "X", "gone"):
                self.returncode = UNKNOWN_EXIT  # reaped by its parent (the service): the code is the parent's
        return self.returncode

    def wait(self, timeout: float | None = None) -> int:
        deadline = None if timeout is None else time.monotonic() + timeout
        while self.poll() is None:
            if deadline is not None and time.monotonic() > deadline:
                raise subprocess.TimeoutExpired(f"pid {self.pid}", timeout or 0.0)
            time.sleep(0.02)
        assert self.returncode is not None
        return self.returncode


def check_bind(
    bind: str | None, tls_cert: str | os.PathLike[str] | None, tls_key: str | os.PathLike[str] | None
) -> tuple[str, str] | None:
    """The (certificate, key) pair a ``bind`` address needs, or None when the router stays on loopback.

    Raises ValueError with the reason: a non-loopback address without TLS, half a TLS pair, a missing file.
    """
    if bind is None or _is_loopback(bind):
        if tls_cert is not None or tls_key is not None:
            raise ValueError("--tls-cert/--tls-key apply only with --bind ADDRESS (a non-loopback interface)")
        return None
    if tls_cert is None or tls_key is None:
        raise ValueError(
            f"binding the router to {bind} exposes it beyond this machine and requires TLS: "
            "give --tls-cert FILE and --tls-key FILE (PEM)"
        )
    try:
        ipaddress.ip_address(bind)
    except ValueError:
        raise ValueError(f"--bind {bind!r}: expected an IP address of one of this machine's interfaces") from None
    pair = (str(Path(tls_cert).resolve()), str(Path(tls_key).resolve()))
    for option, file in zip(("--tls-cert", "--tls-key"), pair, strict=True):
        if not Path(file).is_file():
            raise ValueError(f"{option} {file}: no such file")
    return pair


def _signal_group(pgid: int, sig: signal.Signals) -> None:
    try:
        os.killpg(pgid, sig)
    except ProcessLookupError:
        pass


def _group_alive(pgid: int) -> bool:
    try:
        os.killpg(pgid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True
