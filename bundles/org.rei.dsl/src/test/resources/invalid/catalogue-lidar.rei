// expect: 8:17 org.rei.dsl.outOfRange | A lidar has 1 to 4096 beams, got 0
// expect: 8:30 org.rei.dsl.outOfRange | The lidar's longest range must be above its shortest (2.0 m)
// expect: 8:37 org.rei.dsl.outOfRange | The lidar scans 0 to 100 times a second (above 0), got 500.0
// expect: 8:48 org.rei.dsl.nonPositive | The lidar's mounting height must be above 0
// expect: 7:87 org.rei.dsl.nonPositive | The top turn rate must be above 0
catalogue Lidars {
  robot type Scout : box 0.3 x 0.3 x 0.2 mass 5 wheels 0.05 apart 0.25 speed 0.5 turn 0
    lidar beams 0 range 2 to 1 rate 500 height 0
}
