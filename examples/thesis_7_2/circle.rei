// Thesis 7.2.3, the circular movement scenario: the robot is driven in circles around a table, so that it comes
// close to the table from different sides of the table: at its short ends, and not along its long sides.
// Run it with its command timeline:  rei run examples/thesis_7_2/circle.rei --controller
// script:examples/thesis_7_2/circle.script -o out   (expected signals: circle.expected)
testcase Circle {
  room Hall size 5 x 5 {
    object table1 : Table on F_2_2
    robot tb3 : Waffle on F_2_1
  }
  // two laps end where they began: both goals are the start floor
  mission TwoLaps { goto F_2_1 within 90s goto F_2_1 }
}
