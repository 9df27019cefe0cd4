# SPDX-License-Identifier: EPL-2.0
"""REI's robot for a ROS 2 navigation stack, on DDS with Cyclone DDS's Python binding (``pip install rei[ros2]``).

No ROS 2 installation is needed: a ROS 2 node (on any DDS) sees a topic ``/scan`` as the DDS topic
``rt/scan`` of type ``sensor_msgs::msg::dds_::LaserScan_``, whose CDR (XCDR1, little endian) is the message's
fields in order. ``types`` declares those types field for field; ``messages`` builds them from REI's values and
names the topics with their QoS (``TOPICS``); ``action`` is the client of nav2's NavigateToPose action;
``environment`` keeps a run's DDS traffic on loopback and on a ROS domain of its own; ``bridge`` is the node
(``rei ros2-bridge``, ROS 2's counterpart of ``rei.sut.ros1.bridge``).
"""
