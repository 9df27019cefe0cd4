// expect: 6:10 org.rei.layout.orphanWall | W
testcase T {
  room R {
    floor A right B
    floor B
    wall W
    robot r : Waffle on A
  }
  mission M { goto A goto B }
}
