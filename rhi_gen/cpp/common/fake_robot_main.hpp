// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__FAKE_ROBOT_MAIN_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__FAKE_ROBOT_MAIN_HPP_

// The <robot>_fake_robot executables: arguments, the loopback guard, the node and its spin.
// A fake robot publishes the topics a real robot publishes: on a network shared with a real
// robot its state would reach that robot's controllers, and its commands' readers would take it
// for the robot. So it starts only where its traffic cannot leave this machine: ROS 2 discovery
// limited to this host (ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST, or ROS_LOCALHOST_ONLY=1 on
// Humble, without ROS_STATIC_PEERS) for the ROS 2 topic transports, the loopback interface `lo`
// for the SDK transports; --allow-network overrides, on purpose only.

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <string>

#include <rclcpp/executors.hpp>
#include <rclcpp/node.hpp>
#include <rclcpp/utilities.hpp>

#include "robot_hardware_interface/common/fake_robot.hpp"

namespace robot_hardware_interface
{

// Why `robot`'s traffic could leave this machine, or "" when it cannot. `env` reads an
// environment variable (std::getenv in the executable; tests pass their own).
template<typename GetEnv>
std::string network_exposure(const FakeRobot & robot, GetEnv && env)
{
  const char * interface = robot.network_interface();
  if (interface != nullptr && interface[0] != '\0') {
    if (std::strcmp(interface, "lo") == 0) {
      return "";
    }
    return std::string("it would use network interface '") + interface +
           "', not the loopback interface 'lo'";
  }
  const char * peers = env("ROS_STATIC_PEERS");
  if (peers != nullptr && peers[0] != '\0') {
    return std::string("ROS_STATIC_PEERS names other hosts (") + peers + ")";
  }
  const char * range = env("ROS_AUTOMATIC_DISCOVERY_RANGE");
  if (range != nullptr && range[0] != '\0') {
    if (std::strcmp(range, "LOCALHOST") == 0 || std::strcmp(range, "OFF") == 0) {
      return "";
    }
    return std::string("ROS_AUTOMATIC_DISCOVERY_RANGE is ") + range +
           ": ROS 2 discovery reaches other hosts";
  }
  const char * localhost_only = env("ROS_LOCALHOST_ONLY");
  if (localhost_only != nullptr && std::strcmp(localhost_only, "1") == 0) {
    return "";
  }
  return "ROS 2 discovery reaches other hosts (neither ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST "
         "nor ROS_LOCALHOST_ONLY=1 is set)";
}

// What the command line asks beyond the ROS arguments (which rclcpp reads itself).
struct FakeRobotArguments
{
  bool help{false};
  bool allow_network{false};
  double rate_hz{0.0};  // 0: the robot's own state rate
  std::string network_interface;  // "": the transport's default (SDK transports: lo)
  std::string error;    // a bad argument, in one line
};

inline FakeRobotArguments parse_fake_robot_arguments(int argc, char ** argv)
{
  FakeRobotArguments out;
  bool ros_arguments = false;
  for (int i = 1; i < argc; ++i) {
    const char * arg = argv[i];
    if (std::strcmp(arg, "--ros-args") == 0) {
      ros_arguments = true;
    } else if (ros_arguments) {
      ros_arguments = std::strcmp(arg, "--") != 0;
    } else if (std::strcmp(arg, "--help") == 0 || std::strcmp(arg, "-h") == 0) {
      out.help = true;
    } else if (std::strcmp(arg, "--allow-network") == 0) {
      out.allow_network = true;
    } else if (std::strcmp(arg, "--network-interface") == 0 && i + 1 < argc) {
      out.network_interface = argv[++i];
    } else if (std::strcmp(arg, "--rate") == 0 && i + 1 < argc) {
      char * end = nullptr;
      out.rate_hz = std::strtod(argv[++i], &end);
      if (end == argv[i] || *end != '\0' || !(out.rate_hz >= 1.0 && out.rate_hz <= 10000.0)) {
        out.error = std::string("--rate ") + argv[i] + ": expected a rate in Hz from 1 to 10000";
      }
    } else {
      out.error = std::string("unknown argument '") + arg + "' (--help lists them)";
    }
  }
  return out;
}

inline int run_fake_robot(int argc, char ** argv, std::unique_ptr<FakeRobot> robot)
{
  const FakeRobotArguments args = parse_fake_robot_arguments(argc, argv);
  if (args.help) {
    std::printf(
      "usage: %s [--rate HZ] [--network-interface IF] [--allow-network] [--ros-args ...]\n"
      "A fake %s robot: answers its driver on the robot's own topics with simulated joints.\n"
      "  --rate HZ                state rate (default %.0f Hz)\n"
      "  --network-interface IF   the SDK's network interface (default lo; SDK transports)\n"
      "  --allow-network          start even where ROS 2 discovery or the SDK reaches other hosts\n"
      "Faults: ros2 param set /%s fault REQUEST   (or --ros-args -p fault:=REQUEST at start)\n"
      "  REQUEST: silent | corrupt | hot <joint> <deg C> | error <joint> <code> |\n"
      "           offline <joint> | clear   (those its messages can carry)\n",
      argv[0], robot->transport(), robot->rate_hz(), robot->node_name());
    return 0;
  }
  if (!args.error.empty()) {
    std::fprintf(stderr, "%s: %s\n", robot->node_name(), args.error.c_str());
    return 2;
  }
  if (!args.network_interface.empty() &&
    !robot->set_network_interface(args.network_interface.c_str()))
  {
    std::fprintf(
      stderr, "%s: --network-interface: the %s transport has none (ROS 2 discovery settings "
      "decide where its topics go)\n", robot->node_name(), robot->transport());
    return 2;
  }
  const std::string exposure =
    network_exposure(*robot, [](const char * name) {return std::getenv(name);});
  if (!exposure.empty() && !args.allow_network) {
    std::fprintf(
      stderr, "%s: refusing to start: %s. Start it with use_fake_robot:=true in the robot's launch "
      "file (which keeps discovery on this host), export ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST "
      "(Humble: ROS_LOCALHOST_ONLY=1), or pass --allow-network if no real robot can be reached.\n",
      robot->node_name(), exposure.c_str());
    return 2;
  }
  try {
    rclcpp::init(argc, argv);
    auto node = std::make_shared<rclcpp::Node>(robot->node_name());
    robot->configure(node);
    robot->start(args.rate_hz > 0.0 ? args.rate_hz : robot->rate_hz());
    RCLCPP_INFO(
      node->get_logger(), "fake %s robot running at %.0f Hz%s", robot->transport(),
      args.rate_hz > 0.0 ? args.rate_hz : robot->rate_hz(),
      exposure.empty() ? "" : " (network allowed)");
    rclcpp::spin(node);
    robot->stop();
  } catch (const std::exception & e) {
    std::fprintf(stderr, "%s: %s\n", robot->node_name(), e.what());
    rclcpp::shutdown();
    return 1;
  }
  rclcpp::shutdown();
  return 0;
}

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__FAKE_ROBOT_MAIN_HPP_
