// The simple navigation example (../simple_navigation.rei) with a round robot read from its URDF description.
import "catalogue.rei"
testcase RoundBotNavigation {
  room Lab size 6 x 4 {
    object table1 : Table on F_2_1
    object shelf1 : Shelf on F_0_3
    human walker trajectory [F_1_2 @ 0s, F_3_2 @ 6s, F_4_2 @ 9s] loop
    robot bot : RoundBot on F_0_0
  }
  mission ToElevator {
    goto F_4_0
    goto F_5_3
  }
  monitor { close 0.25 collision 0.01 maxHumanCollisions 1 }
}
