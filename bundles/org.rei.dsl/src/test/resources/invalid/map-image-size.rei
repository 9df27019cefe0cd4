// expect: 5:15 org.rei.dsl.mapUnreadable | Cannot use the map ../maps/short.yaml:1:8: image: 
// The floors of a map that cannot be read are not reported one by one: the map's error says why there are none.
testcase T {
  room R floorSize 0.2
    occupancy "../maps/short.yaml" {
    robot r : Waffle on F_2_1
  }
  mission M { goto F_4_1 goto F_4_2 }
}
