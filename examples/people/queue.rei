// SPDX-License-Identifier: EPL-2.0
// A queue (issue #38, docs/people.md "Queues"): eight visitors walk from the left of a hall to its right, passing
// a ticket gate on F_8_2 one at a time, one every 3 s; who comes while the gate is taken lines up behind it, back
// along the way they came. The robot crosses the hall from its bottom wall to its top one through where the line
// stands: does it wait for a gap, or push through the people waiting?
testcase TicketQueue {
  room Hall size 14 x 5 {
    crowd visitors 8 from [F_0_1, F_0_2, F_0_3, F_1_1, F_1_2, F_1_3]
                     to [F_12_1, F_12_2, F_12_3, F_13_1, F_13_2, F_13_3]
      speed 1.0 to 1.3 queue F_8_2 every 3s
    robot tb3 : Waffle on F_5_0 yaw 90
  }
  mission CrossTheLine {
    goto F_5_2
    goto F_5_4
  }
  monitor { close 0.25 collision 0.01 maxHumanCollisions 1 }
}
