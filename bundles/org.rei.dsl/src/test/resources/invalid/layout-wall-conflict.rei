// expect: 5:19 org.rei.layout.wallConflict | W
testcase T {
  room R {
    floor A right B top W
    floor B right W
    wall W
    robot r : Waffle on A
  }
  mission M { goto A goto B }
}
