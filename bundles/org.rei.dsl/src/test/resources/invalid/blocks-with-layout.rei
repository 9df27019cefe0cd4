// expect: 5:11 org.rei.dsl.blocksWithLayout | derives its floors and walls from its size or map
// expect: 5:11 org.rei.layout.disconnected | floor extra is not connected
testcase T {
  room R size 3 x 2 {
    floor extra
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
}
