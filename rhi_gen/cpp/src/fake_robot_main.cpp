// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that has a fake robot, below the
// package's banner.

// main() of every <robot>_fake_robot executable: the robot's own source
// (src/<vendor>/<robot>_fake_robot.cpp) defines make_fake_robot(); common/fake_robot_main.hpp does
// the rest.
#include "robot_hardware_interface/common/fake_robot_main.hpp"

int main(int argc, char ** argv)
{
  return robot_hardware_interface::run_fake_robot(
    argc, argv, robot_hardware_interface::make_fake_robot());
}
