# SPDX-License-Identifier: EPL-2.0
"""`rei campaign --ray` on a real multi-node Ray cluster on this machine whose worker nodes share nothing with the
driver but Ray: a node in a mount namespace of its own, where the driver's folder (spec, OUT) and this checkout are
hidden under empty tmpfs mounts and REI is the one installed from its wheel (scripts/build-wheel.sh, carrying the
monitor jar) into a virtual environment of the node's, runs every run and the campaign's files arrive in OUT
through Ray, its streams byte for byte those of a local campaign; a node without Java is named at connect time;
and a worker node whose raylet is killed in the middle of a campaign loses nothing (its runs are tried again on
the other node, each recorded once, with the try that gave it). The head has no CPU, so every run goes to a
worker node. Real simulation, monitor jar and evaluator."""

from __future__ import annotations

import ast
import contextlib
import csv
import json
import os
import re
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import sysconfig
import tempfile
import time
import zipfile
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pytest

REPO_ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = REPO_ROOT / "examples" / "simple_navigation.rei"
RAY = Path(sys.executable).parent / "ray"

USER_PATTERN = """\
atomicEvent userTaskStarts() as mission TASK_START
signal SIG_USER_TASK_STARTED utility 7
rule "User: a task starts" on userTaskStarts emits SIG_USER_TASK_STARTED
"""


@dataclass(frozen=True)
class NodeEnv:
    """A worker node's own Python environment: a virtual environment with REI installed from its wheel. Its
    third-party packages (Ray, pybullet, numpy...) are the driver's, read-only: ``deps`` is bind-mounted at
    ``stash`` in the node's namespace, where the venv's .pth file finds them, for downloading and unpacking ~1 GB
    of wheels would cost each test run minutes. The driver's editable REI there is never imported: .pth files are
    processed in site directories only, not in a folder a .pth file adds."""

    python: Path
    deps: Path
    stash: Path
    wheel: Path


@pytest.fixture(scope="module")
def node_env(tmp_path_factory: pytest.TempPathFactory) -> NodeEnv:
    """REI's wheel, built as a user builds it, installed into a venv of the nodes' (~20 s)."""
    root = tmp_path_factory.mktemp("node-env")
    built = subprocess.run(["bash", str(REPO_ROOT / "scripts" / "build-wheel.sh"), "-o", str(root / "dist")],
                           capture_output=True, text=True, timeout=300, check=False)
    assert built.returncode == 0, built.stderr
    wheel = Path(built.stdout.strip().splitlines()[-1])
    venv = root / "venv"
    base = Path(sys.executable).resolve()  # the interpreter the driver's venv was made from
    subprocess.run([str(base), "-m", "venv", "--without-pip", str(venv)], check=True, timeout=120)
    # pip of the driver's venv installs into the node's interpreter: REI alone (its requirements are the stash's)
    subprocess.run([sys.executable, "-m", "pip", "--python", str(venv / "bin" / "python"), "install", "--quiet",
                    "--no-deps", "--no-index", str(wheel)], check=True, timeout=300)
    stash = root / "deps"
    stash.mkdir()
    site = next((venv / "lib").glob("python3*/site-packages"))
    (site / "driver-deps.pth").write_text(f"{stash}\n", encoding="utf-8")
    deps = Path(sysconfig.get_paths()["purelib"]).resolve()  # the driver's site-packages
    return NodeEnv(venv / "bin" / "python", deps, stash, wheel)


def _without_java(folder: Path) -> str:
    """A PATH of one folder: symbolic links to every program of this PATH but java."""
    folder.mkdir()
    for directory in os.environ.get("PATH", "").split(os.pathsep):
        with contextlib.suppress(OSError):
            for program in Path(directory).iterdir():
                link = folder / program.name
                if program.name != "java" and not link.exists() and not link.is_symlink():
                    link.symlink_to(program)
    assert shutil.which("java", path=str(folder)) is None
    return str(folder)


