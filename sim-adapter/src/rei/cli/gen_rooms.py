# SPDX-License-Identifier: EPL-2.0
"""`rei gen-rooms --size S|--map FILE.yaml [--density D] [--humans N [--people reactive [--behaviour B]]] --count K
--seed S [--catalogue FILE] -o DIR`: procedural test rooms.

Writes K `.rei` test cases (thesis 7.4): a grid of floors with walls, furniture from the catalogue, humans
walking lanes of free floors, the robot on the left wall and a mission whose first goal is on the right wall.
The same settings and seed always give the same files. Sizes: small 7 x 5 m (dense: 10 objects), medium
10 x 7 m (sparse: 9 objects, one walking human), large 15 x 10 m (sparse: 20 objects, two humans); see
docs/campaigns.md. `--catalogue FILE` furnishes the rooms with a user catalogue's object types instead (equally
frequent, at most 1.2 x 1.2 m each) and gives the robot its robot type (`--robot NAME` when it has several); the
rooms import it. `--map FILE.yaml` furnishes a real building instead: a ROS occupancy map (map_server format),
its free blocks of `--floor-size` metres (1.0 by default) as floors, the rooms written as `occupancy` rooms that
name the map by its path relative to them (rei.rooms.on_map; a room drawn on a map is drawn again until the planner
finds every leg). `--people reactive` makes the humans people who see the robot (docs/people.md): each loops round
a route of 2 or 3 stops on free floors, reachable from each other, with the behaviour `--behaviour` gives (avoids by
default; mixed: each person's drawn). Every leg of every mission is checked with the reference navigation's planner (`--no-check`
skips it). Exit 0: written; 1: a room failed the check; 2: bad arguments, an invalid catalogue or map.
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from rei.cli.errors import EXIT_INVALID, EXIT_OK, CommandError

#: What the generated humans are: on trajectories (rails), or people who see the robot (reactive, on routes).
PEOPLE = ("rails", "reactive")


def reactive(people: str, behaviour: str | None) -> str | None:
    """``--people`` and ``--behaviour`` as rei.rooms takes them: the people's behaviour, None for humans on rails."""
    if people == "rails":
        if behaviour is not None:
            raise CommandError("--behaviour is the behaviour of people who see the robot: give --people reactive too")
        return None
    return behaviour or "avoids"


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `gen-rooms` subcommand."""
    from rei.rooms.classes import DENSITIES, SIZES
    from rei.rooms.model import BEHAVIOURS, MIXED

    parser = subparsers.add_parser("gen-rooms", help="generate procedural test rooms (.rei files)",
                                   description=__doc__.split("\n\n", 1)[1] if __doc__ else None)
    where = parser.add_mutually_exclusive_group(required=True)
    where.add_argument("--size", choices=SIZES, help="room class")
    where.add_argument("--map", type=Path, metavar="FILE.yaml",
                       help="furnish this occupancy map (ROS map_server YAML) instead of a grid room")
    parser.add_argument("--floor-size", type=float, metavar="M",
                        help="with --map: the edge of a floor block, m (default 1.0)")
    parser.add_argument("--unknown-free", action="store_true",
                        help="with --map: unknown cells are floor (default: obstacles)")
    parser.add_argument("--density", choices=DENSITIES, help="furniture density (default: the class's)")
    parser.add_argument("--humans", type=int, metavar="N", help="walking humans (default: the class's)")
    parser.add_argument("--people", choices=PEOPLE, default="rails",
                        help="rails: humans walk lanes on trajectories (default); reactive: people who see the robot, "
                             "on routes")
    parser.add_argument("--behaviour", choices=(*BEHAVIOURS, MIXED), metavar="B",
                        help=f"with --people reactive: their behaviour towards the robot, one of "
                             f"{', '.join((*BEHAVIOURS, MIXED))} (mixed: each person's drawn; default avoids)")
    parser.add_argument("--count", type=int, default=1, metavar="K", help="rooms to write (default 1)")
    parser.add_argument("--seed", type=int, default=0, metavar="S", help="seed (default 0)")
    parser.add_argument("--catalogue", type=Path, metavar="FILE",
                        help="furnish the rooms from this user catalogue (docs/language.md, 'Catalogues')")
    parser.add_argument("--robot", metavar="NAME", help="the catalogue's robot type to use (default: its only one)")
    parser.add_argument("-o", "--output", required=True, type=Path, metavar="DIR", help="output folder")
    parser.add_argument("--no-check", action="store_true", help="do not check the missions with the planner")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from rei.rooms import DEFAULT_TYPES, GenerationError, write_rooms
    from rei.rooms.catalogue import room_types

    if args.count < 1:
        raise CommandError(f"--count must be at least 1, got {args.count}")
    if args.robot is not None and args.catalogue is None:
        raise CommandError("--robot picks a robot type of --catalogue FILE: give the catalogue too")
    if args.map is None and (args.floor_size is not None or args.unknown_free):
        raise CommandError("--floor-size and --unknown-free describe the floors of --map FILE.yaml: give the map too")
    people = reactive(args.people, args.behaviour)
    try:
        types = DEFAULT_TYPES if args.catalogue is None else room_types(args.catalogue, args.robot)
        if args.map is not None:
            written = _write_map_rooms(args, types, people)
        else:
            written = write_rooms(args.output, args.size, args.density, args.humans, args.seed, args.count, types,
                                  people)
    except (ValueError, GenerationError) as error:
        raise CommandError(str(error)) from None
    except OSError as error:
        raise CommandError(f"cannot write to {args.output}: {error.strerror or error}") from None
    failed = 0
    for room, path in written:
        # a room on a map was checked while it was drawn (drawn again until it passed)
        problems = [] if args.no_check or room.site is not None else _check(room)
        humans = f"{len(room.walkers)} humans" if room.reactive is None else f"{len(room.people)} people on routes"
        print(f"{path}  {len(room.furniture)} objects, {humans}, {len(room.goals)} goals"
              + ("" if not problems else "  UNPLANNABLE: " + "; ".join(problems)))
        failed += bool(problems)
    return EXIT_INVALID if failed else EXIT_OK


def _write_map_rooms(args: argparse.Namespace, types: Any, people: str | None) -> list[tuple[Any, Path]]:
    from rei.maps import MapError
    from rei.rooms import write_map_rooms
    from rei.rooms.on_map import load_site

    floor_size = 1.0 if args.floor_size is None else args.floor_size
    if not floor_size > 0:
        raise CommandError(f"--floor-size must be above 0 m, got {floor_size:g}")
    try:
        site = load_site(args.map, floor_size, args.unknown_free)
    except MapError as error:
        raise CommandError(str(error)) from None
    return write_map_rooms(args.output, site, args.density, args.humans, args.seed, args.count, types,
                           check=not args.no_check, reactive=people)


def _check(room: Any) -> list[str]:
    from rei.rooms.check import unplannable_legs

    return unplannable_legs(room)
