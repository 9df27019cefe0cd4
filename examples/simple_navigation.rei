// Thesis 7.3, the simple navigation scenario: in a small room the robot drives to the "elevator" corner
// (top right) while a person walks back and forth across its way.
testcase SimpleNavigation {
  room Lab size 6 x 4 {
    object table1 : Table on F_2_1
    object shelf1 : Shelf on F_0_3
    human walker trajectory [F_1_2 @ 0s, F_3_2 @ 6s, F_4_2 @ 9s] loop
    robot tb3 : Waffle on F_0_0
  }
  mission ToElevator {
    goto F_4_0
    goto F_5_3
  }
  monitor { close 0.25 collision 0.01 maxHumanCollisions 1 }
}
