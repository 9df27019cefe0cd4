// expect: 5:29 org.rei.dsl.floorOccupied | Floor F_1_0 is already taken by 'crate'
testcase T {
  room R size 3 x 2 {
    object crate : Box on F_1_0
    object table : Table on F_1_0
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
}
