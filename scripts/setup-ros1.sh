#!/usr/bin/env bash
# SPDX-License-Identifier: EPL-2.0
#
# Installs ROS 1 from Debian's packages for the ROS bridge (`--sut "ros1:COMMAND"`, docs/ros.md) and its tests
# (tests/ros): the master (rosmaster, rosout), rospy, the message packages the bridge speaks, actionlib and
# move_base_msgs, rosbag. REI itself does not need ROS: only runs with a ROS stack do.
#
# Why Debian's: it is the ROS 1 this machine's package registry has (ros_comm 1.15, BSD licensed), installed in
# ~30 s (77 packages, ~170 MB, most of it Boost headers that python3-nav-msgs depends on). REI's interpreter
# imports it from /usr/lib/python3/dist-packages (rei.sut.ros1.environment).
#
# Idempotent: exits at once when every package is installed.
set -euo pipefail

PACKAGES=(ros-core python3-rospy python3-sensor-msgs python3-nav-msgs python3-geometry-msgs python3-tf2-msgs
          python3-rosgraph-msgs python3-actionlib python3-move-base-msgs python3-rosbag)

missing=()
for package in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "${package}" 2>/dev/null | grep -q "install ok installed" || missing+=("${package}")
done
if [ "${#missing[@]}" -eq 0 ]; then
    echo "setup-ros1: ROS 1 already installed ($(rosversion rospy 2>/dev/null || echo rospy))"
    exit 0
fi
if [ "$(id -u)" -ne 0 ] || ! command -v apt-get >/dev/null 2>&1; then
    echo "setup-ros1: missing ${missing[*]}; install them as root: apt-get install ${PACKAGES[*]}" >&2
    exit 1
fi

echo "setup-ros1: installing ${missing[*]} with apt-get"
export DEBIAN_FRONTEND=noninteractive
if ! apt-get install -y --no-install-recommends "${PACKAGES[@]}"; then
    apt-get update
    apt-get install -y --no-install-recommends "${PACKAGES[@]}"
fi
echo "setup-ros1: ROS 1 installed ($(rosversion rospy))"
