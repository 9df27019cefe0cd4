// expect: 9:25 org.eclipse.xtext.diagnostics.Diagnostic.Syntax | Expected a number of seconds
// expect: 9:25 org.eclipse.xtext.diagnostics.Diagnostic.Syntax | mismatched input 'five' expecting RULE_INT
testcase T {
  room R size 3 x 2 {
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
  faults {
    laser blackout from five to 7s
  }
}
