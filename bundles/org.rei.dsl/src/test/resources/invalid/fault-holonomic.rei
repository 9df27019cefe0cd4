// expect: 12:11 org.rei.dsl.faultParameter | A stuck wheel is a fault of a differential drive: the robot r (Omni) is holonomic
// SPDX-License-Identifier: EPL-2.0
// A holonomic robot has no left or right wheel to stick; its slip is a fault it has (docs/robots.md#drives).
import "../catalogues/omni.rei"
testcase T {
  room R size 3 x 2 {
    robot r : Omni on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
  faults {
    drive slip fraction 0.5
    drive stuck wheel left from 2s
  }
}
