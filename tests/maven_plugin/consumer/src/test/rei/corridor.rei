testcase Corridor {
  room Hall size 5 x 1 {
    robot tb3 : Waffle on F_0_0
  }
  mission Through { goto F_2_0 goto F_4_0 }
}
