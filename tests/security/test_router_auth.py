# SPDX-License-Identifier: EPL-2.0
"""The router's access control (docs/security.md), against a real Crossbar router; nothing here may skip.

Every refusal is asserted twice: the router's answer (ABORT at join, ``wamp.error.not_authorized`` for an
acknowledged publish) and its effect (a subscriber of the topic receives nothing).
"""

from __future__ import annotations

import json
import os
import ssl
import stat
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from autobahn.wamp.exception import ApplicationError

from rei.wamp import Router, Topics, WampClient, WampError
from rei.wamp.auth import Credentials, load_credentials
from rei.wamp.crossbar_config import ROLE_GRANTS

RUN_ID = "security-run"
TOPICS = Topics(RUN_ID)
#: Time a refused message would have needed to arrive: loopback delivery takes ~1 ms.
QUIET_S = 0.5
JOIN_S = 10.0


@pytest.fixture(scope="module")
def router(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Router]:
    with Router(run_dir=tmp_path_factory.mktemp("security") / "router", run_id=RUN_ID) as running:
        yield running


def _client(router: Router, role: str, url: str | None = None) -> WampClient:
    return WampClient(url or router.rs_url, auth=router.credentials(role), connect_timeout=JOIN_S)


class _Inbox:
    """Events of one subscription, thread-safe."""

    def __init__(self) -> None:
        self.items: list[dict] = []
        self.arrived = threading.Event()

    def __call__(self, payload: dict) -> None:
        self.items.append(payload)
        self.arrived.set()


def _assert_refused_and_unseen(router: Router, publisher_role: str, subscriber_role: str, topic: str) -> None:
    inbox = _Inbox()
    with _client(router, subscriber_role, router.ws_url) as subscriber, _client(router, publisher_role) as publisher:
        subscriber.subscribe(topic, inbox)
        with pytest.raises(ApplicationError) as refused:
            publisher.publish_acknowledged(topic, {"forged": publisher_role})
        assert refused.value.error == "wamp.error.not_authorized", refused.value
        publisher.publish(topic, {"forged": publisher_role, "ack": False})  # fire-and-forget: dropped silently
        publisher.flush()
        time.sleep(QUIET_S)
        assert inbox.items == [], f"{subscriber_role} received {publisher_role}'s forged events on {topic}"


@pytest.mark.parametrize("transport", ["ws", "rs"])
def test_anonymous_client_cannot_join(router: Router, transport: str):
    url = router.ws_url if transport == "ws" else router.rs_url
    with pytest.raises(WampError, match="no_auth_method|not_authorized"):
        WampClient(url, connect_timeout=JOIN_S).start()


@pytest.mark.parametrize("credentials", [
    Credentials("monitor", "not-the-secret"),
    Credentials("root", "whatever"),
    Credentials("monitor", "not-the-secret", method="ticket"),
], ids=["wrong-secret", "unknown-authid", "ticket-not-offered"])
def test_wrong_credentials_are_rejected(router: Router, credentials: Credentials):
    with pytest.raises(WampError, match="not_authorized|no_auth_method|authentication_failed"):
        WampClient(router.ws_url, auth=credentials, connect_timeout=JOIN_S).start()


def test_a_secret_of_another_role_does_not_open_this_role(router: Router):
    evaluator = router.credentials("evaluator")
    assert evaluator is not None
    with pytest.raises(WampError, match="not_authorized"):
        WampClient(router.ws_url, auth=Credentials("monitor", evaluator.secret), connect_timeout=JOIN_S).start()


@pytest.mark.parametrize("role", ["viewer", "evaluator"])
@pytest.mark.parametrize("topic", [TOPICS.state, TOPICS.signal, TOPICS.mission])
def test_read_only_roles_cannot_publish(router: Router, role: str, topic: str):
    subscriber = "monitor" if topic != TOPICS.signal else "evaluator"
    _assert_refused_and_unseen(router, role, subscriber, topic)


