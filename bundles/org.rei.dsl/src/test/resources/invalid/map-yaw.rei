// expect: 5:15 org.rei.dsl.mapUnreadable | Cannot use the map ../maps/yaw.yaml:3:9: origin: a yaw of 0.5 is not supported
// The floors of a map that cannot be read are not reported one by one: the map's error says why there are none.
testcase T {
  room R floorSize 0.2
    occupancy "../maps/yaw.yaml" {
    robot r : Waffle on F_2_1
  }
  mission M { goto F_4_1 goto F_4_2 }
}
