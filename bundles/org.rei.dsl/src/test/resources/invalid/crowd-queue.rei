// expect: 13:37 org.rei.dsl.areaUnreachable | Floor C cannot be reached from the crowd's from floors (B) through neighbouring floors: the crowd queues on its way
// expect: 13:45 org.rei.dsl.nonPositive | A queue lets one person pass every so many seconds, above 0: got 0
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
    crowd c 1 from [B] to [D] queue C every 0s
  }
  mission M { goto B goto A }
}
