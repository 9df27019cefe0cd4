// expect: 7:33 org.eclipse.xtext.diagnostics.Diagnostic.Syntax | Expected a number
testcase T {
  room R size 3 x 2 {
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
  monitor { close 0.25 collision }
}
