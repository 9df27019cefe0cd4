// A room with furniture that is not a box: an L-shaped corner desk and a corner sofa from a user catalogue
// (catalogues/corner_office.rei). The simulator, the monitor, the metrics and the report take their polygons,
// not their bounding boxes: the robot drives past the desk's open corner, where a box would stand.
import "catalogues/corner_office.rei"

testcase CornerDesk {
  room Study size 6 x 4 {
    object desk : CornerDesk on F_1_2
    object sofa : CornerSofa on F_4_2 yaw 180
    robot tb3 : Waffle on F_0_0
  }
  mission PastTheDesk {
    goto F_3_1 within 90s
    goto F_5_0 within 90s
  }
  monitor { close 0.25 collision 0.01 }
}
