// expect: 12:27 org.rei.dsl.goalUnreachable | Goal C cannot be reached from the robot's floor A
// expect: 8:11 org.rei.layout.disconnected | floor C is not connected to the start floor A
testcase T {
  room R {
    floor A right B left W1
    floor B left A right W2
    wall W1 wall W2
    floor C bottom W3
    wall W3
    robot r : Waffle on A
  }
  mission M { goto B goto C }
}
