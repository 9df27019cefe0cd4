// expect: 5:51 org.rei.dsl.negativeTime | A person sets off at 0s or later
// expect: 5:33 org.rei.dsl.negativeTime | A wait is 0s or longer
testcase T {
  room R size 4 x 2 {
    human ann route [F_3_0 wait -2s, F_3_1] start -1
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_0 }
}
