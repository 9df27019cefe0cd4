// Triggers SIG_HUMAN_NEXT_TO_ROBOT_ON_F_3_2: driven by next_to_human.script, the robot drives to F_3_2 and waits
// there while a human walks up the column x = 4 (F_4_0 to F_4_3), past F_3_2's right neighbour F_4_2.
testcase NextToHuman {
  room Hall size 5 x 4 {
    human walker trajectory [F_4_0 @ 0s, F_4_3 @ 24s] once
    robot tb3 : Waffle on F_0_2
  }
  mission ToF32 { goto F_3_2 within 60s goto F_3_2 }
}
