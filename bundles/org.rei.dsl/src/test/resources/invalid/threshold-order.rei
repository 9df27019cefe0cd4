// expect: 7:19 org.rei.dsl.thresholdOrder | The close threshold must be larger than the collision threshold (0.01 m)
testcase T {
  room R size 3 x 2 {
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
  monitor { close 0.005 collision 0.01 }
}
