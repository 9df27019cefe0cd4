// expect: 3:31 org.rei.dsl.nonPositive | Floor size must be positive
testcase T {
  room R size 3 x 2 floorSize -0.5 {
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
}