def test_monitor_cannot_publish_state(router: Router):
    _assert_refused_and_unseen(router, "monitor", "evaluator", TOPICS.state)


@pytest.mark.parametrize("role", ["collector", "simulation"])
def test_collector_cannot_publish_signals(router: Router, role: str):
    _assert_refused_and_unseen(router, role, "evaluator", TOPICS.signal)


def test_permissions_are_scoped_to_the_run(router: Router):
    other = Topics("another-run")
    with _client(router, "collector") as collector, _client(router, "evaluator") as evaluator:
        with pytest.raises(ApplicationError, match="not_authorized"):
            collector.publish_acknowledged(other.state, {"t": 0})
        with pytest.raises(ApplicationError, match="not_authorized"):
            evaluator.subscribe(other.signal, lambda payload: None)
        with pytest.raises(ApplicationError, match="not_authorized"):
            collector.publish_acknowledged("rei.admin", {})


def test_roles_can_do_what_they_need(router: Router):
    """The positive control of the refusals above: the same subscribers do receive the legitimate events."""
    states, signals = _Inbox(), _Inbox()
    with _client(router, "monitor", router.ws_url) as monitor, _client(router, "evaluator") as evaluator, \
            _client(router, "simulation") as simulation, _client(router, "viewer", router.ws_url) as viewer:
        monitor.subscribe(TOPICS.state, states)
        evaluator.subscribe(TOPICS.signal, signals)
        viewer.subscribe(TOPICS.state, lambda payload: None)
        monitor.register(TOPICS.snapshot, lambda: "ok")
        simulation.register(TOPICS.config, lambda: {"world": None})
        simulation.publish_acknowledged(TOPICS.state, {"t": 1.0})
        monitor.publish_acknowledged(TOPICS.signal, {"signal": "SIG_TEST"})
        assert states.arrived.wait(5) and signals.arrived.wait(5)
        assert evaluator.call(TOPICS.snapshot) == "ok"
        assert monitor.call(TOPICS.config) == {"world": None}
        with pytest.raises(ApplicationError, match="not_authorized"):
            viewer.call(TOPICS.snapshot)
        with pytest.raises(ApplicationError, match="not_authorized"):
            viewer.register(TOPICS.snapshot + "_x", lambda: None)
        with pytest.raises(ApplicationError, match="not_authorized"):
            monitor.register(TOPICS.config + "_x", lambda: None)
    assert states.items == [{"t": 1.0}] and signals.items == [{"signal": "SIG_TEST"}]


def test_secrets_are_per_run_per_role_and_private(router: Router, tmp_path: Path):
    auth = router.run_dir / "auth"
    assert stat.S_IMODE(auth.stat().st_mode) == 0o700
    files = sorted(auth.iterdir())
    assert [f.stem for f in files] == sorted(ROLE_GRANTS)
    for file in files:
        assert stat.S_IMODE(file.stat().st_mode) == 0o600, file
        assert file.stat().st_uid == os.getuid()
    config = router.run_dir / ".crossbar" / "config.json"
    assert stat.S_IMODE(config.stat().st_mode) == 0o600
    assert stat.S_IMODE(config.parent.stat().st_mode) == 0o700
    secrets = {role: load_credentials(router.auth_file(role) or "").secret for role in ROLE_GRANTS}
    assert len(set(secrets.values())) == len(secrets), "every role has its own secret"
    assert all(len(s) >= 40 for s in secrets.values())
    # never on a command line (/proc/PID/cmdline is readable by every user)
    cmdline = Path(f"/proc/{router.pid}/cmdline").read_bytes().decode(errors="replace")
    assert not any(s in cmdline for s in secrets.values())
    # WAMP-CRA only, anonymous off, on every transport
    worker = json.loads(config.read_text())["workers"][0]
    assert all(set(t["auth"]) == {"wampcra"} for t in worker["transports"])
    assert "anonymous" not in [r["name"] for r in worker["realms"][0]["roles"]]
    # another run, other secrets
    with Router(run_dir=tmp_path / "other", run_id=RUN_ID) as other:
        assert all(other.credentials(r).secret != secrets[r] for r in ROLE_GRANTS)  # type: ignore[union-attr]


