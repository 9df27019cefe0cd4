// expect: 10:22 org.rei.dsl.stopOccupied | Stop F_2_2 lies under 'table' (on F_3_2), which reaches over its centre
// expect: 11:29 org.rei.dsl.stopOccupied | Stop F_4_2 lies under 'table' (on F_3_2)
// A table 1.2 m long on 0.5 m floors reaches over the centres of the floors left and right of its own: no person
// starts or stops there (the run would stop at its start, the person off the walkable area). A bin 0.4 m across
// covers no other floor's centre, and the table's reach ends short of F_5_2 and F_1_2.
testcase T {
  room R size 8 x 4 floorSize 0.5 {
    object table : Table on F_3_2
    object bin : Bin on F_6_0 yaw 30
    human ann route [F_2_2, F_6_1, F_0_0]
    human bob route [F_1_0, F_4_2 wait 1s, F_5_2, F_1_2]
    robot r : Waffle on F_0_3
  }
  mission M { goto F_1_3 goto F_2_3 }
}
