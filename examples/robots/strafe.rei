// SPDX-License-Identifier: EPL-2.0
// A holonomic robot strafes to a goal 2 m to its left, its heading unchanged:
//   rei sim examples/robots/strafe.rei --controller script:examples/robots/strafe.script
// (the script commands the sideways speed alone); the reference navigation (--controller nav) strafes it there too,
// its heading kept (docs/robots.md#drives).
import "omni_base.rei"
testcase Strafe {
  room Lane size 1 x 4 {
    robot omni : OmniBase on F_0_0
  }
  mission Left {
    tolerance 0.15
    goto F_0_2 within 30s
    goto F_0_2
  }
  monitor { close 0.25 collision 0.01 }
}
