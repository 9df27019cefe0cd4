// expect: 2:10 org.rei.dsl.missingMission | Test case 'T' has no mission
testcase T {
  room R size 3 x 2 {
    robot r : Waffle on F_0_0
  }
}
