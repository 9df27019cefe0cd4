// A search example (docs/search.md): the robot's only way to its goals is a corridor one floor wide, and a
// person's lane crosses it. In this base case the person crosses long after the robot has passed; rei search
// looks for the start time and walking speed at which they meet. The bin stands in an alcove, out of the way:
// shrinking finds that a failure does not need it.
testcase Crossing {
  room Hall map "
    ###.###
    #.....#
    #.#.###
  " {
    object bin1 : Bin on F_0_0
    human walker trajectory [F_2_0 @ 20s, F_2_2 @ 24s]
    robot tb3 : Waffle on F_0_1
  }
  mission Through {
    goto F_3_1
    goto F_4_1
  }
  monitor { close 0.25 collision 0.01 maxHumanCollisions 1 }
}
