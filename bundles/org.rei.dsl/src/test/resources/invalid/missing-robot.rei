// expect: 3:8 org.rei.dsl.missingRobot | Room 'R' has no robot
testcase T {
  room R size 3 x 2 {
    object crate : Box on F_1_0
  }
  mission M { goto F_1_1 goto F_2_1 }
}
