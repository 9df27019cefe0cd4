// expect: 5:19 org.rei.layout.inconsistentLoop | B
testcase T {
  room R {
    floor A right B
    floor B right A
    robot r : Waffle on A
  }
  mission M { goto A goto B }
}
