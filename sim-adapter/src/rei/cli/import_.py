# SPDX-License-Identifier: EPL-2.0
"""`rei import BAG -o OUT --case CASE`: a recorded robot run (ROS 1 .bag, ROS 2 sqlite3 or MCAP) as a REI run.

Writes OUT/streams/state.msgpack (the pose topic as the judged pose, the odometry as the robot's belief, the
newest scan's minimum), OUT/streams/mission.msgpack and OUT/mission_info.json (the goals sent and the navigation's
results, when the bag has them), OUT/case/ (CASE generated, when it is a .rei file) and OUT/sim.json, so that
`rei evaluate OUT` judges the real run in the modelled room: signals, utilities, verdicts, report (docs/ros.md).
Default topics: the pose from /amcl_pose if the bag has it, else /odom; /odom and /scan when present; goals and
results from move_base's /move_base/goal and /move_base/result (ROS 1), else nav2's /goal_pose and
/navigate_to_pose/_action/status (ROS 2), when present. Exit 0: imported; 2: bad arguments or a bag that cannot
be imported (the message names the topic and time).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from rei.cli._case import case_folder, prepare_output
from rei.cli.errors import EXIT_OK, CommandError


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `import` subcommand."""
    parser = subparsers.add_parser("import", help="turn a recorded robot run (a ROS bag) into a run REI judges",
                                   description=__doc__.split("\n\n", 1)[1] if __doc__ else None)
    parser.add_argument("bag", metavar="BAG", type=Path, help="a ROS 1 .bag file or a ROS 2 bag folder or file")
    parser.add_argument("-o", "--output", required=True, metavar="OUT", type=Path, help="output folder")
    parser.add_argument("--case", required=True, metavar="CASE", type=Path,
                        help="the .rei test case (or generated folder) modelling the room the robot drove in")
    parser.add_argument("--pose-topic", metavar="T", help="the judged pose: nav_msgs/Odometry, "
                        "geometry_msgs/PoseStamped or PoseWithCovarianceStamped (default /amcl_pose, else /odom)")
    parser.add_argument("--odom-topic", metavar="T", help="the robot's odometry, nav_msgs/Odometry (default /odom "
                        "when present; 'none' to leave it out)")
    parser.add_argument("--scan-topic", metavar="T", help="sensor_msgs/LaserScan (default /scan when present; "
                        "'none' to leave it out)")
    parser.add_argument("--goal-topic", metavar="T", help="goals sent: move_base_msgs/MoveBaseActionGoal or "
                        "geometry_msgs/PoseStamped (default /move_base/goal, else /goal_pose, when present; 'none')")
    parser.add_argument("--result-topic", metavar="T", help="the navigation's results: "
                        "move_base_msgs/MoveBaseActionResult or action_msgs/GoalStatusArray (default "
                        "/move_base/result, else /navigate_to_pose/_action/status, when present; 'none')")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from rei.bags.importer import import_bag
    from rei.bags.reader import BagError, topics_of

    bag = args.bag.resolve()
    if not bag.exists():
        raise CommandError(f"{args.bag}: no such bag")
    try:
        topics = _topics(args, topics_of(bag))
    except BagError as error:
        raise CommandError(str(error)) from None
    out = args.output.resolve()
    prepare_output(out)
    case_dir = case_folder(args.case, out)
    print(f"importing {bag.name}: " + ", ".join(f"{role} {topic}" for role, topic in topics.items()), flush=True)
    try:
        result = import_bag(bag, out, case_dir, topics, progress=_progress)
    except BagError as error:
        raise CommandError(str(error)) from None
    print(f"{result.messages} messages, {result.duration:.1f} s of robot time, {result.states} states in "
          f"{result.wall_time:.1f} s ({result.messages_per_second:.0f} messages/s): {out / 'streams'}")
    if "goal" in topics:
        failed = f", {result.failed_tasks} failed" if result.failed_tasks else ""
        print(f"mission: {result.goals} goal(s){failed}" if result.goals
              else f"mission: no goals on {topics['goal']}: the mission's requirements on goals will not apply")
    print(f"judge it with: rei evaluate {out}")
    return EXIT_OK


#: Topics each optional role is read from when the bag has them and no option names one, in order of preference.
DEFAULT_TOPICS = {
    "odom": ("/odom",),
    "scan": ("/scan",),
    "goal": ("/move_base/goal", "/goal_pose"),
    "result": ("/move_base/result", "/navigate_to_pose/_action/status"),
}


def _topics(args: argparse.Namespace, available: dict[str, str]) -> dict[str, str]:
    """role -> topic from the options and what the bag has (a given topic is checked when the bag is read)."""
    pose = args.pose_topic or next((t for t in ("/amcl_pose", "/odom") if t in available), None)
    if pose is None:
        raise CommandError(f"{args.bag}: no /amcl_pose or /odom; name the pose topic with --pose-topic (the bag "
                           f"has: {', '.join(sorted(available)) or 'no topics'})")
    topics = {"pose": pose}
    for role, defaults in DEFAULT_TOPICS.items():
        given = getattr(args, f"{role}_topic")
        if given is not None and given != "none":
            topics[role] = given
        elif given is None:
            found = next((topic for topic in defaults if topic in available), None)
            if found is not None and not (role == "odom" and pose == found):
                topics[role] = found
    return topics


def _progress(t: float) -> None:
    if sys.stderr.isatty():
        print(f"\rimported {t:7.1f} s", end="", file=sys.stderr, flush=True)
