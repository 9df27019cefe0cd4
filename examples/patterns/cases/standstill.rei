// Triggers SIG_ROBOT_STILL_IN_TASK: driven by standstill.script, the robot reaches F_1_0 and stands there 6 s
// before its command timeline ends (and its task with it).
testcase StandStill {
  room Corridor size 5 x 1 {
    robot tb3 : Waffle on F_0_0
  }
  mission WaitAtTheDoor { goto F_1_0 within 60s goto F_1_0 }
}