@dataclass
class Cluster:
    root: Path  # RAY_TMPDIR of every process of the cluster, and the nodes' own TMPDIRs below it
    env: dict[str, str]  # what a client needs, RAY_ADDRESS among it
    log: Path
    processes: dict[str, subprocess.Popen[bytes]] = field(default_factory=dict)

    def add_node(self, name: str, *, hide: Path | None = None, own: NodeEnv | None = None,
                 path: str | None = None) -> Path:
        """A worker node of 1 CPU offering one 'rei' (the resource REI's runs ask for) whose processes' temporary
        folder is a folder of its own (returned); ``hide``: the node runs in a mount namespace of its own where that
        folder is an empty tmpfs; ``own``: the node runs the Python environment of REI's wheel, and this checkout is
        hidden too; ``path``: the node's PATH."""
        tmp = self.root / name
        tmp.mkdir()
        ray = [str(RAY)] if own is None else [str(own.python), "-m", "ray.scripts.scripts"]
        command = [*ray, "start", "--block", f"--address={self.env['RAY_ADDRESS']}", "--num-cpus=1",
                   '--resources={"rei": 1}', "--node-ip-address=127.0.0.1", "--disable-usage-stats", "--object-store-memory=80000000"]
        env = {**os.environ, **self.env, "TMPDIR": str(tmp)}
        if own is not None:  # nothing of the driver's Python but the stash: no REI_HOME, no venv of the checkout's
            for key in ("REI_HOME", "VIRTUAL_ENV", "PYTHONPATH", "REI_CROSSBAR"):
                env.pop(key, None)
            env["PATH"] = os.pathsep.join([str(own.python.parent), *(
                p for p in env["PATH"].split(os.pathsep) if not p.startswith(str(REPO_ROOT)))])
        if path is not None:
            env["PATH"] = os.pathsep.join([str(own.python.parent), path]) if own is not None else path
        if hide is not None or own is not None:  # unshare execs sh, sh execs ray: the process is the node's `ray start`
            hidden = [str(p) for p in (hide, REPO_ROOT if own is not None else None) if p is not None]
            script = 'set -e; for h in "$@"; do [ "$h" = -- ] && break; mount -t tmpfs tmpfs "$h"; done; '
            if own is not None:  # the driver's packages, read-only, where the node's .pth file names them
                script = (f'mount --bind "{own.deps}" "{own.stash}"; mount -o remount,bind,ro "{own.stash}"; '
                          + script)
            script += 'while [ "$1" != -- ]; do shift; done; shift; exec "$@"'
            command = ["/usr/bin/unshare", "-m", "/bin/sh", "-c", script, "sh", *hidden, "--", *command]
        self.processes[name] = _start(command, self.log, env)
        return tmp

    def node_root(self, name: str) -> Path:
        """The node's view of the file system (its `ray start`'s)."""
        return Path(f"/proc/{self.processes[name].pid}/root")

    def wait_for_cpus(self, cpus: int, timeout: float = 120) -> None:
        script = "import ray; ray.init(logging_level='ERROR'); print(int(ray.cluster_resources().get('CPU', 0)))"
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            probe = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120,
                                   env={**os.environ, **self.env}, check=False)
            if probe.returncode == 0 and probe.stdout.strip().splitlines()[-1:] == [str(cpus)]:
                return
            time.sleep(2)
        raise AssertionError(f"the cluster never had {cpus} CPUs: {self.log.read_text(errors='replace')[-3000:]}")

    def nodes_with_cpu(self) -> list[tuple[str, str]]:
        """(address, the first 12 digits of the id) of each alive node with a CPU, as Ray has them."""
        script = ("import ray; ray.init(logging_level='ERROR'); print([(n['NodeManagerAddress'], n['NodeID'][:12]) "
                  "for n in ray.nodes() if n['Alive'] and n['Resources'].get('CPU')])")
        probe = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120,
                               env={**os.environ, **self.env}, check=True)
        return [tuple(node) for node in ast.literal_eval(probe.stdout.strip().splitlines()[-1])]

    def raylet(self, name: str) -> int:
        """The pid of the node's raylet (a child of its `ray start`)."""
        parent = self.processes[name].pid
        for stat in Path("/proc").glob("[0-9]*/stat"):
            with contextlib.suppress(OSError):
                text = stat.read_text()
                comm, fields = text[text.index("(") + 1:text.rindex(")")], text[text.rindex(")") + 2:].split()
                if comm == "raylet" and int(fields[1]) == parent:
                    return int(stat.parent.name)
        raise AssertionError(f"no raylet under node {name}")


def _start(command: list[str], log: Path, env: dict[str, str]) -> subprocess.Popen[bytes]:
    with open(log, "ab") as out:
        return subprocess.Popen(command, stdout=out, stderr=subprocess.STDOUT, start_new_session=True, env=env)


def _stop(process: subprocess.Popen[bytes]) -> None:
    """As Ray stops a blocking `ray start`: SIGTERM, on which it stops its own processes; then whatever of its
    process group outlived it is killed (`ray stop` would stop every Ray of this user)."""
    with contextlib.suppress(ProcessLookupError):
        process.send_signal(signal.SIGTERM)
    with contextlib.suppress(subprocess.TimeoutExpired):
        process.wait(60)
    with contextlib.suppress(ProcessLookupError):
        os.killpg(process.pid, signal.SIGKILL)
    process.wait()


