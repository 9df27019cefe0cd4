// A user catalogue: the object and robot types of one office, used by test cases that import this file
// (`import "catalogues/office.rei"`) and by `rei gen-rooms --catalogue examples/catalogues/office.rei`.
// Sizes are x by y by height in metres, mass in kg; furniture is fixed in the world whatever its mass.
catalogue Office {
  type Sofa : object box 1.1 x 0.8 x 0.8 mass 40 colour "#7A5230"
  type Pillar : object cylinder 0.3 x 0.3 x 2.5 colour "#BFBFBF"
  type Plant : object cylinder 0.45 x 0.45 x 1.2 mass 8 colour "#3A7D44"
  type Trolley : dynamic box 0.6 x 0.4 x 1.0 mass 15 colour "#4682B4"
  // A TurtleBot3 Burger: smaller and slower to turn than the default catalogue's Waffle, with a slower lidar.
  robot type Burger : box 0.138 x 0.178 x 0.192 mass 1.0 colour "#202020"
    wheels 0.033 apart 0.160 speed 0.22 turn 2.84
    lidar beams 360 range 0.12 to 3.5 rate 5 height 0.17
}
