// A search example for faults (docs/search.md, "Faults"; docs/faults.md): the robot's only way to its goals is a
// corridor one floor wide, and a person crosses it just as the robot arrives. With its lidar the reference
// navigation waits for the person; blackout.yaml searches when the lidar goes dark and for how long, and shrinks
// a collision to a shorter blackout.
testcase BlackoutCrossing {
  room Hall map "
    ###.###
    #.....#
    #.#.###
  " {
    human walker trajectory [F_2_0 @ 6s, F_2_2 @ 8s]
    robot tb3 : Waffle on F_0_1
  }
  mission Through {
    goto F_3_1
    goto F_4_1
  }
  monitor { close 0.25 collision 0.01 maxHumanCollisions 1 }
}
