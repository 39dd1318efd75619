// The generated G1 fake robot (src/unitree/g1_fake_robot.cpp, linked in) chosen onto MuJoCo the way
// its executable does it: the command line after the scenario goes through the generated
// parse_fake_robot_arguments() and use_fake_robot_physics() (common/fake_robot_main.hpp), then the
// robot is configured on a stand-in node and its loop stepped here at its rate, as its wall timer
// would, commands arriving as LowCmd_ frames on its unitree_sdk2 channel (the stand-in SDK).
//
//   fake_robot_physics_check passive|hold GAINS TOPIC STATE_TOPIC [fake robot arguments...]
//
// passive: no command (every motor passive) for 1 s; hold: one LowCmd_ holding every motor at its
// start position with the gains of GAINS ("slot kp kd" lines), on the command channel TOPIC, for 1 s. Prints key=value lines:
// physics, moved.<joint> (the largest |q - q_start| over the run), moved_max, moved_joint, and
// imu_acc, imu_quat: the IMU of the last LowState_ it wrote on STATE_TOPIC.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "rhi_fake/unitree.hpp"
#include "robot_hardware_interface/common/fake_robot_main.hpp"
#include "robot_hardware_interface/transport/unitree_hg.hpp"

namespace rhi = robot_hardware_interface;

int main(int argc, char ** argv)
{
  if (argc < 5) {
    std::fprintf(
      stderr, "usage: %s passive|hold GAINS TOPIC STATE_TOPIC [fake robot arguments...]\n", argv[0]);
    return 2;
  }
  const std::string scenario = argv[1];
  const char * gains_file = argv[2];
  const char * topic = argv[3];
  const char * state_topic = argv[4];
  // argv[4] stands where the executable's own name would: parsing starts after it.
  const rhi::FakeRobotArguments args = rhi::parse_fake_robot_arguments(argc - 4, argv + 4);
  if (!args.error.empty()) {
    std::printf("error=%s\n", args.error.c_str());
    return 2;
  }
  std::unique_ptr<rhi::FakeRobot> robot = rhi::make_fake_robot();
  std::string error;
  if (!rhi::use_fake_robot_physics(
      args, *robot, [](const char * name) {return std::getenv(name);}, &error))
  {
    std::printf("error=%s\n", error.c_str());
    return 1;
  }
  rclcpp::init(0, nullptr);
  auto node = std::make_shared<rclcpp::Node>(robot->node_name());
  robot->configure(node);
  std::printf("physics=%s\n", robot->physics());

  const size_t n = robot->joint_count();
  std::vector<double> start(n);
  for (size_t k = 0; k < n; ++k) {
    start[k] = robot->position(robot->joint(k).slot);
  }
  if (scenario == "hold") {
    rhi::unitree_hg::LowCmd cmd{};
    std::ifstream gains(gains_file);
    size_t slot = 0;
    double kp = 0.0;
    double kd = 0.0;
    while (gains >> slot >> kp >> kd) {
      auto & motor = cmd.motor_cmd()[slot];
      motor.mode() = rhi::unitree_hg::kMotorEnable;
      motor.q() = static_cast<float>(robot->position(slot));
      motor.kp() = static_cast<float>(kp);
      motor.kd() = static_cast<float>(kd);
    }
    cmd.crc() = rhi::unitree_hg::low_cmd_crc(cmd);
    if (rhi_fake::unitree::deliver(topic, cmd) != 1) {
      std::printf("error=the fake robot does not read %s\n", topic);
      return 1;
    }
  } else if (scenario != "passive") {
    std::printf("error=unknown scenario %s\n", scenario.c_str());
    return 2;
  }
  std::vector<double> moved(n, 0.0);
  const int steps = static_cast<int>(std::lround(robot->rate_hz()));  // 1 s
  for (int i = 0; i < steps; ++i) {
    robot->step();
    for (size_t k = 0; k < n; ++k) {
      moved[k] = std::max(moved[k], std::fabs(robot->position(robot->joint(k).slot) - start[k]));
    }
  }
  size_t most = 0;
  for (size_t k = 0; k < n; ++k) {
    std::printf("moved.%s=%.6f\n", robot->joint(k).name, moved[k]);
    most = moved[k] > moved[most] ? k : most;
  }
  std::printf("moved_max=%.6f\nmoved_joint=%s\n", moved[most], robot->joint(most).name);
  rhi::unitree_hg::LowState state{};
  if (!rhi_fake::unitree::last_written(state_topic, state)) {
    std::printf("error=nothing written on %s\n", state_topic);
    return 1;
  }
  const auto & imu = state.imu_state();
  std::printf(
    "imu_acc=%.4f %.4f %.4f\nimu_quat=%.5f %.5f %.5f %.5f\n", imu.accelerometer()[0],
    imu.accelerometer()[1], imu.accelerometer()[2], imu.quaternion()[0], imu.quaternion()[1],
    imu.quaternion()[2], imu.quaternion()[3]);
  rclcpp::shutdown();
  return 0;
}
