// expect: 6:51 org.rei.dsl.roomTooLarge | floorSize 0.0000001 m cuts the map ../maps/small.yaml (12 x 8 cells of 0.1 m) into
// An editor user typing 0.0000001 on the way to 0.05 gets this message at the number (counted without overflow before
// any block is made), not a dead language server; the room has no floors then, and the floors it names are not
// reported one by one.
testcase T {
  room R occupancy "../maps/small.yaml" floorSize 0.0000001 {
    object crate : Box on F_4_2
    robot r : Waffle on F_2_1
  }
  mission M { goto F_4_1 goto F_2_2 }
}
