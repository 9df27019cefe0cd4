// expect: 8:11 org.rei.layout.overlap | floors B and E are both at cell (1, 0)
testcase T {
  room R {
    floor A right B top C
    floor B
    floor C right D
    floor D bottom E
    floor E
    robot r : Waffle on A
  }
  mission M { goto B goto D }
}
