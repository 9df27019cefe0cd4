// expect: 7:24 org.eclipse.xtext.diagnostics.Diagnostic.Syntax | missing 'on' at 'at'
// expect: 7:27 org.eclipse.xtext.diagnostics.Diagnostic.Syntax | mismatched input 'F_1_0' expecting '}'
// expect: 10:3 org.eclipse.xtext.diagnostics.Diagnostic.Syntax | missing EOF at 'mission'
// expect: 7:24 org.eclipse.xtext.diagnostics.Diagnostic.Linking | Unknown floor 'at'
testcase T {
  room R size 3 x 2 {
    object crate : Box at F_1_0
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
}
