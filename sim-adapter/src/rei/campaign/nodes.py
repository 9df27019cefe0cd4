# SPDX-License-Identifier: EPL-2.0
"""Can every node of a Ray cluster run REI's runs? Asked at connect time, node by node, and of each node that
joins later before it gets a run.

REI's runs go only to the nodes that offer the custom resource ``rei`` (``RESOURCE``; ``ray start
--resources='{"rei": N}'``, N runs at a time there): a run's task asks for one CPU and one ``rei``, so a node
started for other work (a GPU node, a head) never gets one, and a cluster where no node offers it is refused at
connect time rather than left with tasks Ray can never place (``NO_RESOURCE``).

A node that cannot (no Java, REI installed without its monitor jar, no pybullet, no router for runs that need
one, REI not installed at all) would otherwise fail each run it gets with that run's error, in the middle of a
campaign. ``check_cluster`` sends a task of no CPU pinned to each alive node that offers ``rei`` (the nodes runs
go to), which runs ``check_node`` there, and returns one line per node that cannot, naming the node and what it
lacks. ``check_node`` is pickled by reference (``rei.campaign.nodes.check_node``): a node without REI fails to
load it, which is itself the answer.

A node that joins after that is asked the same by the driver as soon as it notices it (``Watch``), and a run's task
asks its own node first (``node_lacks``, once per Ray worker process): on a node that cannot run it, the task
returns without running and the driver submits the run again, kept off that node (Ray's ``ray.io/node-id`` label),
the node named once with what it lacks; so a late node's shortcomings never turn runs into ERROR.
"""

from __future__ import annotations

import contextlib
import functools
import re
import threading
import time
from collections.abc import Callable
from typing import Any

#: The custom Ray resource a run's task asks one of: only nodes that offer it get runs.
RESOURCE = "rei"
#: Why a cluster without such a node gets no run (the driver adds the number of its alive nodes).
NO_RESOURCE = (f"no Ray node offers the resource '{RESOURCE}' that REI's runs ask for; start each node that is "
               f"to run them with `ray start --resources='{{\"{RESOURCE}\": N}}' ...` (N: its runs at a time, e.g. "
               "its CPUs; docs/campaigns.md#setting-up-a-cluster)")
#: Seconds a node has to answer: its first Ray worker starts and imports REI (slow on a busy machine).
CHECK_TIMEOUT = 120.0
_ANSI = re.compile(r"\x1b\[[0-9;]*m")


@functools.cache
def build_id() -> str:
    """This REI's build: a SHA-256 of its package's Python sources (paths and contents; not the people server,
    which only the wheel carries there), the same for a wheel and the tree it was built from, whatever the version
    number (every wheel is 0.1.0) and whether that tree was committed."""
    import hashlib
    from pathlib import Path

    import rei

    root = Path(rei.__file__).resolve().parent
    digest = hashlib.sha256()
    for path in sorted(root.rglob("*.py")):
        relative = path.relative_to(root).as_posix()
        if relative.startswith("pedestrians/") or "__pycache__" in relative:
            continue
        digest.update(relative.encode() + b"\0" + path.read_bytes() + b"\0")
    return digest.hexdigest()


#: What a node whose REI is not the driver's lacks (its build, the driver's).
OTHER_BUILD = ("its REI is another build than the driver's ({0} there, {1} here): install the driver's REI there "
               "(the wheel scripts/build-wheel.sh builds from the driver's tree; docs/campaigns.md#setting-up-a-cluster)")


def check_node(router: bool, people: bool = False, build: str | None = None) -> list[str]:
    """On the node: what it lacks to run REI's runs (empty: nothing). ``router``: the runs start a WAMP router;
    ``people``: they move people who see the robot (JuPedSim's people server); ``build``: the driver's
    ``build_id``, which the node's must be (its runs would otherwise run other code than the driver's)."""
    problems = []
    if build is not None and build != build_id():
        problems.append(OTHER_BUILD.format(build_id()[:12], build[:12]))
    try:
        import pybullet  # noqa: F401 - the simulation
    except ImportError as error:
        problems.append(f"the simulation cannot import pybullet ({error})")
    from rei import toolchain

    try:
        toolchain.find_java()
    except toolchain.ToolchainError as error:
        problems.append(str(error))
    try:
        toolchain.find_jar("monitor")
    except toolchain.ToolchainError as error:
        problems.append(str(error))
    if router:
        from rei.wamp.router import RouterError, find_crossbar

        try:
            find_crossbar()
        except RouterError as error:
            problems.append(str(error))
    if people:
        from rei.sim.people.server import people_problem

        lack = people_problem()
        if lack is not None:
            problems.append(lack)
    return problems


