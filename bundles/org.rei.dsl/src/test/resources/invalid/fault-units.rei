// expect: 12:31 org.eclipse.xtext.diagnostics.Diagnostic.Syntax | 'ms' is not a unit the language reads: times are seconds (5 or 5s)
// SPDX-License-Identifier: EPL-2.0
// A unit after a number: the language reads seconds (the parser's own message was "no viable alternative at input
// 'ms'").
testcase T {
  room R size 3 x 2 {
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
  faults {
    laser blackout from 1s to 2s
    commands latency delay 200ms from 3s
  }
}
