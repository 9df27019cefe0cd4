// expect: 12:25 org.eclipse.xtext.diagnostics.Diagnostic.Syntax | Expected a finite number but found '1000
// expect: 13:25 org.eclipse.xtext.diagnostics.Diagnostic.Syntax | Expected a whole number of at most 2147483647 but found '99999999999'
// SPDX-License-Identifier: EPL-2.0
// Numbers too large to be read: a double's Infinity reached the generator as an internal error, an int's overflow
// said only 'For input string'.
testcase T {
  room R size 3 x 2 {
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
  faults {
    laser blackout from 1000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000s
    laser impulse width 99999999999
  }
}
