// expect: 5:12 org.rei.dsl.duplicateName | Duplicate name 'crate': names must be unique in a test case, and it is already used on line 4
testcase T {
  room R size 3 x 2 {
    object crate : Box on F_1_0
    object crate : Box on F_2_0
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
}
