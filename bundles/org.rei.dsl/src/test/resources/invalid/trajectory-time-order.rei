// expect: 4:57 org.rei.dsl.trajectoryTimeOrder | Times must increase strictly: expected a time after 5s
testcase T {
  room R size 3 x 2 {
    human h trajectory [F_2_0 @ 0s, F_2_1 @ 5s, F_1_1 @ 5s] loop
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
}
