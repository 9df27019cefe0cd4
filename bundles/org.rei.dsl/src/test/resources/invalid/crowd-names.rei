// expect: 5:11 org.rei.dsl.duplicateName | Crowd 'shoppers' names its people shoppers_1 to shoppers_3, and shoppers_2 is already used on line 6
// expect: 8:11 org.rei.dsl.duplicateName | Group 'F_2' names its people F_2_1 to F_2_2, and F_2_1 is already used by a floor or wall derived
testcase T {
  room R size 8 x 4 {
    crowd shoppers 3 from [F_0_0, F_0_1] to [F_7_0]
    human shoppers_2 route [F_3_3]
    human shoppers_4 route [F_3_2]
    group F_2 2 route [F_4_2]
    robot r : Waffle on F_4_0
  }
  mission M { goto F_4_1 goto F_5_2 }
}