_LACKS: dict[tuple[bool, bool, str | None], list[str]] = {}


def node_lacks(router: bool, people: bool = False, build: str | None = None) -> list[str]:
    """``check_node``, asked once per process (a Ray worker runs many runs): what a run's task asks before it runs."""
    if (router, people, build) not in _LACKS:
        _LACKS[router, people, build] = check_node(router, people, build)
    return _LACKS[router, people, build]


def name(node: dict[str, Any]) -> str:
    """How a node is named to the user: its address and the first 12 digits of its id."""
    return f"node {node.get('NodeManagerAddress', '?')} ({node['NodeID'][:12]})"


def ask(ray: Any, node: dict[str, Any], router: bool, people: bool = False) -> Any:
    """A reference to ``check_node``'s answer on ``node`` (a task of no CPU pinned to it)."""
    from ray.util.scheduling_strategies import NodeAffinitySchedulingStrategy

    remote = ray.remote(num_cpus=0, max_retries=0)(check_node)
    return remote.options(scheduling_strategy=NodeAffinitySchedulingStrategy(node["NodeID"], soft=False)).remote(
        router, people, build=build_id())


def answer(ray: Any, ref: Any) -> list[str]:
    """What the node of a finished ``ask`` lacks; a check that could not even run there says why."""
    try:
        lacks: list[str] = ray.get(ref)
        return lacks
    except Exception as error:  # noqa: BLE001 - the check could not even run there: REI or its Python is broken
        lines = [line.strip() for line in _ANSI.sub("", str(error)).splitlines() if line.strip()]
        # the innermost cause is the last line of the node's traceback ("ModuleNotFoundError: No module ...")
        cause = lines[-1] if lines else type(error).__name__
        hint = "install REI there (pip install rei-*.whl, docs/campaigns.md#setting-up-a-cluster)"
        if "check_node()" in cause:  # its REI's check takes other arguments: an older or newer REI
            hint = ("its REI is another version than the driver's: install the driver's REI there (the wheel "
                    "scripts/build-wheel.sh builds from the driver's tree; docs/campaigns.md#setting-up-a-cluster)")
        return [f"cannot run REI's check ({cause}); {hint}"]


def check_cluster(ray: Any, router: bool = False, people: bool = False,
                  timeout: float = CHECK_TIMEOUT) -> tuple[list[tuple[str, str]], set[str]]:
    """``(node IP (ID), what it lacks)`` for every alive node offering ``RESOURCE`` that cannot run REI's runs ([]
    if all can), and the ids of those that can. ``NodesUnfitError``: no alive node offers it."""
    nodes = offering(ray.nodes())
    if not nodes:
        alive = sum(1 for node in ray.nodes() if node.get("Alive"))
        raise NodesUnfitError(f"{NO_RESOURCE} ({alive} node(s) alive)")
    refs = {ask(ray, node, router, people): node for node in nodes}
    _, late = ray.wait(list(refs), num_returns=len(refs), timeout=timeout)
    problems = []
    fit = set()
    for ref, node in refs.items():
        if ref in late:
            problems.append((name(node), f"did not answer REI's check within {timeout:.0f} s"))
            with contextlib.suppress(Exception):
                ray.cancel(ref, force=True)
            continue
        lacks = answer(ray, ref)
        problems += [(name(node), lack) for lack in lacks]
        if not lacks:
            fit.add(node["NodeID"])
    return problems, fit


