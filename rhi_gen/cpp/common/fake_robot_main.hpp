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
// --physics mujoco puts its joints on MuJoCo (fake_physics_mujoco.hpp) where the package was built
// with it: the robot's URDF (--urdf, or the package's urdf/<robot>.urdf found under
// AMENT_PREFIX_PATH, where package:// meshes are looked up too), held as --base says.

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include <rclcpp/executors.hpp>
#include <rclcpp/node.hpp>
#include <rclcpp/utilities.hpp>

#include "robot_hardware_interface/common/fake_physics.hpp"
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
  bool mujoco{false};   // --physics mujoco (default vacuum)
  FakeBase base{FakeBase::kBand};
  bool base_given{false};
  std::string urdf;     // "": the package's urdf/<robot>.urdf under AMENT_PREFIX_PATH
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
    } else if (std::strcmp(arg, "--physics") == 0 && i + 1 < argc) {
      const char * value = argv[++i];
      out.mujoco = std::strcmp(value, "mujoco") == 0;
      if (!out.mujoco && std::strcmp(value, "vacuum") != 0) {
        out.error = std::string("--physics ") + value + ": expected vacuum or mujoco";
      }
    } else if (std::strcmp(arg, "--base") == 0 && i + 1 < argc) {
      out.base_given = true;
      if (!FakePhysicsOptions::parse_base(argv[++i], &out.base)) {
        out.error = std::string("--base ") + argv[i] + ": expected free, band or fixed";
      }
    } else if (std::strcmp(arg, "--urdf") == 0 && i + 1 < argc) {
      out.urdf = argv[++i];
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
  if (out.error.empty() && !out.mujoco && (out.base_given || !out.urdf.empty())) {
    out.error = std::string(out.base_given ? "--base" : "--urdf") + " is for --physics mujoco only";
  }
  return out;
}

// The file `relative` of the robot_hardware_interface package's share folder under the first
// prefix of `prefixes` (':'-separated, AMENT_PREFIX_PATH) that has it; "" when none has it.
inline std::string fake_robot_share_file(const char * prefixes, const char * relative)
{
  const std::string all = prefixes != nullptr ? prefixes : "";
  size_t begin = 0;
  while (begin < all.size()) {
    size_t end = all.find(':', begin);
    if (end == std::string::npos) {
      end = all.size();
    }
    const std::string prefix = all.substr(begin, end - begin);
    begin = end + 1;
    if (prefix.empty()) {
      continue;
    }
    const std::string path = prefix + "/share/robot_hardware_interface/" + relative;
    if (FILE * f = std::fopen(path.c_str(), "r")) {
      std::fclose(f);
      return path;
    }
  }
  return "";
}

// --physics mujoco: the robot on MuJoCo (true, warnings printed), or false with one line in *error.
// `env` reads an environment variable, as for network_exposure.
template<typename GetEnv>
bool use_fake_robot_physics(
  const FakeRobotArguments & args, FakeRobot & robot, GetEnv && env, std::string * error)
{
  if (!args.mujoco) {
    return true;
  }
  if (!kFakeRobotHasMujoco) {
    *error = std::string("--physics mujoco: ") + kFakeRobotWithoutMujoco;
    return false;
  }
  const char * prefixes = env("AMENT_PREFIX_PATH");
  FakePhysicsOptions options;
  options.base = args.base;
  options.package_path = prefixes != nullptr ? prefixes : "";
  options.urdf_path = args.urdf.empty() ?
    fake_robot_share_file(prefixes, robot.physics_spec().urdf) : args.urdf;
  if (options.urdf_path.empty()) {
    *error = std::string("--physics mujoco: ") + robot.physics_spec().urdf +
      " of robot_hardware_interface is not under any prefix of AMENT_PREFIX_PATH (source the "
      "workspace's install/setup.bash, or pass --urdf FILE)";
    return false;
  }
  std::vector<std::string> warnings;
  if (!robot.use_mujoco(options, error, &warnings)) {
    *error = "--physics mujoco: " + *error;
    return false;
  }
  for (const std::string & warning : warnings) {
    std::fprintf(stderr, "%s: warning: %s\n", robot.node_name(), warning.c_str());
  }
  return true;
}

inline int run_fake_robot(int argc, char ** argv, std::unique_ptr<FakeRobot> robot)
{
  const FakeRobotArguments args = parse_fake_robot_arguments(argc, argv);
  if (args.help) {
    std::printf(
      "usage: %s [--rate HZ] [--network-interface IF] [--allow-network]\n"
      "       [--physics vacuum|mujoco] [--base free|band|fixed] [--urdf FILE] [--ros-args ...]\n"
      "A fake %s robot: answers its driver on the robot's own topics with simulated joints.\n"
      "  --rate HZ                state rate (default %.0f Hz)\n"
      "  --network-interface IF   the SDK's network interface (default lo; SDK transports)\n"
      "  --allow-network          start even where ROS 2 discovery or the SDK reaches other hosts\n"
      "  --physics vacuum|mujoco  the joints alone without gravity (default), or the robot on\n"
      "                           MuJoCo: gravity, a floor, its links' coupling (%s)\n"
      "  --base free|band|fixed   mujoco: the base free, held by an elastic band (default), or\n"
      "                           fixed to the world\n"
      "  --urdf FILE              mujoco: the robot's URDF (default %s of this package,\n"
      "                           found under AMENT_PREFIX_PATH, as package:// meshes are)\n"
      "Faults: ros2 param set /%s fault REQUEST   (or --ros-args -p fault:=REQUEST at start)\n"
      "  REQUEST: silent | corrupt | hot <joint> <deg C> | error <joint> <code> |\n"
      "           offline <joint> | clear   (those its messages can carry)\n"
      "Band: ros2 param set /%s release_band true   lets go of the robot\n",
      argv[0], robot->transport(), robot->rate_hz(),
      kFakeRobotHasMujoco ? "built with MuJoCo" : "this build has no MuJoCo",
      robot->physics_spec().urdf, robot->node_name(), robot->node_name());
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
  std::string physics_error;
  if (!use_fake_robot_physics(
      args, *robot, [](const char * name) {return std::getenv(name);}, &physics_error))
  {
    std::fprintf(stderr, "%s: %s\n", robot->node_name(), physics_error.c_str());
    return 2;
  }
  try {
    rclcpp::init(argc, argv);
    auto node = std::make_shared<rclcpp::Node>(robot->node_name());
    robot->configure(node);
    robot->start(args.rate_hz > 0.0 ? args.rate_hz : robot->rate_hz());
    RCLCPP_INFO(
      node->get_logger(), "fake %s robot running at %.0f Hz, physics %s%s%s%s%s",
      robot->transport(), args.rate_hz > 0.0 ? args.rate_hz : robot->rate_hz(), robot->physics(),
      args.mujoco ? " (base " : "", args.mujoco ? FakePhysicsOptions::base_name(args.base) : "",
      args.mujoco ? ")" : "", exposure.empty() ? "" : " (network allowed)");
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
