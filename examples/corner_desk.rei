// A room with furniture that is not a box: an L-shaped corner desk and a corner sofa from a user catalogue
// (catalogues/corner_office.rei). The simulator, the monitor, the navigation, the metrics and the report take
// their polygons, not their bounding boxes: the first goal, F_2_2, lies in the desk's open corner (0.3 m above its
// long arm, inside its bounding box), where a box desk would stand.
import "catalogues/corner_office.rei"

testcase CornerDesk {
  room Study size 6 x 4 {
    object desk : CornerDesk on F_1_2
    object sofa : CornerSofa on F_4_2 yaw 180
    robot tb3 : Waffle on F_0_0
  }
  mission IntoTheCorner {
    goto F_2_2 within 90s
    goto F_5_0 within 90s
  }
  monitor { close 0.25 collision 0.01 }
}
