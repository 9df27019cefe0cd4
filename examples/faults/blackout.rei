// A lidar blackout (docs/faults.md): on its way to the first goal the robot's lidar reads no return from 4 s to
// 7 s. The requirement in blackout.vepl: the robot's speed falls below 0.05 m/s within 1 s of a blackout's start.
//   rei run examples/faults/blackout.rei -o OUT --queries examples/faults --patterns examples/faults
// The reference navigation takes a scan without returns for free space and drives on: SIG_DROVE_ON_BLIND.
testcase LidarBlackout {
  room Lab size 6 x 4 {
    object table1 : Table on F_2_1
    object shelf1 : Shelf on F_0_3
    robot tb3 : Waffle on F_0_0
  }
  mission ToElevator {
    goto F_4_0
    goto F_5_3
  }
  faults {
    laser blackout from 4s to 7s
  }
  monitor { close 0.25 collision 0.01 }
}
