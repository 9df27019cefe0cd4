// expect: 5:11 org.rei.layout.disconnected | C
testcase T {
  room R {
    floor A right B
    floor C
    floor B
    robot r : Waffle on A
  }
  mission M { goto A goto B }
}