class Watch:
    """The nodes runs may go to, for the driver: those that passed the connect-time check, and each that joins
    later, checked as it is noticed (``poll``, at most every ``every`` seconds: ``ask``, without waiting for the
    answer) or by a run's task that landed there first (``refused``). A node that cannot run REI's runs is said once
    through ``log`` and ``excluded`` from the runs submitted afterwards. Shared by the threads of a search."""

    def __init__(self, ray: Any, fit: set[str], router: bool, people: bool, log: Callable[[str], None],
                 every: float = 2.0) -> None:
        self._ray = ray
        #: runs the nodes that can take them take at a time, as of the latest ``poll``: a search keeps that many
        #: candidates in flight, so a node that joins gets work and one lost or unfit gets none
        self.slots = slots(ray.nodes())
        self._needs = (router, people)
        self._log = log
        self._every = every
        self._known = set(fit)  # checked: fit, unfit or being asked
        self.unfit: dict[str, str] = {}  # node id -> "node ADDRESS (ID): what it lacks"
        self._asked: dict[Any, dict[str, Any]] = {}
        self._next = 0.0
        self._lock = threading.Lock()
        self._stranded: float | None = None  # since when no alive node can take a run (monotonic); None: one can

    def poll(self) -> None:
        """Notices the nodes that joined and reads the answers of those asked; Ray's node list out of reach (its
        head busy, a node being lost) only puts it off."""
        with contextlib.suppress(Exception), self._lock:
            if self._asked:
                ready, _ = self._ray.wait(list(self._asked), num_returns=len(self._asked), timeout=0)
                for ref in ready:
                    node = self._asked.pop(ref)
                    lacks = answer(self._ray, ref)
                    if lacks:
                        self._unfit(node, lacks)
            if time.monotonic() < self._next:
                return
            self._next = time.monotonic() + self._every
            nodes = offering(self._ray.nodes())
            self.slots = sum(_slots(node) for node in nodes if node["NodeID"] not in self.unfit)
            if self.slots == 0 and self._stranded is None:
                self._stranded = time.monotonic()
                self._log(f"no alive Ray node can take REI's runs now (each offering '{RESOURCE}' was lost or cannot "
                          "run them): the runs left wait for one to join; Ctrl-C stops, and the same command "
                          "resumes")
            elif self.slots > 0 and self._stranded is not None:
                self._stranded = None
                self._log("a Ray node that can take REI's runs is alive again: the runs go on")
            for node in nodes:
                if node["NodeID"] not in self._known:
                    self._known.add(node["NodeID"])
                    self._asked[ask(self._ray, node, *self._needs)] = node

    def stranded(self) -> float | None:
        """Seconds since no alive node can take a run, as of the latest ``poll``; None: one can."""
        with self._lock:
            return None if self._stranded is None else time.monotonic() - self._stranded

    def refused(self, node_id: str, lacks: list[str]) -> None:
        """A run's task found its node cannot run it (and did not run it)."""
        with self._lock:
            self._known.add(node_id)
            if node_id not in self.unfit:
                try:
                    node = next(n for n in self._ray.nodes() if n["NodeID"] == node_id)
                except Exception:  # noqa: BLE001 - named by its id alone
                    node = {"NodeID": node_id}
                self._unfit(node, lacks)

    def _unfit(self, node: dict[str, Any], lacks: list[str]) -> None:
        if node["NodeID"] in self.unfit:  # said once: its check and a run's task may both have found it
            return
        self.unfit[node["NodeID"]] = f"{name(node)}: {'; '.join(lacks)}"
        self._log(f"{self.unfit[node['NodeID']]}; it joined after the check and cannot run REI's runs: they go to "
                  "the other nodes")

    def excluded(self) -> dict[str, Any]:
        """Task options that keep a run off the nodes found unfit (Ray's node id label); {} when none is."""
        with self._lock:
            ids = sorted(self.unfit)
        return {"label_selector": {"ray.io/node-id": f"!in({','.join(ids)})"}} if ids else {}

    def nowhere(self) -> str | None:
        """Why no alive node can take a run: each offering ``RESOURCE`` is unfit (what each lacks); None: one can."""
        with self._lock:
            try:
                alive = [node["NodeID"] for node in offering(self._ray.nodes())]
            except Exception:  # noqa: BLE001 - Ray's node list out of reach: try the run again
                return None
            if alive and all(node in self.unfit for node in alive):
                return "no Ray node can run REI's runs: " + "; ".join(self.unfit[node] for node in alive)
            return None


def offering(nodes: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The alive nodes (of ``ray.nodes()``) that runs go to: those offering one ``RESOURCE`` and one CPU."""
    return [node for node in nodes if node.get("Alive") and node.get("Resources", {}).get(RESOURCE, 0) >= 1
            and node.get("Resources", {}).get("CPU", 0) >= 1]


def slots(nodes: list[dict[str, Any]]) -> int:
    """How many runs the nodes take at a time: per node the fewer of its CPUs and its ``RESOURCE``."""
    return sum(_slots(node) for node in offering(nodes))


def _slots(node: dict[str, Any]) -> int:
    return int(min(node["Resources"]["CPU"], node["Resources"][RESOURCE]))


class NodesUnfitError(RuntimeError):
    """Some nodes of the cluster cannot run REI's runs, or none offers ``RESOURCE``; the message names each and
    what it lacks."""
