// expect: 4:13 org.rei.dsl.trajectoryTooShort | A trajectory needs at least two control points
testcase T {
  room R size 3 x 2 {
    human h trajectory [F_2_0 @ 0s]
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
}
