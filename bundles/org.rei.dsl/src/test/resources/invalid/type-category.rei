// expect: 4:20 org.rei.dsl.typeCategory | Type Waffle is a ROBOT type, but 'crate' needs a STATIC type
testcase T {
  room R size 3 x 2 {
    object crate : Waffle on F_1_0
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
}
