// A search example with a crowd (docs/search.md): the robot drives along a hall three floors wide while people
// come the other way, one after another, from its far end. In this base case three of them walk at a rate of one
// every two seconds and see the robot (avoids, the default): they pass it and nobody is hit. rei search looks for
// how many, how often and with which behaviour towards the robot they make it drive into one of them.
testcase CrowdCorridor {
  room Hall size 12 x 3 {
    crowd oncoming 3 from [F_10_0, F_10_1, F_10_2, F_11_0, F_11_1, F_11_2]
                     to [F_1_0, F_1_2, F_2_0, F_2_1, F_2_2]
      rate 0.5 speed 1.0 to 1.3
    robot tb3 : Waffle on F_0_1
  }
  mission Along {
    goto F_6_1
    goto F_9_1
  }
  monitor { close 0.25 collision 0.01 maxHumanCollisions 1 }
}
