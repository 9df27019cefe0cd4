// expect: 6:11 org.rei.dsl.tooFewGoals | Mission 'M' has 1 goal(s): expected at least two
testcase T {
  room R size 3 x 2 {
    robot r : Waffle on F_0_0
  }
  mission M { goto F_2_1 }
}
