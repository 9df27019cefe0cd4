# SPDX-License-Identifier: EPL-2.0
"""The ROS 1 bridge: a move_base-compatible navigation stack as REI's system under test (docs/ros.md).

``rei run CASE --sut "ros1:COMMAND"`` starts ``rei ros1-bridge -- COMMAND``: the bridge starts a private ROS master
(or joins one), starts COMMAND with the ROS environment, and is an external SUT to REI (``rei.sut.client``) while
it plays the robot to the stack: /clock (sim time), /scan, /odom, /tf, /tf_static, /robot_description, /map,
/cmd_vel and the move_base action.

Modules: ``environment`` (making Debian's rospy importable, the ROS environment), ``master`` (a private master),
``messages`` (REI's values as ROS messages), ``bridge`` (the node).
"""
