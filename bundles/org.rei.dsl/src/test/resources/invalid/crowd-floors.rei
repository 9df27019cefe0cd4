// expect: 10:35 org.rei.dsl.floorOccupied | Floor F_0_3 is already taken by 'table': expected a free floor, a crowd's people stand on its from floors alone
// expect: 11:21 org.rei.dsl.floorOccupied | Floor F_0_1 is already taken by 'a'
// expect: 11:39 org.rei.dsl.floorOccupied | Floor F_1_3 is already taken by 'ann': expected a free floor for the crowd's people to walk to
// expect: 12:32 org.rei.dsl.floorOccupied | Floor F_4_0 is already taken by 'r'
// expect: 13:15 org.rei.dsl.floorOccupied | Floor F_0_0 is already taken by 'a'
testcase T {
  room R size 8 x 4 {
    object table : Table on F_0_3
    human ann route [F_1_3, F_5_3]
    crowd a 2 from [F_0_0, F_0_1, F_0_3] to [F_7_0, F_7_1]
    crowd b 1 from [F_0_1, F_3_0] to [F_1_3, F_7_0]
    crowd c 1 from [F_6_3] to [F_4_0, F_5_0]
    human bob route [F_0_0, F_2_2]
    robot r : Waffle on F_4_0
  }
  mission M { goto F_4_1 goto F_4_2 }
}
