// expect: 11:26 org.rei.dsl.faultParameter | A laser blackout fault has no 'sigma' (it has no parameters besides its times)
// expect: 12:11 org.rei.dsl.faultParameter | A laser noise fault needs 'sigma' (metres)
// expect: 13:11 org.rei.dsl.faultParameter | A laser occlusion fault needs 'angles FROM to TO' (degrees) and 'range' (metres)
// expect: 14:24 org.rei.dsl.outOfRange | The rate is impulses per beam per scan: expected 0 to 1
testcase T {
  room R size 3 x 2 {
    robot r : Waffle on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
  faults {
    laser blackout sigma 0.1 from 1s
    laser noise from 2s
    laser occlusion angles -30 to 30
    laser impulse rate 2 width 3
  }
}