def _leftovers(root: Path) -> list[str]:
    """Processes that still name the cluster's folder in their command line or environment."""
    found = []
    for proc in Path("/proc").glob("[0-9]*"):
        with contextlib.suppress(OSError):
            if str(root).encode() in (proc / "cmdline").read_bytes() + (proc / "environ").read_bytes():
                command = (proc / "cmdline").read_bytes().replace(b"\0", b" ")[:200]
                found.append(f"{proc.name}: {command!r}")
    return found


@pytest.fixture
def cluster(tmp_path: Path) -> Iterator[Cluster]:
    """A Ray head on loopback with no CPU (so runs go to worker nodes only), its files in a folder of the test's
    own (short: Ray's unix sockets live below it), with a token of its own; every process it and its nodes
    started is stopped afterwards, none is left naming that folder, and the folder is removed."""
    root = Path(tempfile.mkdtemp(prefix="rei-rc-"))
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    token = root / "auth_token"
    token.write_text(secrets.token_hex(32), encoding="ascii")
    env = {"RAY_TMPDIR": str(root), "RAY_AUTH_MODE": "token", "RAY_AUTH_TOKEN_PATH": str(token),
           # a lost node is noticed within seconds rather than Ray's default half minute
           "RAY_health_check_period_ms": "1000", "RAY_health_check_failure_threshold": "3"}
    cluster = Cluster(root, {**env, "RAY_ADDRESS": f"127.0.0.1:{port}"}, tmp_path / "ray.log")
    try:
        cluster.processes["head"] = _start(
            [str(RAY), "start", "--head", "--block", f"--port={port}", "--node-ip-address=127.0.0.1",
             "--num-cpus=0", "--include-dashboard=false", "--disable-usage-stats",
             "--object-store-memory=80000000", f"--temp-dir={root / 'ray'}"],
            cluster.log, {**os.environ, **env})
        yield cluster
    finally:
        for name in sorted(cluster.processes, key=lambda n: n == "head"):  # worker nodes first
            _stop(cluster.processes[name])
        left = _leftovers(root)
        for line in left:
            with contextlib.suppress(ProcessLookupError, ValueError):
                os.kill(int(line.split(":")[0]), signal.SIGKILL)
        shutil.rmtree(root, ignore_errors=True)
        assert not left, f"Ray processes outlived the test: {left}"


def _runs_reis_wheel(cluster: Cluster, name: str, own: NodeEnv) -> None:
    """The node is its own venv's Python, and this checkout is nothing to it: REI can only be the wheel's."""
    node = cluster.processes[name].pid
    assert Path(f"/proc/{node}/cmdline").read_bytes().split(b"\0")[0] == bytes(own.python)
    root = cluster.node_root(name)
    assert (REPO_ROOT / "pom.xml").is_file() and list((root / REPO_ROOT.relative_to("/")).iterdir()) == []
    assert (root / own.stash.relative_to("/") / "ray").is_dir()  # its third-party packages, read-only
    mounts = [line.split() for line in Path(f"/proc/{node}/mountinfo").read_text().splitlines()]
    assert [m[5].split(",")[0] for m in mounts if m[4] == str(own.stash)] == ["ro"], mounts


def _spec(folder: Path, repetitions: int, script: str, more: str = "") -> Path:
    (folder / "short.txt").write_text(script, encoding="utf-8")
    (folder / "mine").mkdir(exist_ok=True)
    (folder / "mine" / "tasks.vepl").write_text(USER_PATTERN, encoding="utf-8")
    (folder / "utilities.yaml").write_text("SIG_USER_TASK_STARTED: 9\n", encoding="utf-8")
    spec = folder / "spec.yaml"
    spec.write_text(f"""
name: shared-nothing
patterns: mine
utilities: utilities.yaml
groups:
  - name: example
    cases: [{EXAMPLE}]
    repetitions: {repetitions}
    variants: [{{name: short, humans: false, controller: "script:{folder / 'short.txt'}"}}]
{more}""", encoding="utf-8")
    return spec


