// expect: 4:27 org.eclipse.xtext.diagnostics.Diagnostic.Linking | Unknown floor 'F_9_9': expected the name of a floor
testcase T {
  room R size 3 x 2 {
    object crate : Box on F_9_9
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
}
