// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef HARDWARE_INTERFACE_TEST_HPP_
#define HARDWARE_INTERFACE_TEST_HPP_

// What every generated colcon test checks, once for all robots: the robot's test file only holds
// its data (RobotUnderTest) and instantiates the suite. A plugin is loaded the way the controller
// manager does it: a URDF (the robot's joints plus the same <ros2_control> block as its
// description/<robot>.ros2_control.xacro) goes through hardware_interface::ResourceManager, which
// finds the plugin with pluginlib, parses the description, calls on_init() and imports the
// exported interfaces. Nothing is sent to a robot: only on_init() runs (the component stays
// unconfigured) and network_interface is "lo".

#include <gmock/gmock.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "hardware_interface/resource_manager.hpp"
#include "hardware_interface/types/lifecycle_state_names.hpp"
#include "rclcpp/rclcpp.hpp"
#include "robot_hardware_interface/common/ros2_control_compat.hpp"
#include "ros2_control_test_assets/descriptions.hpp"

namespace robot_hardware_interface_test
{

struct TestJoint
{
  std::string name;      // URDF joint name, as ros2_control reports it
  std::string name_xml;  // the same name escaped for XML
  std::string type;      // revolute | continuous | prismatic
  std::string limit_xml;  // the joint's <limit/> element ("" if none)
  std::string min_max_xml;  // <param name="min"/"max"> of the position command ("" if none)
  std::vector<std::string> command_interfaces;
  std::vector<std::string> state_interfaces;
  size_t sdk_slot;
};

struct RobotUnderTest
{
  std::string hardware_name;  // <ros2_control name>
  std::string plugin_name;
  std::string parameters_xml;  // the <param> elements of <hardware>
  std::vector<TestJoint> joints;  // URDF order
  std::string imu_name;  // "" when the robot has no IMU
  std::string imu_name_xml;
  std::string imu_frame_xml;
  // What the generator counted, so that a data mix-up cannot pass as an empty list.
  size_t state_interface_count;
  size_t command_interface_count;
  // Motor health the driver exports beyond the description where the installed vendor messages
  // carry it (EngineAI: the native SDK's interface_protocol): every joint has it, or none does.
  std::vector<std::string> detected_state_interfaces;
};

inline const std::vector<std::string> & imu_state_interfaces()
{
  static const std::vector<std::string> interfaces = {
    "orientation.x", "orientation.y", "orientation.z", "orientation.w",
    "angular_velocity.x", "angular_velocity.y", "angular_velocity.z",
    "linear_acceleration.x", "linear_acceleration.y", "linear_acceleration.z"};
  return interfaces;
}

// The driver's health GPIO, <gpio name="<hardware name>_health"> of the generated description.
inline const std::vector<std::string> & health_state_interfaces()
{
  static const std::vector<std::string> interfaces = {
    "state_age_ms", "invalid_states", "stale_holds", "rejected_commands", "writer_overruns",
    "fault", "estop"};
  return interfaces;
}

inline std::string health_gpio(const RobotUnderTest & robot)
{
  return robot.hardware_name + "_health";
}

inline std::string ros2_control_xml(const RobotUnderTest & robot)
{
  std::string xml = "  <ros2_control name=\"" + robot.hardware_name + "\" type=\"system\">\n";
  xml += "    <hardware>\n";
  xml += "      <plugin>" + robot.plugin_name + "</plugin>\n";
  xml += robot.parameters_xml;
  xml += "    </hardware>\n";
  for (const TestJoint & joint : robot.joints) {
    xml += "    <joint name=\"" + joint.name_xml + "\">\n";
    for (const std::string & interface : joint.command_interfaces) {
      if (interface == "position" && !joint.min_max_xml.empty()) {
        xml += "      <command_interface name=\"position\">" + joint.min_max_xml +
          "</command_interface>\n";
      } else {
        xml += "      <command_interface name=\"" + interface + "\"/>\n";
      }
    }
    for (const std::string & interface : joint.state_interfaces) {
      xml += "      <state_interface name=\"" + interface + "\"/>\n";
    }
    xml += "    </joint>\n";
  }
  if (!robot.imu_name.empty()) {
    xml += "    <sensor name=\"" + robot.imu_name_xml + "\">\n";
    for (const std::string & interface : imu_state_interfaces()) {
      xml += "      <state_interface name=\"" + interface + "\"/>\n";
    }
    xml += "      <param name=\"frame_id\">" + robot.imu_frame_xml + "</param>\n";
    xml += "    </sensor>\n";
  }
  xml += "    <gpio name=\"" + health_gpio(robot) + "\">\n";
  xml += "      <command_interface name=\"estop\"/>\n";
  for (const std::string & interface : health_state_interfaces()) {
    xml += "      <state_interface name=\"" + interface + "\"/>\n";
  }
  xml += "    </gpio>\n";
  xml += "  </ros2_control>\n";
  return xml;
}

// A URDF whose kinematic chain holds every driven joint (link i -> joint i -> link i+1): newer
// ros2_control releases reject <ros2_control> joints that the URDF does not define.
inline std::string test_urdf(const RobotUnderTest & robot)
{
  std::string urdf = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<robot name=\"rhi_test\">\n";
  urdf += "  <link name=\"rhi_test_link_0\"/>\n";
  for (size_t i = 0; i < robot.joints.size(); ++i) {
    const TestJoint & joint = robot.joints[i];
    const std::string child = "rhi_test_link_" + std::to_string(i + 1);
    urdf += "  <joint name=\"" + joint.name_xml + "\" type=\"" + joint.type + "\">\n";
    urdf += "    <parent link=\"rhi_test_link_" + std::to_string(i) + "\"/>\n";
    urdf += "    <child link=\"" + child + "\"/>\n";
    urdf += "    <axis xyz=\"0 0 1\"/>\n";
    if (!joint.limit_xml.empty()) {
      urdf += "    " + joint.limit_xml + "\n";
    }
    urdf += "  </joint>\n";
    urdf += "  <link name=\"" + child + "\"/>\n";
  }
  urdf += ros2_control_xml(robot);
  urdf += ros2_control_test_assets::urdf_tail;
  return urdf;
}

class HardwareInterfaceTest : public ::testing::TestWithParam<const RobotUnderTest *>
{
protected:
  // The driver creates an rclcpp::Node in on_init(), which needs an initialised context.
  static void SetUpTestSuite() {rclcpp::init(0, nullptr);}
  static void TearDownTestSuite() {rclcpp::shutdown();}