def _runs(out: Path) -> list[dict[str, str]]:
    with open(out / "runs.csv", newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def _campaign(run_cli: Any, spec: Path, out: Path, cluster: Cluster, timeout: float = 300) -> Any:
    return run_cli("campaign", spec, "-o", out, "--ray", cluster.env["RAY_ADDRESS"], timeout=timeout,
                   env=cluster.env)


def test_a_node_that_cannot_see_out_runs_the_campaign_as_a_local_one(tmp_path: Path, cluster: Cluster,
                                                                    run_cli: Any, node_env: NodeEnv) -> None:
    started = time.monotonic()
    work = tmp_path / "driver"  # the spec, its patterns, utilities and script, and OUT: hidden from the node
    work.mkdir()
    # and a room on an occupancy map: its generated case holds the map, which travels with it
    spec = _spec(work, 2, "1.0 0.1 0.0\n", f"""  - name: map
    cases: [{REPO_ROOT / "examples" / "maps" / "two_rooms.rei"}]
    variants: [{{name: short, humans: false, controller: "script:{work / 'short.txt'}"}}]
""")
    node_tmp = cluster.add_node("node1", hide=work, own=node_env)
    cluster.wait_for_cpus(1)
    node_root = cluster.node_root("node1")
    assert (work / "spec.yaml").is_file() and not (node_root / (work / "spec.yaml").relative_to("/")).exists()
    _runs_reis_wheel(cluster, "node1", node_env)
    out = work / "out"
    result = _campaign(run_cli, spec, out, cluster)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "on 1 ray worker(s)" in result.stdout
    assert not (node_root / out.relative_to("/")).exists()  # OUT never was the node's to see
    rows = _runs(out)
    assert [(r["status"], r["attempt"]) for r in rows] == [("COMPLETED", "1")] * 3, rows
    assert (out / "cases" / "two_rooms" / "map.pgm").is_file()
    assert list(node_tmp.glob("rei-run-*")) == []  # the node's temporary run folders are gone
    assert len(list(node_tmp.glob("rei-node-monitor-*"))) == 1  # its Ray worker's warm monitor JVM's folder
    cluster_time = time.monotonic() - started
    moved = json.loads((out / "campaign.json").read_text(encoding="utf-8"))["metrics"]["transfer"]
    case = sum(p.stat().st_size for name in ("simple_navigation", "two_rooms")
               for p in (out / "cases" / name).rglob("*") if p.is_file())
    runs = sum(p.stat().st_size for p in (out / "runs").rglob("*") if p.is_file() and p.name not in (
        "task.json", "result.json"))
    # the case once for its two runs, the user's files with each; the run folders back (their summaries then name
    # the driver's paths instead of the node's)
    assert case < moved["sent"] < case + 8192 and abs(moved["received"] - runs) < 2048, (moved, case, runs)
    print(f"moved: {moved['sent']} bytes to the node (cases {case}), {moved['received'] // 3} back per run")

    local = tmp_path / "local"
    shutil.copytree(work, local, ignore=shutil.ignore_patterns("out"))
    (local / "spec.yaml").write_text((work / "spec.yaml").read_text(encoding="utf-8").replace(str(work), str(local)),
                                     encoding="utf-8")
    result = run_cli("campaign", local / "spec.yaml", "-o", local / "out", "--workers", "1", "--no-service",
                     timeout=300)
    assert result.returncode == 0, result.stdout + result.stderr
    for row in rows:
        shipped, here = out / "runs" / row["key"], local / "out" / "runs" / row["key"]
        names = sorted(p.relative_to(shipped).as_posix() for p in shipped.rglob("*") if p.is_file())
        assert names == sorted(p.relative_to(here).as_posix() for p in here.rglob("*") if p.is_file())
        for name in ("streams/state.msgpack", "streams/mission.msgpack", "streams/signal.msgpack",
                     "signals.jsonl", "events.csv", "patterns/tasks.vepl"):
            assert (shipped / name).read_bytes() == (here / name).read_bytes(), name
        # the same but for the wall seconds the evaluation took, and the same paths: the driver's, not the node's
        verdicts = [re.sub(r' time="[0-9.]+"', "", (run / "verdicts.xml").read_text(encoding="utf-8"))
                    for run in (shipped, here)]
        assert verdicts[0] == verdicts[1]
        summary, local_summary = (json.loads((run / "summary.json").read_text(encoding="utf-8"))
                                  for run in (shipped, here))
        assert summary.pop("wall_time") > 0 and local_summary.pop("wall_time") > 0
        assert str(shipped / "patterns") in summary["utilities"], summary["utilities"]
        assert summary == {**local_summary, "utilities": local_summary["utilities"].replace(str(local), str(work))}
        assert summary["counts"]["SIG_USER_TASK_STARTED"] == 2  # the user's pattern ran on the node
        # replayed in the warm monitor JVM the node's Ray worker keeps, not in a JVM of its own
        assert json.loads((shipped / "timing.json").read_text(encoding="utf-8"))["monitor"].get("served"), row
        task = json.loads((shipped / "task.json").read_text(encoding="utf-8"))
        assert task["run_dir"] == str(shipped) and task["patterns"] == str(work / "mine")  # the driver's task
    print(f"shared-nothing campaign of 3 runs (cluster start included): {cluster_time:.1f} s")


def test_a_node_lost_in_the_middle_of_a_campaign_loses_no_run_and_repeats_none(tmp_path: Path, cluster: Cluster,
                                                                             run_cli: Any) -> None:
    """Nodes come and go: one dies while it runs a run, and one that cannot run REI's runs (no java) joins after
    the connect-time check; it is checked before it gets a run, named, and every run goes to the node left."""
    started = time.monotonic()
    spec = _spec(tmp_path, 4, "1.0 0.1 0.0\n")
    doomed = cluster.add_node("doomed")
    cluster.wait_for_cpus(1)  # one node at a time: two joining at once on one machine time out now and then
    cluster.add_node("survivor")
    cluster.wait_for_cpus(2)
    survivors = cluster.nodes_with_cpu()
    out = tmp_path / "out"
    argv = [str(Path(sys.executable).parent / "rei"), "campaign", str(spec), "-o", str(out), "--ray",
            cluster.env["RAY_ADDRESS"]]
    with open(tmp_path / "campaign.log", "wb") as log:
        campaign = subprocess.Popen(argv, stdout=log, stderr=subprocess.STDOUT, start_new_session=True,
                                    env={**os.environ, "REI_HOME": str(REPO_ROOT), **cluster.env})
    try:
        deadline = time.monotonic() + 180
        # a run in flight on the doomed node: its temporary run folder holds the run's streams
        while not any(doomed.glob("rei-run-*/run/streams")):
            assert campaign.poll() is None, (tmp_path / "campaign.log").read_text(errors="replace")
            assert time.monotonic() < deadline, "no run ever started on the doomed node"
            time.sleep(0.1)
        late = cluster.add_node("late", path=_without_java(tmp_path / "bin"))
        os.kill(cluster.raylet("doomed"), signal.SIGKILL)
        code = campaign.wait(240)
    finally:
        if campaign.poll() is None:
            os.killpg(campaign.pid, signal.SIGKILL)
            campaign.wait()
    text = (tmp_path / "campaign.log").read_text(errors="replace")
    assert code == 0, text
    assert "lost" in text and "trying again" in text, text
    late_id = next(node for node in cluster.nodes_with_cpu() if node not in survivors)
    said = re.findall(rf"^node \S+ \({late_id[1]}\): java not found on PATH; install a Java 17\+ runtime or "
                      r"set JAVA_HOME; it joined after the check and cannot run REI's runs: they go to the other nodes$",
                      text, re.MULTILINE)
    assert len(said) == 1, text  # once, whether its check or a run's task found it first
    assert not list(late.glob("rei-node-monitor-*")) and not list(late.glob("rei-run-*"))  # it ran no run
    rows = _runs(out)
    keys = [r["key"] for r in rows]
    assert sorted(keys) == sorted(set(keys)) and len(keys) == 4, rows  # every run, once
    assert all(r["status"] == "COMPLETED" for r in rows), rows
    assert any(r["attempt"] == "2" for r in rows), rows  # the lost one, tried again
    for row in rows:
        result = json.loads((out / "runs" / row["key"] / "result.json").read_text(encoding="utf-8"))
        assert result["attempt"] == int(row["attempt"])
    assert not list(out.glob("runs/.*.incoming"))
    print(f"campaign of 4 runs with a node lost (cluster start included): {time.monotonic() - started:.1f} s")


def test_a_campaign_that_loses_its_last_node_says_so_and_ends_instead_of_waiting_forever(tmp_path: Path,
                                                                                        cluster: Cluster) -> None:
    """The cluster's only worker node dies in the middle of a campaign: its runs were tried again and then waited
    for a node without end, saying nothing. Now the wait is said at once and bounded ($REI_RAY_NODE_WAIT): the runs
    left are ERROR naming why (exit 1, --retry-errors redoes them), each run recorded once (writing such a result,
    of a run none of whose files arrived, was a traceback too)."""
    spec = _spec(tmp_path, 3, "1.0 0.1 0.0\n")
    only = cluster.add_node("only")
    cluster.wait_for_cpus(1)
    out = tmp_path / "out"
    argv = [str(Path(sys.executable).parent / "rei"), "campaign", str(spec), "-o", str(out), "--ray",
            cluster.env["RAY_ADDRESS"]]
    with open(tmp_path / "campaign.log", "wb") as log:
        campaign = subprocess.Popen(argv, stdout=log, stderr=subprocess.STDOUT, start_new_session=True,
                                    env={**os.environ, "REI_HOME": str(REPO_ROOT), **cluster.env,
                                         "REI_RAY_NODE_WAIT": "5"})
    try:
        deadline = time.monotonic() + 180
        while not any(only.glob("rei-run-*/run/streams")):
            assert campaign.poll() is None, (tmp_path / "campaign.log").read_text(errors="replace")
            assert time.monotonic() < deadline, "no run ever started on the node"
            time.sleep(0.1)
        os.kill(cluster.raylet("only"), signal.SIGKILL)
        code = campaign.wait(120)
    finally:
        if campaign.poll() is None:
            os.killpg(campaign.pid, signal.SIGKILL)
            campaign.wait()
    text = (tmp_path / "campaign.log").read_text(errors="replace")
    assert code == 1, text
    assert text.count("no alive Ray node can take REI's runs now") == 1, text
    rows = _runs(out)
    assert sorted(r["key"] for r in rows) == sorted({r["key"] for r in rows}) and len(rows) == 3, rows
    assert all(r["status"] == "ERROR" for r in rows), rows
    assert all("no alive Ray node could take the run for 5 s ($REI_RAY_NODE_WAIT)" in r["error"] for r in rows), rows


def test_a_search_on_a_node_that_cannot_see_out_finds_what_a_local_search_finds(tmp_path: Path, cluster: Cluster,
                                                                               run_cli: Any,
                                                                               node_env: NodeEnv) -> None:
    """`rei search --ray` uses the same backend: its candidates' cases go to the node as bytes, their runs come
    back, and the study's journal stays on the driver; the same candidates and values as a local search."""
    started = time.monotonic()
    work = tmp_path / "driver"
    work.mkdir()
    for name in ("crossing.rei", "crossing.yaml"):
        shutil.copy(REPO_ROOT / "examples" / "search" / name, work / name)
    node_tmp = cluster.add_node("node1", hide=work, own=node_env)
    cluster.wait_for_cpus(1)
    node_root = cluster.node_root("node1")
    _runs_reis_wheel(cluster, "node1", node_env)
    out = work / "out"
    result = run_cli("search", work / "crossing.yaml", "-o", out, "--ray", cluster.env["RAY_ADDRESS"], "--budget",
                     "2", "--no-shrink", timeout=300, env=cluster.env)
    assert result.returncode in (0, 1), result.stdout + result.stderr
    assert "on 1 ray worker(s)" in result.stdout, result.stdout
    assert (out / "study.journal").is_file() and not (node_root / out.relative_to("/")).exists()
    assert list(node_tmp.glob("rei-run-*")) == []
    searched = json.loads((out / "search.json").read_text(encoding="utf-8"))
    cluster_time = time.monotonic() - started

    local = tmp_path / "local"
    shutil.copytree(work, local, ignore=shutil.ignore_patterns("out"))
    result = run_cli("search", local / "crossing.yaml", "-o", local / "out", "--workers", "1", "--budget", "2",
                     "--no-shrink", timeout=300)
    assert result.returncode in (0, 1), result.stdout + result.stderr
    here = json.loads((local / "out" / "search.json").read_text(encoding="utf-8"))

    def evaluations(document: dict[str, Any]) -> list[tuple[Any, ...]]:
        return [(e["key"], e["status"], e.get("values")) for e in document["evaluations"]]

    assert evaluations(searched) == evaluations(here) and searched["counts"]["simulated"] == 2, searched
    for evaluation in searched["evaluations"]:
        if evaluation["status"] == "COMPLETED":
            for name in ("streams/state.msgpack", "streams/signal.msgpack", "events.csv"):
                shipped = out / "runs" / evaluation["key"] / name
                assert shipped.read_bytes() == (local / "out" / "runs" / evaluation["key"] / name).read_bytes()
    print(f"shared-nothing search of 2 evaluations (cluster start included): {cluster_time:.1f} s")


OTHER_JOB = """
import time, ray
ray.init(logging_level="ERROR")
@ray.remote(num_cpus=0)
def other():
    time.sleep(25)
    return "the other job's task finished"
print(ray.get(other.remote()), flush=True)
"""


def test_sigterm_stops_this_campaigns_runs_on_the_cluster_and_nothing_else(tmp_path: Path, cluster: Cluster) -> None:
    started = time.monotonic()
    spec = _spec(tmp_path, 3, "1.0 0.1 0.0\n")
    node_tmp = cluster.add_node("node1")
    cluster.wait_for_cpus(1)
    env = {**os.environ, "REI_HOME": str(REPO_ROOT), **cluster.env}
    other = subprocess.Popen([sys.executable, "-c", OTHER_JOB], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             env=env, start_new_session=True)
    out = tmp_path / "out"
    with open(tmp_path / "campaign.log", "wb") as log:
        campaign = subprocess.Popen([str(Path(sys.executable).parent / "rei"), "campaign", str(spec), "-o", str(out),
                                     "--ray", cluster.env["RAY_ADDRESS"]], stdout=log, stderr=subprocess.STDOUT,
                                    env=env, start_new_session=True)
    try:
        deadline = time.monotonic() + 180
        while not any(node_tmp.glob("rei-run-*/run/streams")):
            assert campaign.poll() is None, (tmp_path / "campaign.log").read_text(errors="replace")
            assert time.monotonic() < deadline, "no run ever started on the node"
            time.sleep(0.1)
        campaign.send_signal(signal.SIGTERM)
        code = campaign.wait(60)
        said, _ = other.communicate(timeout=120)
    finally:
        for process in (campaign, other):
            if process.poll() is None:
                os.killpg(process.pid, signal.SIGKILL)
                process.wait()
    text = (tmp_path / "campaign.log").read_text(errors="replace")
    assert code == 130 and "campaign interrupted" in text, text
    assert list(out.glob("runs/*/result.json")) == []  # the run stopped is not finished: a resume runs it
    assert list(node_tmp.glob("rei-run-*")) == []  # its worker stopped and its folder removed on the node
    assert not [line for line in _leftovers(node_tmp) if "rei.campaign.worker" in line]
    assert other.returncode == 0 and "the other job's task finished" in said.decode(), said
    print(f"campaign stopped on the cluster (cluster start included): {time.monotonic() - started:.1f} s")


def _refused(result: Any, cluster: Cluster, *lacks: str) -> None:
    """The command stopped at connect time (exit 2) naming the cluster's one node, by its address and id, once
    for each of ``lacks`` (regular expressions), in that order."""
    assert result.returncode == 2, result.stdout + result.stderr
    lines = result.stderr.strip().splitlines()[-1 - len(lacks):]
    assert lines[0] == "rei: error: 1 of 1 Ray node(s) cannot run REI's runs:", result.stderr
    named = [re.fullmatch(rf"rei: error: node (\S+) \(([0-9a-f]{{12}})\): {lack}", line)
             for line, lack in zip(lines[1:], lacks, strict=True)]
    assert all(named), result.stderr
    assert {m.groups() for m in named if m} == {*cluster.nodes_with_cpu()}, (result.stderr, cluster.nodes_with_cpu())


def test_a_node_without_java_is_named_when_the_campaign_connects(tmp_path: Path, cluster: Cluster, run_cli: Any,
                                                                 node_env: NodeEnv) -> None:
    """Checked at connect time, node by node: a node whose PATH has no java fails the campaign before any run,
    named by its address and id, with what it lacks (not each of its runs with that error); `rei search --ray` is
    refused the same way, and for the router too when its runs start one (an external SUT's). Before the node
    joins, the cluster has no node offering the resource 'rei' (its head has none), which is said as plainly."""
    started = time.monotonic()
    spec = _spec(tmp_path, 1, "1.0 0.1 0.0\n")
    cluster.wait_for_cpus(0)
    result = _campaign(run_cli, spec, tmp_path / "none", cluster, timeout=120)
    assert result.returncode == 2, result.stdout + result.stderr
    assert result.stderr.strip().splitlines()[-1] == (
        "rei: error: no Ray node offers the resource 'rei' that REI's runs ask for; start each node that is to run "
        "them with `ray start --resources='{\"rei\": N}' ...` (N: its runs at a time, e.g. its CPUs; "
        "docs/campaigns.md#setting-up-a-cluster) (1 node(s) alive)"), result.stderr
    cluster.add_node("nojava", own=node_env, path=_without_java(tmp_path / "bin"))
    cluster.wait_for_cpus(1)
    out = tmp_path / "out"
    no_java = r"java not found on PATH; install a Java 17\+ runtime or set JAVA_HOME"
    _refused(_campaign(run_cli, spec, out, cluster, timeout=240), cluster, no_java)
    assert not (out / "runs.csv").exists()  # no run was tried
    # a search of an external SUT, whose runs start a router: the wheel's node has none either
    for name in ("crossing.rei", "crossing.yaml"):
        shutil.copy(REPO_ROOT / "examples" / "search" / name, tmp_path / name)
    searched = tmp_path / "crossing.yaml"
    searched.write_text(searched.read_text(encoding="utf-8").replace(
        "controller: nav", 'sut: {command: "rei nav-sut", map: true}'), encoding="utf-8")
    result = run_cli("search", searched, "-o", tmp_path / "search", "--ray", cluster.env["RAY_ADDRESS"],
                     "--budget", "1", timeout=240, env=cluster.env)
    _refused(result, cluster, no_java,
             r"crossbar executable not found \(.+\); run scripts/setup-router.sh or set REI_CROSSBAR")
    assert not (tmp_path / "search" / "runs").exists()  # no candidate was run
    print(f"a node without java refused (cluster start included): {time.monotonic() - started:.1f} s")


def test_the_wheel_carries_the_monitor_jar_and_the_people_server_and_names_what_it_lacks(
        node_env: NodeEnv, tmp_path: Path) -> None:
    """Outside any checkout (run from a temporary folder, no REI_HOME), the wheel's REI finds its own monitor jar,
    and a jar it was built without is refused saying which jars it has and how to get the one asked for. It finds
    its own people server too, run by the Python that ``$REI_PEOPLE_PYTHON`` names (here the checkout's
    .venv-people, which has JuPedSim), and the node check names a missing JuPedSim when the runs move people."""
    script = ("import json\nfrom rei import toolchain\n"
              "from rei.sim.people.server import people_problem, server_command\n"
              "print(toolchain.find_jar('monitor'))\ntry:\n    toolchain.find_jar('cli')\n"
              "except toolchain.ToolchainError as error:\n    print(error)\n"
              "print(json.dumps([server_command(), people_problem()]))\n")
    env = {key: value for key, value in os.environ.items()
           if key not in ("REI_HOME", "VIRTUAL_ENV", "PYTHONPATH", "REI_PEOPLE_PYTHON")}
    # the driver's third-party packages (msgpack, PyYAML...) as the node's namespace has them in its stash; a
    # folder on PYTHONPATH is no site directory: the driver's editable REI's .pth file there is not read
    env["PYTHONPATH"] = str(node_env.deps)
    people = REPO_ROOT / ".venv-people" / "bin" / "python"
    done = subprocess.run([str(node_env.python), "-c", script], capture_output=True, text=True, cwd=tmp_path,
                          env={**env, "REI_PEOPLE_PYTHON": str(people)}, timeout=120, check=False)
    assert done.returncode == 0, done.stderr
    jar, refusal, server = done.stdout.strip().splitlines()
    assert Path(jar).is_relative_to(node_env.python.parent.parent)  # the node's venv, where the wheel went
    assert Path(jar).name == "rei-monitor.jar" and Path(jar).stat().st_size == (
        REPO_ROOT / "runtime-monitor" / "target" / "rei-monitor.jar").stat().st_size
    assert refusal == ("this installation of REI carries no rei-cli.jar (it has: rei-monitor.jar); install a wheel "
                       "built with it (scripts/build-wheel.sh --jars cli) or set REI_HOME to a built checkout")
    (python, found), lacks = json.loads(server)
    assert python == str(people) and lacks is None  # JuPedSim imports there
    assert Path(found).is_relative_to(node_env.python.parent.parent) and Path(found).read_bytes() == (
        REPO_ROOT / "pedestrians" / "jupedsim_server.py").read_bytes()
    with zipfile.ZipFile(node_env.wheel) as wheel:
        assert "rei/pedestrians/jupedsim_server.py" in wheel.namelist()
    # a node with no Python for JuPedSim: runs with people cannot go there, runs without can
    script = "import json\nfrom rei.campaign.nodes import check_node\nprint(json.dumps([check_node(False, True), " \
             "check_node(False)]))"
    done = subprocess.run([str(node_env.python), "-c", script], capture_output=True, text=True, cwd=tmp_path,
                          env=env, timeout=120, check=False)
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout) == [[(
        "reactive people need JuPedSim, and $REI_PEOPLE_PYTHON names no Python that has it; install JuPedSim into "
        "a Python of its own (python -m venv V && V/bin/pip install numpy shapely deprecated msgpack && V/bin/pip "
        "install --no-deps jupedsim==1.4.2, as scripts/setup-people.sh does) and set REI_PEOPLE_PYTHON to "
        "V/bin/python")], []]


def test_a_wheel_built_from_uncommitted_changes_says_so(tmp_path: Path) -> None:
    """Every wheel is rei 0.1.0: one built from an edited tree was told from the committed one by nothing. The tree
    is seen dirty here through an index of the test's own (empty: every file is untracked), the checkout untouched."""
    built = subprocess.run(["bash", str(REPO_ROOT / "scripts" / "build-wheel.sh"), "-o", str(tmp_path / "dist")],
                           capture_output=True, text=True, timeout=300, check=False,
                           env={**os.environ, "GIT_INDEX_FILE": str(tmp_path / "empty-index")})
    assert built.returncode == 0, built.stderr
    assert re.search(r"^build-wheel: warning: built from uncommitted changes \(\d+ file\(s\), e\.g\. \S+\): the wheel "
                     r"holds them as they are now; nodes must run the driver's build", built.stderr, re.MULTILINE), \
        built.stderr
    assert Path(built.stdout.strip().splitlines()[-1]).is_file()  # a warning: the wheel is built all the same
