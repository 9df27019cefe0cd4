// expect: 12:14 org.rei.dsl.faultParameter | An odometry drift fault needs 'scale' other than 1 or 'bias' other than 0
// expect: 13:14 org.rei.dsl.faultParameter | An odometry drift fault needs 'scale' other than 1 or 'bias' other than 0
// SPDX-License-Identifier: EPL-2.0
// A drift that changes nothing: the simulator refuses it (rei.sim.faults.motion.Drift), so the language does.
testcase T {
  room R size 3 x 2 {
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
  faults {
    odometry drift scale 1.05 bias 0
    odometry drift scale 1 from 2s
    odometry drift bias 0 scale 1.0
    odometry drift scale 1 bias 2
  }
}
