# SPDX-License-Identifier: EPL-2.0
"""Where runs execute: worker processes on this machine (default) or tasks on a Ray cluster (``--ray``).

Both run the same ``supervise`` (a worker process per run, with its timeout) and hand each ``Outcome`` back to
the caller's thread as it arrives, so results are written and printed in one place, in completion order.
"""

from __future__ import annotations

import contextlib
import os
import re
import secrets
import shutil
import tempfile
import threading
from collections.abc import Callable, Iterator, Mapping, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ThreadPoolExecutor, wait
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rei.campaign.forkserver import ForkServer, ForkServerError
from rei.campaign.nodes import RESOURCE, NodesUnfitError
from rei.campaign.plan import RunTask
from rei.campaign.supervise import KILL_GRACE, Outcome, supervise
from rei.campaign.transfer import folder_bundle, inputs, receive, run_shipped, sweep_monitor_folders
from rei.campaign.worker import MONITOR_SERVER_ENV
from rei.run.jvm import JarServer, JarServerError

OnOutcome = Callable[[RunTask, Outcome], None]
_ANSI = re.compile(r"\x1b\[[0-9;]*m")


@dataclass(frozen=True)
class Warm:
    """What the workers of a ``warm_start`` block use: their environment and the fork server (None: each worker
    starts as a new process)."""

    env: dict[str, str]
    forks: ForkServer | None


@contextlib.contextmanager
def warm_start(who: str, forks: ForkServer | None, monitor_log: Path | None, *, monitor_server: Path | None = None,
               env: Mapping[str, str] | None = None) -> Iterator[Warm]:
    """Starts what makes the local runs cheap and stops it at the end: ``forks`` (the workers are forked from it)
    and, with ``monitor_log``, one warm monitor JVM for every run's replay (rei.run.jvm.JarServer), its log there;
    the workers find its socket in ``$REI_MONITOR_SERVER`` (rei.campaign.worker). ``monitor_server``: replay in that
    warm monitor JVM instead (the background service's), started by someone else. ``env``: added to every worker's
    environment. Either failing to start is said on the terminal, prefixed ``who:``, and the runs go on without it.
    Shared by the campaign's local backend and rei.search's local pool."""
    with contextlib.ExitStack() as stack:
        workers_env = dict(env or {})
        if forks is not None:
            try:
                stack.enter_context(forks)
            except ForkServerError as error:  # each worker then starts as a new process
                print(f"{who}: {error}; each run's worker starts as a new process", flush=True)
                forks = None
        if monitor_server is not None:
            workers_env[MONITOR_SERVER_ENV] = str(monitor_server)
        elif monitor_log is not None:
            server = JarServer("monitor", monitor_log)
            try:
                stack.enter_context(server)
                workers_env[MONITOR_SERVER_ENV] = str(server.socket)
            except (JarServerError, OSError) as error:  # each replay then starts a JVM of its own
                print(f"{who}: no warm monitor JVM ({error}); each run replays in a JVM of its own", flush=True)
        yield Warm(workers_env, forks)