def test_credentials_files_readable_by_others_are_refused(router: Router, tmp_path: Path):
    copy = tmp_path / "monitor.json"
    copy.write_text((router.auth_file("monitor") or Path()).read_text())
    copy.chmod(0o644)
    with pytest.raises(ValueError, match="readable by other users"):
        load_credentials(copy)


@pytest.mark.parametrize("address", ["0.0.0.0", "192.0.2.1"])
def test_binding_another_interface_without_tls_is_refused(address: str, tmp_path: Path):
    with pytest.raises(ValueError, match="requires TLS: give --tls-cert FILE and --tls-key FILE"):
        Router(bind=address)
    with pytest.raises(ValueError, match="must authenticate"):
        Router(bind=address, auth=False, tls_cert=__file__, tls_key=__file__)
    with pytest.raises(ValueError, match="not loopback"):
        Router(host=address)
    for command in ("sim", "run"):
        result = subprocess.run(
            [sys.executable, "-m", "rei.cli", command, str(tmp_path / "case"), "-o", str(tmp_path / "out"),
             "--bind", address], check=False, capture_output=True, text=True, timeout=60)
        assert result.returncode == 2, result
        assert "requires TLS" in result.stderr and "--tls-cert" in result.stderr
        assert not (tmp_path / "out").exists(), "refused before anything was written"


def _self_signed(folder: Path) -> tuple[Path, Path]:
    cert, key = folder / "cert.pem", folder / "key.pem"
    subprocess.run(["openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-days", "1", "-subj", "/CN=rei-test",
                    "-addext", "subjectAltName=IP:127.0.0.1", "-keyout", str(key), "-out", str(cert)],
                   check=True, capture_output=True, timeout=60)
    return cert, key


def test_rei_run_with_bind_and_tls_exposes_the_router_over_wss_and_still_judges_the_run(
        run_cli, repo_root: Path, tmp_path: Path):
    cert, key = _self_signed(tmp_path)
    result = run_cli("run", repo_root / "examples" / "simple_navigation.rei", "-o", tmp_path / "out", "--no-humans",
                     "--bind", "0.0.0.0", "--tls-cert", cert, "--tls-key", key, timeout=300)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "router: wss://0.0.0.0:" in result.stdout and "(TLS, authenticated)" in result.stdout
    config = json.loads((tmp_path / "out" / "router" / ".crossbar" / "config.json").read_text())
    endpoints = [t["endpoint"] for worker in config["workers"] for t in worker.get("transports", [])]
    exposed = [e for e in endpoints if e.get("interface") == "0.0.0.0"]
    assert len(exposed) == 1 and "tls" in exposed[0]
    local = [e for e in endpoints if e not in exposed]  # the nodelay endpoints name their interface in a string
    assert len(local) == 2 and all("interface=127.0.0.1" in e["server_string"] for e in local)


