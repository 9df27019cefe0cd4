// A room from a robot's own occupancy map (ROS map_server format): two rooms and a corridor, 10 x 6 m
// (two_rooms.yaml and its image, drawn by draw_two_rooms.py). Floors are the free 0.5 m blocks of the map,
// F_x_y counted from its bottom-left corner; its occupied and unknown cells are the walls.
testcase TwoRooms {
  room Office occupancy "two_rooms.yaml" floorSize 0.5 {
    object desk : Table on F_3_9
    object chair1 : Chair on F_5_3
    object shelf1 : Shelf on F_16_10
    object bin1 : Bin on F_17_2
    human visitor trajectory [F_4_1 @ 0s, F_6_1 @ 6s] loop
    robot tb3 : Waffle on F_2_7
  }
  mission AcrossTheCorridor {
    timeout 120s
    goto F_16_5
    goto F_13_9
  }
  monitor { close 0.25 collision 0.01 }
}
