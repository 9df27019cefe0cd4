// SPDX-License-Identifier: EPL-2.0
// Crowds and groups (issue #38): the robot crosses a hall from its bottom wall to its top one while a crowd of
// twelve crosses its way from the left of the hall to the right, one person a second, each walking back and forth
// at 1.0 to 1.4 m/s, and a family of three walks up and down beside the robot's way. The generator expands the
// crowd into shoppers_1 ... shoppers_12, standing spread over their floors, and the group into family_1, its
// leader, and family_2 and family_3 beside it: each a person who sees the robot.
testcase CrowdCrossing {
  room Hall size 14 x 8 {
    object shelf1 : Shelf on F_3_7
    object table1 : Table on F_10_0
    crowd shoppers 12 from [F_0_2, F_0_3, F_0_4, F_0_5, F_1_2, F_1_3, F_1_4, F_1_5]
                      to [F_12_2, F_12_3, F_12_4, F_12_5, F_13_2, F_13_3, F_13_4, F_13_5]
      rate 1 speed 1.0 to 1.4 loop
    group family 3 route [F_5_1, F_5_6 wait 2s] speed 1.0 to 1.2 loop
    robot tb3 : Waffle on F_7_0 yaw 90
  }
  mission BottomToTop {
    goto F_7_4
    goto F_7_7
  }
  monitor { close 0.25 collision 0.01 maxHumanCollisions 1 }
}