class LocalBackend:
    """``workers`` runs at a time, each in its own process (forked by one rei.campaign.forkserver), supervised by
    one thread each.

    ``monitor_log``: keep one warm monitor JVM for every run's replay (rei.run.jvm.JarServer), its log there; the
    workers find its socket in ``$REI_MONITOR_SERVER`` (rei.campaign.worker). ``monitor_server``: replay in that
    warm monitor JVM instead (the background service's), started by someone else. ``worker_env``: added to every
    worker's environment. ``fork_log``: fork the workers from one rei.campaign.forkserver, its log there; else
    each is a new process. ``command`` (for tests) replaces the worker command line of every run.
    """

    name = "local"

    def __init__(self, workers: int, command: Callable[[RunTask], Sequence[str]] | None = None,
                 monitor_log: Path | None = None, fork_log: Path | None = None,
                 monitor_server: Path | None = None, worker_env: dict[str, str] | None = None) -> None:
        if workers < 1:
            raise ValueError(f"workers must be >= 1, got {workers}")
        self.workers = workers
        self._command = command
        self._monitor_log = monitor_log
        self._monitor_server = monitor_server
        self._worker_env = dict(worker_env or {})
        # without ``command``: workers forked by a rei.campaign.forkserver logging there
        self._forks = ForkServer(fork_log) if fork_log is not None and command is None else None

    def warm_up(self) -> None:
        """Launches the fork server, which imports the workers' modules while the cases are generated."""
        if self._forks is not None:
            self._forks.launch()

    def run(self, tasks: Sequence[RunTask], on_outcome: OnOutcome, stop: threading.Event) -> None:
        with warm_start("campaign", self._forks if tasks else None, self._monitor_log if tasks else None,
                        monitor_server=self._monitor_server, env=self._worker_env) as warm:
            self._run(tasks, on_outcome, stop, warm.env, warm.forks)

    def _run(self, tasks: Sequence[RunTask], on_outcome: OnOutcome, stop: threading.Event,
             env: dict[str, str] | None, forks: ForkServer | None) -> None:
        with ThreadPoolExecutor(self.workers, thread_name_prefix="rei-campaign") as pool:
            pending: dict[Future[Outcome], RunTask] = {
                pool.submit(supervise, task, stop, self._command(task) if self._command else None, env, forks): task
                for task in tasks}
            try:
                while pending:
                    done, _ = wait(pending, timeout=0.5, return_when=FIRST_COMPLETED)
                    for future in done:
                        on_outcome(pending.pop(future), future.result())
            except BaseException:
                stop.set()  # running workers are stopped by their supervisors, queued ones never start
                for future in pending:
                    future.cancel()
                raise

    def close(self) -> None:
        if self._forks is not None:
            self._forks.stop()  # launched by warm_up for a campaign that then did not run


