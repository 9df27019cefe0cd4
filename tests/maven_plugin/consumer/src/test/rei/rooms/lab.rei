testcase Lab {
  room Lab size 3 x 3 {
    object crate : Box on F_1_1
    robot tb3 : Waffle on F_0_0
  }
  mission Around { goto F_2_0 goto F_2_2 }
}
