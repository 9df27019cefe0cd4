// expect: 8:44 org.rei.dsl.nonPositive | A crowd's rate is above 0 people a second: got 0
// expect: 8:52 org.rei.dsl.outOfRange | A walking speed is above 0 and at most 3 m/s
// expect: 9:52 org.rei.dsl.outOfRange | The fastest walking speed of a range is at least its slowest (1.4) and at most 3 m/s: got 1
// expect: 9:62 org.rei.dsl.negativeTime | A crowd sets off at 0s or later
// expect: 10:49 org.rei.dsl.outOfRange | at least its slowest (1) and at most 3 m/s: got 3.5
testcase T {
  room R size 8 x 4 {
    crowd a 1 from [F_0_0] to [F_7_0] rate 0 speed 0
    crowd b 1 from [F_0_2] to [F_7_2] speed 1.4 to 1.0 start -2s
    human ann route [F_3_3, F_5_3] speed 1.0 to 3.5
    robot r : Waffle on F_4_0
  }
  mission M { goto F_4_1 goto F_4_2 }
}
