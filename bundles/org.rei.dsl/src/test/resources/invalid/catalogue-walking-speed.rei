// expect: 5:60 org.rei.dsl.outOfRange | A walking speed is above 0 and at most 3 m/s
// expect: 6:66 org.rei.dsl.outOfRange | The fastest walking speed of a range is at least its slowest (1.4)
// expect: 7:43 org.rei.dsl.typeCategory | Only a human type walks: a static type has no walking speed
catalogue Walkers {
  type Slow : human cylinder 0.5 x 0.5 x 1.7 mass 70 speed 0
  type Odd : human cylinder 0.5 x 0.5 x 1.7 mass 70 speed 1.4 to 1.0
  type Crate : object box 1 x 1 x 1 speed 1
  type Fine : human box 0.6 x 0.4 x 1.8 mass 80 speed 1.0 to 1.4
}