class RayBackend:
    """Runs as Ray tasks of one CPU each. ``address``: a cluster's (``ray start --head`` prints it), or
    ``local`` for a Ray instance started here with ``workers`` CPUs and stopped at the end.

    ``local`` always starts a new instance (Ray's ``address="local"``): without it ``ray.init`` would connect to
    the cluster named in Ray's ``ray_current_cluster`` file, which a ``ray start`` stopped without ``ray stop``
    leaves behind. The instance keeps its temporary files (sessions, sockets, logs) and its authentication token
    in a folder of its own in the system's temporary directory, deleted at the end: nothing is left in the
    machine's shared Ray folder, nor in ``~/.ray`` (where Ray would save a new token, which every later
    ``ray start`` of the user would then require).

    Nodes share nothing with this machine but Ray (rei.campaign.transfer): a run's case and inputs travel as
    bytes, it runs in a temporary folder of the node's, its run folder comes back into OUT. A task lost with its
    node (or its Ray worker, or the chunks of its files) is tried again, up to ``attempts`` tries, by REI rather
    than by Ray, so the try that gave a run's result is known (``attempt`` in result.json and runs.csv) and a run
    is recorded once: only after its files arrived. A run that crashes or times out in its worker is a result,
    not a lost task, and is not tried again.
    """

    name = "ray"

    def __init__(self, address: str, workers: int | None = None, attempts: int = 3,
                 log: Callable[[str], None] = print, router: bool = False, people: bool = False) -> None:
        import ray

        from rei.campaign.nodes import Watch, build_id, check_cluster

        if attempts < 1:
            raise ValueError(f"attempts must be >= 1, got {attempts}")
        self._ray = ray
        self._temp_dir: Path | None = None
        self._saved_env: dict[str, str | None] = {}
        self.attempts = attempts
        #: seconds the runs in flight wait for a node that can take them once none is alive (a cluster that lost
        #: its last worker node; an autoscaler may bring one): then they are ERROR, and --retry-errors redoes them
        self.node_wait = _node_wait()
        self._log = log
        #: bytes sent to the nodes (case bundles once each, the tasks' other inputs) and received from them (run
        #: files): the campaign's metrics (campaign.json: transfer)
        self.moved = {"sent": 0, "received": 0}
        init: dict[str, Any] = {"include_dashboard": False, "log_to_driver": False, "logging_level": "WARNING"}
        runtime_env = _runtime_env()
        if runtime_env is not None:  # else Ray's own: a job's (`ray job submit --runtime-env-json`), or none
            init["runtime_env"] = runtime_env
        if address == "local":
            # short, in the system's temporary directory: Ray's unix sockets live below it (108-byte limit)
            self._temp_dir = Path(tempfile.mkdtemp(prefix="rei-ray-"))  # mode 0700: the token is ours alone
            try:
                token = self._temp_dir / "auth_token"
                token.write_text(secrets.token_hex(32), encoding="ascii")
                # Ray enables token authentication for a new local instance (unless RAY_AUTH_MODE says otherwise)
                # and takes this token instead of making one; the instance's processes, started from here, inherit
                # the environment (a path, not the secret)
                self._set_env({"RAY_AUTH_TOKEN_PATH": str(token)})
                # this instance is REI's own: its one node offers the runs' resource, one a CPU
                ray.init(address="local", num_cpus=workers or 1, resources={RESOURCE: workers or 1},
                         _temp_dir=str(self._temp_dir), **init)
            except BaseException:
                self.close()
                raise
        else:
            _reachable(address)
            ray.init(address=address, **init)
        # every node runs can go to (those offering the resource 'rei') is asked once whether it can run them (Java,
        # the monitor jar, pybullet, the router when the runs start one): one that cannot is named now rather than
        # failing its runs one by one
        try:
            problems, fit = check_cluster(ray, router, people)
        except NodesUnfitError:  # no node offers the resource
            self.close()
            raise
        if problems:
            nodes = sum(1 for node in ray.nodes() if node.get("Alive") and node.get("Resources", {}).get(RESOURCE))
            self.close()
            raise NodesUnfitError(f"{len({name for name, _ in problems})} of {nodes} Ray node(s) cannot run "
                                  "REI's runs:\n" + "\n".join(f"{name}: {lack}" for name, lack in problems))
        # a node that joins later is checked before it gets a run: by the driver when it notices it, or by the
        # run's task that lands there first (it then returns without running, and the run goes elsewhere)
        self._needs = (router, people, build_id())
        self._watch = Watch(ray, fit, router, people, log)
        # a CPU and a 'rei' each: only the nodes offering it get runs; max_retries=0: REI tries a lost task again
        # itself (above); Ray's own retry would hide the attempt
        self._remote = ray.remote(num_cpus=1, resources={RESOURCE: 1}, max_retries=0)(run_shipped)

    @property
    def workers(self) -> int:
        """Runs at a time on the nodes that can take them, followed while runs go on (``Watch.poll``)."""
        return max(1, self._watch.slots)

    def warm_up(self) -> None:
        pass

    def run(self, tasks: Sequence[RunTask], on_outcome: OnOutcome, stop: threading.Event) -> None:
        ray = self._ray
        cases: dict[str, Any] = {}  # case folder -> its bundle in the object store, put once for its runs
        refs: dict[Any, tuple[RunTask, int, dict[str, Any]]] = {}

        def submit(task: RunTask, attempt: int) -> None:
            try:
                if task.case_dir not in cases:
                    bundle = folder_bundle(Path(task.case_dir))
                    cases[task.case_dir] = ray.put(bundle)
                    self.moved["sent"] += sum(map(len, bundle.values()))
                extra, fields = inputs(task)
                self.moved["sent"] += sum(map(len, extra.values()))
            except (OSError, ValueError) as error:  # an input that cannot be read is the run's ERROR
                on_outcome(task, Outcome(task.key, None, False, False, 0.0, 0.0,
                                         f"cannot ship the run's inputs: {error}", "-", attempt))
                return
            ref = self._remote.options(**self._watch.excluded()).remote(
                task.to_dict(), cases[task.case_dir], extra, fields, attempt, self._needs)
            refs[ref] = (task, attempt, fields)

        for task in tasks:
            submit(task, 1)
        try:
            while refs and not stop.is_set():
                self._watch.poll()
                stranded = self._watch.stranded()
                if stranded is not None and stranded > self.node_wait:  # the cluster lost every node runs go to
                    why = (f"no alive Ray node could take the run for {self.node_wait:.0f} s (${NODE_WAIT_ENV}): each "
                           f"offering '{RESOURCE}' was lost or cannot run REI's runs")
                    for ref, (task, attempt, _) in list(refs.items()):
                        del refs[ref]
                        with contextlib.suppress(Exception):
                            ray.cancel(ref)
                        on_outcome(task, Outcome(task.key, None, False, False, 0.0, 0.0, why, "?", attempt))
                    break
                ready, _ = ray.wait(list(refs), num_returns=1, timeout=0.5)
                for ref in ready:
                    task, attempt, fields = refs.pop(ref)
                    try:
                        shipped = ray.get(ref)
                        if "unfit" in shipped:  # its node cannot run it (a node that joined after the check)
                            self._watch.refused(shipped["node"], shipped["unfit"])
                            nowhere = self._watch.nowhere()
                            if nowhere is None:
                                submit(task, attempt)  # not a try: it did not run
                                continue
                            outcome = Outcome(task.key, None, False, False, 0.0, 0.0, nowhere, "?", attempt)
                            on_outcome(task, outcome)
                            continue
                        self.moved["received"] += receive(task, shipped["files"], ray.get, shipped["work"], fields)
                        outcome = Outcome(**shipped["outcome"])
                    except ray.exceptions.TaskCancelledError:
                        continue
                    except Exception as error:  # noqa: BLE001 - lost: its node, its Ray worker, its files' chunks
                        first = (_ANSI.sub("", str(error)).strip().splitlines() or [""])[0]  # Ray colours its errors
                        why = f"{type(error).__name__}: {first[:160]}{'...' if len(first) > 160 else ''}"
                        if isinstance(error, OSError) and not isinstance(error, ray.exceptions.RayError):
                            # writing into OUT here failed (the disk is full): another try would not help
                            outcome = Outcome(task.key, None, False, False, 0.0, 0.0,
                                              f"cannot write the run's files into OUT: {error}", "?", attempt)
                        elif attempt < self.attempts and not stop.is_set():
                            self._log(f"{task.key}: try {attempt} lost ({why}); trying again")
                            submit(task, attempt + 1)
                            continue
                        else:
                            outcome = Outcome(task.key, None, False, False, 0.0, 0.0,
                                              f"ray task lost on each of {attempt} tries: {why}", "?", attempt)
                    on_outcome(task, outcome)
        except BaseException:
            stop.set()
            raise
        finally:
            if refs:  # stopped: this campaign's tasks only; not forced: the task's supervisor stops its worker
                for ref in refs:
                    ray.cancel(ref)
                # and removes its folder before the driver disconnects (which ends the job's Ray workers at once)
                with contextlib.suppress(Exception):
                    ray.wait(list(refs), num_returns=len(refs), timeout=KILL_GRACE + 3.0)

    def _set_env(self, values: dict[str, str]) -> None:
        for key, value in values.items():
            self._saved_env.setdefault(key, os.environ.get(key))
            os.environ[key] = value

    def close(self) -> None:
        self._ray.shutdown()  # stops the processes of an instance started here, and waits for them
        if self._temp_dir is not None:  # its Ray workers' warm monitor folders, in this machine's TMPDIR
            sweep_monitor_folders(wait=5.0)
        for key, value in self._saved_env.items():
            if value is None:
                os.environ.pop(key, None)
            else:
                os.environ[key] = value
        if self._temp_dir is not None:
            shutil.rmtree(self._temp_dir, ignore_errors=True)


