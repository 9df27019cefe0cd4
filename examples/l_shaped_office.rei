// An L-shaped office drawn as a map: '.' is a floor, '#' or a blank is none; walls are put around the floors.
// Names count floors from the bottom-left floor F_0_0, whatever border is drawn.
testcase OfficeCorner {
  room Office floorSize 0.8 map "
    ####
    #..#
    #..#######
    #........#
    #........#
    ##########
  " {
    object desk : Table on F_4_1
    robot tb3 : Waffle on F_0_0 yaw 90
  }
  mission AroundTheCorner {
    tolerance 0.2
    goto F_7_0
    goto F_1_3 within 90s
  }
}
