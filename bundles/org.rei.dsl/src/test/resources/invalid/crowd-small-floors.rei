// expect: 4:53 org.rei.dsl.areaTooSmall | Crowd 'a': its to floors hold no person of radius 0.25
testcase T {
  room R size 8 x 4 floorSize 0.5 {
    crowd a 1 from [F_0_0, F_1_0, F_0_1, F_1_1] to [F_6_0]
    robot r : Waffle on F_4_0
  }
  mission M { goto F_4_1 goto F_4_2 }
}
