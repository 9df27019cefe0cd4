// expect: 13:14 org.rei.dsl.faultParameter | 'slip' is a fault of the drive, not of the odometry
// expect: 14:31 org.rei.dsl.faultParameter | A commands latency fault has no 'fraction' (its parameter: delay)
// expect: 15:14 org.rei.dsl.faultParameter | A commands loss fault needs 'probability'
// expect: 16:25 org.rei.dsl.outOfRange | The fraction of the commanded motion the robot makes: expected more than 0 and at most 1
// expect: 17:10 org.rei.dsl.faultParameter | A pose kidnap fault needs an offset: 'dx', 'dy' or 'dyaw' other than 0
// expect: 18:28 org.rei.dsl.nonPositive | The delay must be positive, in seconds (a whole number of control periods)
testcase T {
  room R size 3 x 2 {
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
  faults {
    odometry slip fraction 0.5
    commands latency fraction 0.5 delay 0.2s
    commands loss from 2s
    drive slip fraction 1.5
    pose kidnap dx 0 from 3s
    commands latency delay 0s from 1s
  }
}
