// SPDX-License-Identifier: EPL-2.0
// A holonomic (omnidirectional) robot: besides forward speed and turn rate it takes a sideways speed vy, limited as
// its forward speed is (docs/robots.md#drives).
catalogue OmniBases {
  robot type OmniBase : box 0.4 x 0.4 x 0.3 mass 12 speed 0.3 turn 1.5 drive holonomic
    lidar beams 360 range 0.12 to 3.5 rate 10 height 0.25
}
