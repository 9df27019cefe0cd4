// expect: 4:33 org.rei.dsl.negativeTime | Times start at 0s or later
testcase T {
  room R size 3 x 2 {
    human h trajectory [F_2_0 @ -1s, F_2_1 @ 5s]
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
}
