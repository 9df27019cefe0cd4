// expect: 12:25 org.rei.dsl.stopUnreachable | Stop C cannot be reached from the stop before it, B
// expect: 12:38 org.rei.dsl.stopUnreachable | Stop A cannot be reached from the stop before it, C
// expect: 9:11 org.rei.layout.disconnected | floor C is not connected to the start floor A
testcase T {
  room R {
    floor A right B left W1
    floor B left A right W2
    wall W1 wall W2
    floor C bottom W3
    wall W3
    robot r : Waffle on A
    human ann route [B, C, C wait 1, A] loop
  }
  mission M { goto B goto A }
}
