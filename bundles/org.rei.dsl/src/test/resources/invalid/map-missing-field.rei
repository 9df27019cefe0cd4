// expect: 5:15 org.rei.dsl.mapUnreadable | Cannot use the map ../maps/missing-field.yaml:1:1: free_thresh: missing (map_server requires it)
// The floors of a map that cannot be read are not reported one by one: the map's error says why there are none.
testcase T {
  room R floorSize 0.2
    occupancy "../maps/missing-field.yaml" {
    robot r : Waffle on F_2_1
  }
  mission M { goto F_4_1 goto F_4_2 }
}
