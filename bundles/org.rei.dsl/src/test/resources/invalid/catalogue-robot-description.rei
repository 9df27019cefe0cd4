// expect: 9:29 org.rei.dsl.robotDescription | Cannot read the robot's description 'no_such_robot.urdf': no such file
// expect: 10:29 org.rei.dsl.robotDescription | A robot read from a description names its lidar's link
// expect: 11:82 org.rei.dsl.robotDescription | The xacro argument 'namespace' is given twice
// expect: 12:91 org.rei.dsl.robotDescription | The lidar's height comes from its link in the description
// expect: 13:59 org.rei.dsl.robotDescription | Only a robot read from a description has links
// expect: 14:27 org.rei.dsl.robotDescription | The robot's description names no file
// A robot type read from a URDF or xacro description: what the validator checks itself (the reader's own errors
catalogue Described { // are rei generate's, tests/generator/test_robot_description.py)
  robot type Missing : urdf "no_such_robot.urdf" mass 1 lidar link "base_scan"
  robot type NoLidar : urdf "catalogue-robot-description.rei" mass 1
  robot type Twice : urdf "catalogue-robot-description.rei" arg namespace "" arg namespace "a" mass 1 lidar link "l"
  robot type Height : urdf "catalogue-robot-description.rei" mass 1 lidar link "l" height 0.2
  robot type Boxy : box 0.3 x 0.3 x 0.2 mass 1 lidar link "base_scan"
  robot type Blank : urdf "" mass 1 lidar link "l"
}
