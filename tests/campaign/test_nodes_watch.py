# SPDX-License-Identifier: EPL-2.0
"""rei.campaign.nodes.Watch, the driver's record of the nodes that cannot run REI's runs, with Ray's node list
given: a node a run's task found unfit is said once, kept off the runs submitted afterwards (Ray's node id label),
and when every alive node offering 'rei' is unfit the runs are told why instead of waiting for a node forever.
And what the nodes are asked for. The real cluster's late node: tests/campaign/test_campaign_ray_cluster.py."""

from __future__ import annotations

from typing import Any

from rei.campaign.nodes import Watch


class Nodes:
    """Ray's node list, and its tasks as far as the node check uses them (asked: the node ids; never answered)."""

    def __init__(self, *nodes: dict[str, Any]) -> None:
        self.list = list(nodes)
        self.asked: list[str] = []

    def nodes(self) -> list[dict[str, Any]]:
        return self.list

    def remote(self, **_options: Any) -> Any:
        ray = self

        class Check:
            def __init__(self, _function: Any) -> None:
                pass

            def options(self, scheduling_strategy: Any) -> Any:
                ray.asked.append(scheduling_strategy.node_id)
                return self

            def remote(self, *_args: Any) -> object:
                return object()
        return Check

    def wait(self, refs: list[Any], num_returns: int, timeout: float) -> tuple[list[Any], list[Any]]:
        return [], refs


def _node(digit: str, rei: float = 1.0) -> dict[str, Any]:
    return {"NodeID": digit * 56, "NodeManagerAddress": f"10.0.0.{int(digit, 16)}", "Alive": True,
            "Resources": {"CPU": 2.0, **({"rei": rei} if rei else {})}}


def test_a_node_a_run_found_unfit_is_said_once_and_kept_off_the_later_runs() -> None:
    fit, late, other = _node("a"), _node("b"), _node("c", rei=0)  # other: offers no 'rei', gets no run anyway
    ray = Nodes(fit, late, other)
    said: list[str] = []
    watch = Watch(ray, {fit["NodeID"]}, router=False, people=False, log=said.append)
    assert watch.excluded() == {} and watch.nowhere() is None
    for _ in range(2):  # two of its runs' tasks landed there
        watch.refused(late["NodeID"], ["java not found on PATH; install a Java 17+ runtime or set JAVA_HOME"])
    assert said == [("node 10.0.0.11 (bbbbbbbbbbbb): java not found on PATH; install a Java 17+ runtime or set "
                     "JAVA_HOME; it joined after the check and cannot run REI's runs: they go to the other nodes")]
    assert watch.excluded() == {"label_selector": {"ray.io/node-id": f"!in({late['NodeID']})"}}
    assert watch.nowhere() is None  # the first node takes them
    fit["Alive"] = False
    assert watch.nowhere() == ("no Ray node can run REI's runs: node 10.0.0.11 (bbbbbbbbbbbb): java not found on "
                               "PATH; install a Java 17+ runtime or set JAVA_HOME")


def test_the_runs_at_a_time_follow_the_nodes_that_join_leave_or_cannot_run_them() -> None:
    """What `rei search --ray` keeps in flight: a node that joins mid-search is asked and its slots count at once
    (its task checks it too), one found unfit or lost no longer counts."""
    first, late = _node("a"), _node("b", rei=2.0)  # 1 and 2 runs at a time (each the fewer of CPUs and 'rei')
    ray = Nodes(first)
    watch = Watch(ray, {first["NodeID"]}, router=False, people=False, log=[].append, every=0.0)
    assert watch.slots == 1
    ray.list.append(late)
    watch.poll()
    assert watch.slots == 3 and ray.asked == [late["NodeID"]]
    watch.refused(late["NodeID"], ["no java"])
    watch.poll()
    assert watch.slots == 1 and ray.asked == [late["NodeID"]]  # asked once
    first["Alive"] = False
    watch.poll()
    assert watch.slots == 0


def test_the_nodes_are_asked_for_jupedsim_when_the_campaign_moves_people() -> None:
    """A campaign whose cases have people who see the robot (and a variant with humans) asks its nodes for the
    people server's JuPedSim too; the thesis campaign (humans on rails) does not."""
    from pathlib import Path

    from rei.campaign import load_spec
    from rei.campaign.spec import spec_moves_people

    examples = Path(__file__).resolve().parents[2] / "examples" / "campaigns"
    assert spec_moves_people(load_spec(examples / "behaviours.yaml"))
    assert not spec_moves_people(load_spec(examples / "thesis.yaml"))
