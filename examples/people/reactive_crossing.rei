// SPDX-License-Identifier: EPL-2.0
// People who see the robot (issue #38): the robot drives across a hall from the left wall to the right one while
// two people cross its way. Ann steps around the robot and walks back and forth; Bob sets off a little later and
// avoids other people but not the robot: he walks on as if it were not there. A pedestrian model finds their way
// between the stops, around the furniture.
testcase ReactiveCrossing {
  room Hall size 8 x 4 {
    object table1 : Table on F_1_3
    object shelf1 : Shelf on F_7_3
    human ann route [F_3_3, F_3_0 wait 2s] speed 1.1 loop avoids
    human bob route [F_5_0, F_5_3 wait 1s] start 3s ignores
    robot tb3 : Waffle on F_0_1
  }
  mission LeftToRight {
    goto F_4_1
    goto F_7_1
  }
  monitor { close 0.25 collision 0.01 maxHumanCollisions 1 }
}
