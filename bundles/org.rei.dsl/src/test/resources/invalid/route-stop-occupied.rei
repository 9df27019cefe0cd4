// expect: 7:29 org.rei.dsl.stopOccupied | Stop F_2_1 is occupied by 'table'
// expect: 8:15 org.rei.dsl.floorOccupied | Floor F_3_0 is already taken by 'ann'
// expect: 10:25 org.rei.dsl.floorOccupied | Floor F_0_0 is already taken by 'cat'
testcase T {
  room R size 4 x 2 {
    object table : Table on F_2_1
    human ann route [F_3_0, F_2_1 wait 2s, F_0_0] scared
    human bob route [F_3_0, F_1_0]
    human cat route [F_0_0]
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_0 }
}
