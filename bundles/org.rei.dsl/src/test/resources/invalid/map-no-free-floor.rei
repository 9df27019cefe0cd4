// expect: 7:15 org.rei.dsl.emptyLayout | The map ../maps/small.yaml (12 x 8 cells of 0.1 m) has no free block of 0.5 m
// expect: 8:25 org.eclipse.xtext.diagnostics.Diagnostic.Linking | F_0_0 is not a free floor of small.yaml: 10 of its 25 cells
// expect: 10:20 org.eclipse.xtext.diagnostics.Diagnostic.Linking | F_0_0 is not a free floor
// expect: 10:31 org.eclipse.xtext.diagnostics.Diagnostic.Linking | F_1_0 is not a free floor of small.yaml: 5 of its 25 cells
testcase T {
  room R floorSize 0.5
    occupancy "../maps/small.yaml" {
    robot r : Waffle on F_0_0
  }
  mission M { goto F_0_0 goto F_1_0 }
}
