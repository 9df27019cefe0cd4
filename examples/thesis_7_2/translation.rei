// Thesis 7.2.2, the simple translation scenario: the robot is driven (not navigated) forwards into a box and
// back again, and the monitor must raise the geometric and laser events when it really comes close and collides.
// Run it with its command timeline:  rei run examples/thesis_7_2/translation.rei --controller
// script:examples/thesis_7_2/translation.script -o out   (expected signals: translation.expected)
testcase Translation {
  room Corridor size 5 x 1 {
    object box1 : Box on F_3_0
    robot tb3 : Waffle on F_0_0
  }
  // the timeline ends where it began: both goals are the start floor
  mission ThereAndBack { goto F_0_0 within 60s goto F_0_0 }
}
