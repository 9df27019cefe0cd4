// expect: 11:31 org.rei.dsl.faultTimeOrder | 'to' must be after 'from' (7.0 s)
// expect: 12:33 org.rei.dsl.outOfRange | The pulse must be longer than 0 s and at most the period (2.0 s)
// expect: 13:41 org.rei.dsl.outOfRange | The duty is a share of the period
// expect: 14:53 org.rei.dsl.faultTimeOrder | The gain's times must increase: 5.0 s after 10.0 s
testcase T {
  room R size 3 x 2 {
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
  faults {
    laser blackout from 7s to 5s
    laser freeze every 2s pulse 3s
    laser noise sigma 0.1 every 2s duty 150%
    laser impulse rate 0.01 gain 0.2 at 10s, 0.8 at 5s
  }
}
