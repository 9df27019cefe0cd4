// expect: 9:27 org.eclipse.xtext.diagnostics.Diagnostic.Linking | F_1_1 is not a free floor of small.yaml: 1 of its 4 cells are obstacles (occupied or unknown)
// expect: 13:20 org.eclipse.xtext.diagnostics.Diagnostic.Linking | F_3_2 is not a free floor of small.yaml: 2 of its 4 cells are obstacles
// expect: 13:31 org.eclipse.xtext.diagnostics.Diagnostic.Linking | F_6_0 is not a floor of small.yaml: the map has 6 x 4 blocks of 0.2 m (F_0_0 to F_5_3)
// expect: 10:37 org.eclipse.xtext.diagnostics.Diagnostic.Linking | F_0_0 is not a free floor of small.yaml: 3 of its 4 cells
// Floors are the map's free blocks only (../maps/small.pgm: a pillar cell in F_1_1, unknown cells in F_3_2); the
// names of the others say why they are no floor.
testcase T {
  room R occupancy "../maps/small.yaml" floorSize 0.2 {
    object crate : Box on F_1_1
    human h trajectory [F_2_2 @ 0s, F_0_0 @ 5s]
    robot r : Waffle on F_2_1
  }
  mission M { goto F_3_2 goto F_6_0 }
}
