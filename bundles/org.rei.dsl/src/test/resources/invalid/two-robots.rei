// expect: 5:5 org.rei.dsl.multipleRobots | Room 'R' already has a robot on line 4: expected one robot per test case
testcase T {
  room R size 3 x 2 {
    robot r : Waffle on F_0_0
    robot s : Waffle on F_1_0
  }
  mission M { goto F_1_1 goto F_2_1 }
}
