// expect: 10:91 org.rei.dsl.stopOccupied | A queue's floor F_6_3 lies under 'table' (on F_5_3), which reaches over its centre
// expect: 11:91 org.rei.dsl.stopOccupied | A queue's floor F_9_0 is occupied by 'chair'
// A crowd's queue is a place where the first in line stands: not on a chair, not under a table 1.2 m long on 0.5 m
// floors that reaches over the centres of the floors beside its own. The third crowd queues beyond the table, clear.
testcase T {
  room R size 12 x 6 floorSize 0.5 {
    object table : Table on F_5_3
    object chair : Chair on F_9_0
    robot r : Waffle on F_0_5
    crowd a 1 from [F_0_0, F_1_0, F_0_1, F_1_1] to [F_10_4, F_11_4, F_10_5, F_11_5] queue F_6_3 every 2s
    crowd b 1 from [F_2_0, F_3_0, F_2_1, F_3_1] to [F_10_2, F_11_2, F_10_3, F_11_3] queue F_9_0 every 2s
    crowd c 1 from [F_4_0, F_5_0, F_4_1, F_5_1] to [F_10_0, F_11_0, F_10_1, F_11_1] queue F_7_3 every 2s
  }
  mission M { goto F_1_5 goto F_2_5 }
}
