// expect: 9:22 org.rei.dsl.floorOccupied | 'bob' starts 0.5 m from 'ann' (on F_2_2, centre to centre): their bodies touch
// expect: 13:22 org.rei.dsl.floorOccupied | 'fay' starts 0.5 m from 'eve' (on F_8_1, centre to centre)
// On 0.5 m floors two people of the default Human (radius 0.25) on neighbouring floors touch, and the pedestrian
// model refuses them at the run's start; on diagonal neighbours (0.71 m) they stand. Above and below count as beside.
testcase T {
  room R size 12 x 6 floorSize 0.5 {
    robot r : Waffle on F_0_5
    human ann route [F_2_2, F_9_4]
    human bob route [F_3_2, F_9_3]
    human cat route [F_5_3, F_1_1]
    human dan route [F_6_4, F_1_0]
    human eve route [F_8_1, F_4_0]
    human fay route [F_8_2, F_2_4]
  }
  mission M { goto F_1_5 goto F_2_5 }
}
