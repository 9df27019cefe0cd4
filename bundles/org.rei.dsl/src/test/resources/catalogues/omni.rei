// SPDX-License-Identifier: EPL-2.0
// A holonomic robot, for the validation of what only a differential drive has (invalid/fault-holonomic.rei).
catalogue Omni {
  robot type Omni : box 0.4 x 0.4 x 0.3 mass 12 speed 0.3 turn 1.5 drive holonomic
}
