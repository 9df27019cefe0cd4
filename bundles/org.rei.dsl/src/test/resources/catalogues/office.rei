// A valid catalogue the tests import.
catalogue Office {
  type Sofa : object box 1.1 x 0.8 x 0.8 mass 40 colour "#7A5230"
  type Pillar : object cylinder 0.3 x 0.3 x 2.5
  robot type Scout : box 0.3 x 0.25 x 0.2 mass 4.5 colour "#202020CC"
    wheels 0.04 apart 0.22 speed 0.5 turn 2.0
    lidar beams 720 range 0.05 to 8 rate 15 height 0.18
}
