// A larger room: two aisles of shelves, two people at work, and a round trip through all four corners.
testcase WarehouseRound {
  room Warehouse size 12 x 8 {
    object shelfA1 : Shelf on F_3_2
    object shelfA2 : Shelf on F_4_2
    object shelfA3 : Shelf on F_5_2
    object shelfB1 : Shelf on F_6_5
    object shelfB2 : Shelf on F_7_5
    object shelfB3 : Shelf on F_8_5
    object bin1 : Bin on F_10_3
    object crate1 : Box on F_1_6
    human picker trajectory [F_2_4 @ 0s, F_9_4 @ 20s] loop
    human driver trajectory [F_11_1 @ 0s, F_11_6 @ 15s, F_9_7 @ 22s] once
    robot tb3 : Waffle on F_0_0
  }
  mission Round {
    timeout 180s
    goto F_11_0
    goto F_10_7
    goto F_0_7
    goto F_0_0
  }
  monitor { close 0.3 collision 0.01 maxHumanCollisions 1 }
}
