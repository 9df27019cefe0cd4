# SPDX-License-Identifier: EPL-2.0
"""Can every node of a Ray cluster run REI's runs? Asked once at connect time, node by node.

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
"""

from __future__ import annotations

import contextlib
import re
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


def check_node(router: bool) -> list[str]:
    """On the node: what it lacks to run REI's runs (empty: nothing). ``router``: the runs start a WAMP router."""
    problems = []
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
    return problems


def check_cluster(ray: Any, router: bool = False, timeout: float = CHECK_TIMEOUT) -> list[tuple[str, str]]:
    """``(node IP (ID), what it lacks)`` for every alive node offering ``RESOURCE`` that cannot run REI's runs; []
    if all can. ``NodesUnfitError``: no alive node offers it."""
    from ray.util.scheduling_strategies import NodeAffinitySchedulingStrategy

    remote = ray.remote(num_cpus=0, max_retries=0)(check_node)
    refs = {}
    nodes = offering(ray.nodes())
    if not nodes:
        alive = sum(1 for node in ray.nodes() if node.get("Alive"))
        raise NodesUnfitError(f"{NO_RESOURCE} ({alive} node(s) alive)")
    for node in nodes:
        strategy = NodeAffinitySchedulingStrategy(node["NodeID"], soft=False)
        refs[remote.options(scheduling_strategy=strategy).remote(router)] = node
    _, late = ray.wait(list(refs), num_returns=len(refs), timeout=timeout) if refs else ([], [])
    problems = []
    for ref, node in refs.items():
        name = f"node {node.get('NodeManagerAddress', '?')} ({node['NodeID'][:12]})"
        if ref in late:
            problems.append((name, f"did not answer REI's check within {timeout:.0f} s"))
            with contextlib.suppress(Exception):
                ray.cancel(ref, force=True)
            continue
        try:
            lacks = ray.get(ref)
        except Exception as error:  # noqa: BLE001 - the check could not even run there: REI or its Python is broken
            lines = [line.strip() for line in _ANSI.sub("", str(error)).splitlines() if line.strip()]
            # the innermost cause is the last line of the node's traceback ("ModuleNotFoundError: No module ...")
            cause = lines[-1] if lines else type(error).__name__
            hint = "install REI there (pip install rei-*.whl, docs/campaigns.md#setting-up-a-cluster)"
            problems.append((name, f"cannot run REI's check ({cause}); {hint}"))
            continue
        problems += [(name, lack) for lack in lacks]
    return problems


def offering(nodes: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The alive nodes (of ``ray.nodes()``) that runs go to: those offering one ``RESOURCE`` and one CPU."""
    return [node for node in nodes if node.get("Alive") and node.get("Resources", {}).get(RESOURCE, 0) >= 1
            and node.get("Resources", {}).get("CPU", 0) >= 1]


def slots(nodes: list[dict[str, Any]]) -> int:
    """How many runs the nodes take at a time: per node the fewer of its CPUs and its ``RESOURCE``."""
    return sum(int(min(node["Resources"]["CPU"], node["Resources"][RESOURCE])) for node in offering(nodes))


class NodesUnfitError(RuntimeError):
    """Some nodes of the cluster cannot run REI's runs, or none offers ``RESOURCE``; the message names each and
    what it lacks."""