  void SetUp() override
  {
    const RobotUnderTest & robot = *GetParam();
    // As the controller manager of this ROS 2 release builds it. On Humble the interfaces are
    // validated (construction throws unless the plugin exports exactly what the <ros2_control>
    // block lists); later releases create the handles from the block themselves.
    ASSERT_NO_THROW(
      rm_ = robot_hardware_interface::make_resource_manager<hardware_interface::ResourceManager>(
        test_urdf(robot))) << "URDF under test:\n" << test_urdf(robot);
    ASSERT_NE(rm_, nullptr);
    ASSERT_TRUE(robot_hardware_interface::components_initialized(*rm_))
      << "on_init() of " << robot.plugin_name << " failed; URDF under test:\n" << test_urdf(robot);
  }

  std::unique_ptr<hardware_interface::ResourceManager> rm_;
};

TEST_P(HardwareInterfaceTest, loads_one_system_component)
{
  const RobotUnderTest & robot = *GetParam();
  EXPECT_EQ(rm_->system_components_size(), 1u);
  EXPECT_EQ(rm_->actuator_components_size(), 0u);
  EXPECT_EQ(rm_->sensor_components_size(), 0u);

  const auto status = rm_->get_components_status();
  const auto it = status.find(robot.hardware_name);
  ASSERT_NE(it, status.end()) << "no hardware component named " << robot.hardware_name;
  EXPECT_EQ(it->second.type, "system");
  // on_init() succeeded: the component waits in 'unconfigured' until the controller manager
  // configures it.
  EXPECT_EQ(it->second.state.label(), hardware_interface::lifecycle_state_names::UNCONFIGURED);
}

TEST_P(HardwareInterfaceTest, exports_every_state_interface)
{
  const RobotUnderTest & robot = *GetParam();
  std::vector<std::string> expected;
  for (const TestJoint & joint : robot.joints) {
    for (const std::string & interface : joint.state_interfaces) {
      const std::string key = joint.name + "/" + interface;
      EXPECT_TRUE(rm_->state_interface_exists(key))
        << "missing state interface " << key << " (SDK slot " << joint.sdk_slot << ")";
      expected.push_back(key);
    }
  }
  if (!robot.imu_name.empty()) {
    for (const std::string & interface : imu_state_interfaces()) {
      const std::string key = robot.imu_name + "/" + interface;
      EXPECT_TRUE(rm_->state_interface_exists(key)) << "missing IMU state interface " << key;
      expected.push_back(key);
    }
  }
  EXPECT_EQ(expected.size(), robot.state_interface_count);
  for (const std::string & interface : robot.detected_state_interfaces) {
    const bool found = !robot.joints.empty() &&
      rm_->state_interface_exists(robot.joints.front().name + "/" + interface);
    for (const TestJoint & joint : robot.joints) {
      const std::string key = joint.name + "/" + interface;
      EXPECT_EQ(rm_->state_interface_exists(key), found)
        << key << ": the driver exports " << interface << " for every joint or for none";
      if (found) {
        expected.push_back(key);
      }
    }
  }
  for (const std::string & interface : health_state_interfaces()) {
    const std::string key = health_gpio(robot) + "/" + interface;
    EXPECT_TRUE(rm_->state_interface_exists(key)) << "missing health state interface " << key;
    expected.push_back(key);
  }
  EXPECT_THAT(rm_->state_interface_keys(), ::testing::UnorderedElementsAreArray(expected));
}

TEST_P(HardwareInterfaceTest, exports_every_command_interface)
{
  const RobotUnderTest & robot = *GetParam();
  std::vector<std::string> expected;
  for (const TestJoint & joint : robot.joints) {
    for (const std::string & interface : joint.command_interfaces) {
      const std::string key = joint.name + "/" + interface;
      EXPECT_TRUE(rm_->command_interface_exists(key))
        << "missing command interface " << key << " (SDK slot " << joint.sdk_slot << ")";
      EXPECT_FALSE(rm_->command_interface_is_claimed(key)) << key;
      expected.push_back(key);
    }
  }
  EXPECT_EQ(expected.size(), robot.command_interface_count);
  const std::string estop = health_gpio(robot) + "/estop";
  EXPECT_TRUE(rm_->command_interface_exists(estop)) << "missing the e-stop " << estop;
  expected.push_back(estop);
  EXPECT_THAT(rm_->command_interface_keys(), ::testing::UnorderedElementsAreArray(expected));
}

}  // namespace robot_hardware_interface_test

#endif  // HARDWARE_INTERFACE_TEST_HPP_