#: Environment variable: seconds the runs wait for a Ray node that can take them when none is alive (default 300).
NODE_WAIT_ENV = "REI_RAY_NODE_WAIT"


def _node_wait() -> float:
    value = os.environ.get(NODE_WAIT_ENV, "").strip()
    try:
        wait = float(value) if value else 300.0
    except ValueError:
        raise ValueError(f"${NODE_WAIT_ENV}: seconds, got {value!r}") from None
    if wait < 0:
        raise ValueError(f"${NODE_WAIT_ENV}: seconds, got {value!r}")
    return wait


#: Environment variable naming a Ray runtime environment for the runs' tasks: a JSON file, or the JSON itself
#: (``{"py_modules": ["dist/rei-0.1.0-py3-none-any.whl"]}`` installs REI's wheel on each node for the job).
RUNTIME_ENV_ENV = "REI_RAY_RUNTIME_ENV"


def _runtime_env() -> dict[str, Any] | None:
    import json

    value = os.environ.get(RUNTIME_ENV_ENV, "").strip()
    if not value:
        return None
    try:
        text = value if value.startswith("{") else Path(value).read_text(encoding="utf-8")
        env = json.loads(text)
    except (OSError, ValueError) as error:
        raise ValueError(f"${RUNTIME_ENV_ENV}: not a JSON object nor a JSON file: {error}") from None
    if not isinstance(env, dict):
        raise TypeError(f"${RUNTIME_ENV_ENV}: a runtime environment is a JSON object, got {type(env).__name__}")
    return env


