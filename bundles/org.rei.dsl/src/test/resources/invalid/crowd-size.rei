// expect: 7:16 org.rei.dsl.tooFewPeople | A crowd has 1 person or more: got 0
// expect: 8:16 org.rei.dsl.tooFewPeople | A group has 2 people or more, its leader included: got 1
// expect: 9:20 org.rei.dsl.areaTooSmall | Crowd 'shoppers' of 40: its from floors hold at most 9 people of radius 0.25
// expect: 10:18 org.rei.dsl.areaTooSmall | Group 'family' of 5: F_7_0 and the free floors beside it hold at most 4 people of radius 0.25
testcase T {
  room R size 8 x 4 {
    crowd none 0 from [F_0_0] to [F_6_3]
    group solo 1 route [F_3_2, F_5_2]
    crowd shoppers 40 from [F_0_2, F_0_3, F_1_2, F_1_3] to [F_7_2, F_7_3]
    group family 5 route [F_7_0, F_5_0]
    robot r : Waffle on F_4_0
  }
  mission M { goto F_4_1 goto F_4_2 }
}
