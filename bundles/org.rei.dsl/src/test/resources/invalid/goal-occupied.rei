// expect: 7:31 org.rei.dsl.goalOccupied | Goal F_2_1 is occupied by 'crate'
testcase T {
  room R size 3 x 2 {
    object crate : Box on F_2_1
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
}