#: Seconds a cluster's head has to accept a connection before ``--ray HOST:PORT`` is refused (Ray itself would try
#: again for minutes, printing a warning every few seconds).
CONNECT_TIMEOUT = 10.0
_HOST_PORT = re.compile(r"^(?:\[(?P<v6>[^\]]+)\]|(?P<host>[^:/\[\]]+)):(?P<port>\d+)$")
#: What the driver needs when the head asks for Ray's token (``ray start --head``'s default), and that Ray's own
#: error leaves out.
AUTH_HINT = ("if the cluster asks for Ray's authentication token (`ray start --head` does by default), give this "
             "machine the head's: RAY_AUTH_MODE=token and RAY_AUTH_TOKEN_PATH=FILE or RAY_AUTH_TOKEN=TOKEN "
             "(docs/campaigns.md#setting-up-a-cluster)")


class NoHeadError(ConnectionError):
    """Nothing accepts a connection at the address of ``--ray HOST:PORT``."""


def _reachable(address: str, timeout: float = CONNECT_TIMEOUT) -> None:
    """Refuses at once a ``HOST:PORT`` where nothing accepts a connection, which Ray would retry for minutes;
    other forms (``auto``, ``ray://...``) are Ray's to resolve."""
    import socket

    match = _HOST_PORT.match(address.strip())
    if match is None:
        return
    host = match["v6"] or match["host"]
    try:
        with socket.create_connection((host, int(match["port"])), timeout=timeout):
            pass
    except OSError as error:
        why = "timed out" if isinstance(error, TimeoutError) else (error.strerror or str(error))
        raise NoHeadError(f"nothing answers at {address} ({why}); is the cluster's head started there (`ray start "
                          "--head --port=PORT` prints the address to give), and is the address right?") from None


class RayUnavailableError(RuntimeError):
    """The runs have nowhere to go: Ray is missing, its cluster can not be reached or some of its nodes cannot run
    REI (the message says which)."""


def connect_ray(address: str, workers: int, router: bool = False, people: bool = False) -> RayBackend:
    """The Ray backend for ``--ray ADDRESS`` (``local``: a Ray instance of ``workers`` CPUs started here; a cluster
    has CPUs of its own), for rei campaign and rei search; ``router``: the runs start a WAMP router (``mode:
    pipeline``, an external SUT), ``people``: they move people who see the robot (JuPedSim), which the nodes are
    then checked to have."""
    try:
        return RayBackend(address, workers if address == "local" else None, router=router, people=people)
    except ImportError:
        raise RayUnavailableError("--ray needs Ray: pip install 'rei[campaign-ray]'") from None
    except NodesUnfitError as error:
        raise RayUnavailableError(str(error)) from None
    except NoHeadError as error:
        raise RayUnavailableError(f"cannot connect to Ray at {address}: {error}") from None
    except Exception as error:  # noqa: BLE001 - any failure to reach the cluster is the user's to fix
        hint = ""
        if (address != "local" and os.environ.get("RAY_AUTH_MODE", "").strip().lower() != "token"
                and re.search(r"failed to connect|auth|token", str(error), re.IGNORECASE)):
            hint = f"; {AUTH_HINT}"  # Ray says only that it failed to connect, after retrying
        raise RayUnavailableError(f"cannot connect to Ray at {address}: {error}{hint}") from None