def test_bind_with_tls_serves_authenticated_wss_only(tmp_path: Path):
    cert, key = _self_signed(tmp_path)
    with Router(run_dir=tmp_path / "router", run_id=RUN_ID, bind="0.0.0.0", tls_cert=cert, tls_key=key) as router:
        assert router.exposed_url is not None and router.exposed_url.startswith("wss://0.0.0.0:")
        url = router.exposed_url.replace("0.0.0.0", "127.0.0.1")
        context = ssl.create_default_context(cafile=str(cert))
        inbox = _Inbox()
        with WampClient(url, auth=router.credentials("viewer"), ssl_context=context, connect_timeout=JOIN_S) as viewer, \
                _client(router, "simulation") as simulation:
            viewer.subscribe(TOPICS.state, inbox)
            simulation.publish_acknowledged(TOPICS.state, {"t": 2.0})
            assert inbox.arrived.wait(5) and inbox.items == [{"t": 2.0}]
            with pytest.raises(ApplicationError, match="not_authorized"):
                viewer.publish_acknowledged(TOPICS.signal, {"forged": True})
        with pytest.raises(WampError, match="no_auth_method"):
            WampClient(url, ssl_context=context, connect_timeout=JOIN_S).start()
        with pytest.raises(WampError):  # plain WebSocket on the TLS port: no handshake
            WampClient(url.replace("wss://", "ws://"), auth=router.credentials("viewer"), connect_timeout=5).start()
        # the loopback transports stay loopback
        assert router.ws_url.startswith("ws://127.0.0.1:") and router.rs_url.startswith("rs://127.0.0.1:")


# -- the external system under test (docs/sut.md) ----------------------------------------------------------------


def _sut(name: str) -> str:
    return f"rei.run.{RUN_ID}.sut.{name}"


def test_the_sut_role_sees_what_a_robot_sees_and_answers_but_never_the_ground_truth(router: Router):
    commands, ticks = _Inbox(), _Inbox()
    with _client(router, "simulation") as simulation, _client(router, "sut", router.ws_url) as sut:
        simulation.subscribe(_sut("command"), commands)
        simulation.register(_sut("hello"), lambda *args: {"protocol": 1})
        sut.subscribe(_sut("tick"), ticks)
        assert sut.call(_sut("hello"), {"name": "test"}) == {"protocol": 1}
        simulation.publish_acknowledged(_sut("tick"), {"tick": 0})
        sut.publish_acknowledged(_sut("command"), {"tick": 0, "v": 0.0, "w": 0.0})
        assert ticks.arrived.wait(5) and commands.arrived.wait(5)
        for topic in (TOPICS.state, TOPICS.mission, TOPICS.signal):  # ground truth and verdict inputs
            with pytest.raises(ApplicationError, match="not_authorized"):
                sut.subscribe(topic, lambda payload: None)
        for procedure in (TOPICS.config, TOPICS.mission_info, TOPICS.snapshot):
            with pytest.raises(ApplicationError, match="not_authorized"):
                sut.call(procedure)
        with pytest.raises(ApplicationError, match="not_authorized"):  # it cannot play the simulation
            sut.publish_acknowledged(_sut("tick"), {"tick": 1})
        with pytest.raises(ApplicationError, match="not_authorized"):
            sut.register(_sut("hello") + "_x", lambda: None)
    assert commands.items == [{"tick": 0, "v": 0.0, "w": 0.0}]


@pytest.mark.parametrize("topic", [TOPICS.state, TOPICS.mission, TOPICS.signal])
def test_the_sut_cannot_forge_what_verdicts_read(router: Router, topic: str):
    _assert_refused_and_unseen(router, "sut", "evaluator", topic)


def test_a_sut_with_another_run_s_credentials_or_none_is_refused(router: Router, tmp_path: Path):
    with Router(run_dir=tmp_path / "other", run_id="another-run") as other:
        stolen = other.credentials("sut")
        with pytest.raises(WampError, match="not_authorized|authentication_failed"):
            WampClient(router.ws_url, auth=stolen, connect_timeout=JOIN_S).start()
    # and the kit's own check: no credential file, no join
    script = "from rei.sut.client import SystemUnderTest, main\nmain(SystemUnderTest())\n"
    env = {**os.environ, "REI_ROUTER_URL": router.ws_url, "REI_RUN_ID": RUN_ID}
    env.pop("REI_AUTH_FILE", None)
    result = subprocess.run([sys.executable, "-c", script], check=False, env=env, capture_output=True, text=True,
                            timeout=60)
    assert result.returncode == 2
    assert "no_auth_method" in result.stderr or "not_authorized" in result.stderr, result.stderr
