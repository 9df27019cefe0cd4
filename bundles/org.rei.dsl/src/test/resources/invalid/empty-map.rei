// expect: 5:14 org.rei.dsl.emptyLayout | The map draws no floor
// expect: 5:8 org.rei.dsl.missingRobot | Room 'R' has no robot
// expect: 4:10 org.rei.dsl.missingMission | Test case 'T' has no mission
testcase T {
  room R map "
    ####
  " {
  }
}
