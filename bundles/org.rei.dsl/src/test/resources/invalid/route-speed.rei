// expect: 5:47 org.rei.dsl.outOfRange | A walking speed is above 0 and at most 3 m/s
// expect: 6:35 org.rei.dsl.outOfRange | got 3.5
testcase T {
  room R size 4 x 2 {
    human ann route [F_3_0, F_3_1] loop speed 0
    human bob route [F_2_1] speed 3.5
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_0 }
}
