// expect: 13:24 org.rei.dsl.areaUnreachable | Floor C cannot be reached from B, the first of the crowd's from floors
// expect: 13:34 org.rei.dsl.areaUnreachable | Floor C cannot be reached from the crowd's from floors (B)
// expect: 10:11 org.rei.layout.disconnected | floor C is not connected to the start floor A
testcase T {
  room R {
    floor A right B left W1
    floor B left A right D
    floor D left B right W2
    wall W1 wall W2
    floor C bottom W3
    wall W3
    robot r : Waffle on A
    crowd c 1 from [B, C] to [D, C]
  }
  mission M { goto B goto A }
}
