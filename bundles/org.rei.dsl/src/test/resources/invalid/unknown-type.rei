// expect: 4:20 org.eclipse.xtext.diagnostics.Diagnostic.Linking | Unknown object type 'Sofa': expected the name of an object type (Floor, Wall, Box
testcase T {
  room R size 3 x 2 {
    object crate : Sofa on F_1_0
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
}
