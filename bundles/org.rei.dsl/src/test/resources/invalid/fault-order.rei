// expect: 10:3 org.eclipse.xtext.diagnostics.Diagnostic.Syntax | 'faults' is out of place: a test case has its room, then mission, faults { } and monitor { } in this order
// SPDX-License-Identifier: EPL-2.0
// The faults after the monitor (the parser's own message was "mismatched input 'faults' expecting '}'").
testcase T {
  room R size 3 x 2 {
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
  monitor { close 0.25 collision 0.01 }
  faults {
    laser blackout from 1s to 2s
  }
}
