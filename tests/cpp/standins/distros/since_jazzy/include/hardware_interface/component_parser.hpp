// rhi-gen test stand-in (not the real ROS 2 code): hardware_interface/component_parser.hpp of
// ros2_control 4.x+, header-only (upstream: tinyxml2 + urdfdom in a .cpp).
//
// parse_control_resources_from_urdf() reads every <ros2_control> block of the root <robot> like
// upstream (name, type, rw_rate, is_async, <hardware><plugin>/<group>/<param>, <joint>/<sensor>/
// <gpio> with their interfaces, min/max/initial_value params, data_type/size, <limits enable>),
// throws std::runtime_error for what upstream rejects -- empty or malformed XML, a root other
// than <robot>, no <ros2_control>, a missing <plugin>, an unknown child tag, a <ros2_control>
// joint that is NOT a joint of the URDF, a fixed joint, mimic misuse, a revolute/prismatic joint
// without <limit> (urdfdom) -- and fills HardwareInfo::limits/soft_limits from the URDF joint
// (<limit>, <safety_controller>) tightened by the position/velocity/effort interfaces' min/max.
// Not parsed: <transmission>s (kept empty), <properties><async>, <sdf> roots, acceleration/jerk
// limits from interface params.
#ifndef HARDWARE_INTERFACE__COMPONENT_PARSER_HPP_
#define HARDWARE_INTERFACE__COMPONENT_PARSER_HPP_

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "hardware_interface/hardware_info.hpp"
#include "hardware_interface/lexical_casts.hpp"
#include "hardware_interface/types/hardware_interface_type_values.hpp"
#include "rhi_fake/detail/xml.hpp"

namespace hardware_interface
{
namespace rhi_parser
{
namespace xml = ::rhi_fake::detail::xml;

inline std::string required_attribute(const xml::Element & e, const char * key)
{
  const std::string * value = e.attribute(key);
  if (value == nullptr) {
    throw std::runtime_error(
            std::string("no attribute ") + key + " in " + e.name + " tag");
  }
  return *value;
}

inline std::unordered_map<std::string, std::string> params(const xml::Element & parent)
{
  std::unordered_map<std::string, std::string> out;
  for (const xml::Element * p : parent.all("param")) {
    out[xml::trim(required_attribute(*p, "name"))] = xml::trim(p->text);
  }
  return out;
}

inline InterfaceInfo interface_from_xml(const xml::Element & e)
{
  InterfaceInfo info{};
  info.name = required_attribute(e, "name");
  info.parameters = params(e);
  const auto find = [&info](const char * key) {
      const auto it = info.parameters.find(key);
      return it == info.parameters.end() ? std::string() : it->second;
    };
  info.min = find("min");
  info.max = find("max");
  info.initial_value = find("initial_value");
  info.enable_limits = true;
  if (const xml::Element * limits = e.first("limits")) {
    info.enable_limits = parse_bool(required_attribute(*limits, "enable"));
  }
  const std::string * data_type = e.attribute("data_type");
  info.data_type = data_type != nullptr ? *data_type : "double";
  const std::string * size = e.attribute("size");
  info.size = size != nullptr ? std::stoi(*size) : 1;
  if (info.size <= 0) {
    throw std::runtime_error("Could not parse size tag in \"" + e.name + "\": not positive");
  }
  return info;
}

inline ComponentInfo component_from_xml(const xml::Element & e)
{
  ComponentInfo component;
  component.type = e.name;
  component.name = required_attribute(e, "name");
  if (component.type == "joint") {
    const std::string * mimic = e.attribute("mimic");
    component.is_mimic = mimic == nullptr ? MimicAttribute::NOT_SET :
      (parse_bool(*mimic) ? MimicAttribute::TRUE : MimicAttribute::FALSE);
  }
  if (const xml::Element * limits = e.first("limits")) {
    component.enable_limits = parse_bool(required_attribute(*limits, "enable"));
  }
  for (const xml::Element * c : e.all("command_interface")) {
    InterfaceInfo info = interface_from_xml(*c);
    info.enable_limits = info.enable_limits && component.enable_limits;
    component.command_interfaces.push_back(info);
  }
  for (const xml::Element * s : e.all("state_interface")) {
    InterfaceInfo info = interface_from_xml(*s);
    info.enable_limits = info.enable_limits && component.enable_limits;
    component.state_interfaces.push_back(info);
  }
  component.parameters = params(e);
  return component;
}

inline HardwareInfo hardware_from_xml(const xml::Element & e, const std::string & urdf)
{
  HardwareInfo hw{};
  hw.name = required_attribute(e, "name");
  hw.type = required_attribute(e, "type");
  const std::string * rw_rate = e.attribute("rw_rate");
  const int rate = rw_rate != nullptr ? std::stoi(xml::trim(*rw_rate)) : 0;
  if (rate < 0) {
    throw std::runtime_error("Could not parse rw_rate tag in \"ros2_control\": negative");
  }
  hw.rw_rate = static_cast<unsigned int>(rate);
  const std::string * is_async = e.attribute("is_async");
  hw.is_async = is_async != nullptr && parse_bool(xml::trim(*is_async));
  for (const auto & child : e.children) {
    if (child->name == "hardware") {
      const xml::Element * plugin = child->first("plugin");
      if (plugin == nullptr) {
        throw std::runtime_error(
                "Missing <plugin> tag of <hardware> element for '" + hw.name + "' in your URDF.");
      }
      hw.hardware_plugin_name = xml::trim(plugin->text);
      if (const xml::Element * group = child->first("group")) {
        hw.group = xml::trim(group->text);
      }
      hw.hardware_parameters = params(*child);
    } else if (child->name == "joint") {
      hw.joints.push_back(component_from_xml(*child));
    } else if (child->name == "sensor") {
      hw.sensors.push_back(component_from_xml(*child));
    } else if (child->name == "gpio") {
      hw.gpios.push_back(component_from_xml(*child));
    } else if (child->name != "transmission" && child->name != "properties") {
      throw std::runtime_error("invalid tag name '" + child->name + "'");
    }
  }
  hw.original_xml = urdf;
  return hw;
}

inline bool min_max(const InterfaceInfo & itf, double & min, double & max)
{
  if (itf.min.empty() && itf.max.empty()) {
    return false;
  }
  try {
    if (!itf.min.empty()) {min = hardware_interface::stod(itf.min);}
    if (!itf.max.empty()) {max = hardware_interface::stod(itf.max);}
    return true;
  } catch (const std::invalid_argument &) {
    return false;  // upstream prints and skips
  }
}

// Upstream's update_interface_limits() for position, velocity and effort.
inline void tighten_limits(const ComponentInfo & joint, joint_limits::JointLimits & limits)
{
  constexpr double big = std::numeric_limits<double>::max();
  if (!joint.enable_limits) {
    limits.disable_all_limits();
    return;
  }
  for (const auto & itf : joint.command_interfaces) {
    if (itf.name == HW_IF_POSITION) {
      limits.min_position = limits.has_position_limits && itf.enable_limits ? limits.min_position : -big;
      limits.max_position = limits.has_position_limits && itf.enable_limits ? limits.max_position : big;
      double lo = limits.min_position, hi = limits.max_position;
      if (itf.enable_limits && min_max(itf, lo, hi)) {
        limits.min_position = std::max(lo, limits.min_position);
        limits.max_position = std::min(hi, limits.max_position);
        limits.has_position_limits = true;
      }
      limits.has_position_limits = limits.has_position_limits && itf.enable_limits;
    } else if (itf.name == HW_IF_VELOCITY || itf.name == HW_IF_EFFORT) {
      const bool velocity = itf.name == HW_IF_VELOCITY;
      double & bound = velocity ? limits.max_velocity : limits.max_effort;
      bool & has = velocity ? limits.has_velocity_limits : limits.has_effort_limits;
      bound = has ? bound : big;
      double lo = -bound, hi = bound;
      if (itf.enable_limits && min_max(itf, lo, hi)) {
        bound = std::min(std::min(std::abs(lo), hi), bound);
        has = true;
      }
      has = has && itf.enable_limits;
    }
  }
}

inline double number_attribute(const xml::Element & e, const char * key, double fallback)
{
  const std::string * v = e.attribute(key);
  return v == nullptr ? fallback : hardware_interface::stod(xml::trim(*v));
}

// The URDF checks of upstream's parse_control_resources_from_urdf() (urdf::Model part).
inline void check_against_urdf(const xml::Element & robot, HardwareInfo & hw)
{
  std::unordered_map<std::string, const xml::Element *> urdf_joints;
  for (const xml::Element * j : robot.all("joint")) {
    const std::string type = required_attribute(*j, "type");
    if ((type == "revolute" || type == "prismatic") && j->first("limit") == nullptr) {
      throw std::runtime_error("Failed to parse URDF file");  // urdfdom: limits required
    }
    urdf_joints[required_attribute(*j, "name")] = j;
  }
  for (std::size_t i = 0; i < hw.joints.size(); ++i) {
    const ComponentInfo & joint = hw.joints[i];
    const auto found = urdf_joints.find(joint.name);
    if (found == urdf_joints.end()) {
      throw std::runtime_error("Joint '" + joint.name + "' not found in URDF");
    }
    const xml::Element & urdf_joint = *found->second;
    const std::string type = *urdf_joint.attribute("type");
    const xml::Element * mimic = urdf_joint.first("mimic");
    if (mimic == nullptr && joint.is_mimic == MimicAttribute::TRUE) {
      throw std::runtime_error("Joint '" + joint.name + "' has no mimic information in the URDF");
    }
    if (mimic != nullptr && joint.is_mimic != MimicAttribute::FALSE) {
      if (!joint.command_interfaces.empty()) {
        throw std::runtime_error(
                "Joint '" + joint.name + "' has mimic attribute not set to false: Activated mimic "
                "joints cannot have command interfaces.");
      }
      const std::string mimicked = required_attribute(*mimic, "joint");
      const auto it = std::find_if(
        hw.joints.begin(), hw.joints.end(), [&](const ComponentInfo & j) {return j.name == mimicked;});
      if (it == hw.joints.end()) {
        throw std::runtime_error("Mimic joint '" + mimicked + "' not found in <ros2_control> tag");
      }
      MimicJoint m;
      m.joint_index = i;
      m.mimicked_joint_index = static_cast<std::size_t>(it - hw.joints.begin());
      m.multiplier = number_attribute(*mimic, "multiplier", 1.0);
      m.offset = number_attribute(*mimic, "offset", 0.0);
      hw.mimic_joints.push_back(m);
    }
    if (type == "fixed") {
      throw std::runtime_error(
              "Joint '" + joint.name +
              "' is of type 'fixed'. Fixed joints do not make sense in ros2_control.");
    }
    joint_limits::JointLimits limits;
    if (const xml::Element * limit = urdf_joint.first("limit")) {
      limits.has_position_limits = type == "revolute" || type == "prismatic";
      if (limits.has_position_limits) {
        limits.min_position = number_attribute(*limit, "lower", 0.0);
        limits.max_position = number_attribute(*limit, "upper", 0.0);
      } else if (type == "continuous") {
        limits.angle_wraparound = true;
      }
      limits.has_velocity_limits = true;
      limits.max_velocity = std::abs(number_attribute(*limit, "velocity", 0.0));
      limits.has_effort_limits = true;
      limits.max_effort = std::abs(number_attribute(*limit, "effort", 0.0));
    }
    tighten_limits(joint, limits);
    hw.limits[joint.name] = limits;
    if (const xml::Element * safety = urdf_joint.first("safety_controller")) {
      joint_limits::SoftJointLimits soft;
      soft.min_position = number_attribute(*safety, "soft_lower_limit", 0.0);
      soft.max_position = number_attribute(*safety, "soft_upper_limit", 0.0);
      soft.k_position = number_attribute(*safety, "k_position", 0.0);
      soft.k_velocity = number_attribute(*safety, "k_velocity", 0.0);
      if (limits.has_position_limits) {
        soft.min_position = std::max(soft.min_position, limits.min_position);
        soft.max_position = std::min(soft.max_position, limits.max_position);
      }
      hw.soft_limits[joint.name] = soft;
    }
  }
}
}  // namespace rhi_parser

/// Every <ros2_control> block of the URDF, checked against the URDF's joints.
inline std::vector<HardwareInfo> parse_control_resources_from_urdf(const std::string & urdf)
{
  if (urdf.empty()) {
    throw std::runtime_error("empty URDF passed to robot");
  }
  std::unique_ptr<rhi_parser::xml::Element> robot;
  try {
    robot = rhi_parser::xml::parse(urdf);
  } catch (const std::exception & e) {
    throw std::runtime_error(std::string("invalid URDF passed in to robot parser: ") + e.what());
  }
  if (robot->name != "robot") {
    throw std::runtime_error(
            "the robot tag is not root element in URDF or sdf tag is not root element in SDF");
  }
  const auto blocks = robot->all("ros2_control");
  if (blocks.empty()) {
    throw std::runtime_error("no 'ros2_control' tag found in the URDF");
  }
  std::vector<HardwareInfo> hardware;
  for (const auto * block : blocks) {
    hardware.push_back(rhi_parser::hardware_from_xml(*block, urdf));
  }
  for (auto & hw : hardware) {
    rhi_parser::check_against_urdf(*robot, hw);
  }
  return hardware;
}

inline std::vector<InterfaceDescription> parse_state_interface_descriptions(
  const std::vector<ComponentInfo> & component_info)
{
  std::vector<InterfaceDescription> out;
  for (const auto & component : component_info) {
    for (const auto & itf : component.state_interfaces) {
      out.emplace_back(component.name, itf);
    }
  }
  return out;
}

inline void parse_state_interface_descriptions(
  const std::vector<ComponentInfo> & component_info,
  std::unordered_map<std::string, InterfaceDescription> & state_interfaces_map)
{
  for (const auto & d : parse_state_interface_descriptions(component_info)) {
    state_interfaces_map.insert(std::make_pair(d.get_name(), d));
  }
}

inline std::vector<InterfaceDescription> parse_command_interface_descriptions(
  const std::vector<ComponentInfo> & component_info)
{
  std::vector<InterfaceDescription> out;
  for (const auto & component : component_info) {
    for (const auto & itf : component.command_interfaces) {
      out.emplace_back(component.name, itf);
    }
  }
  return out;
}

inline void parse_command_interface_descriptions(
  const std::vector<ComponentInfo> & component_info,
  std::unordered_map<std::string, InterfaceDescription> & command_interfaces_map)
{
  for (const auto & d : parse_command_interface_descriptions(component_info)) {
    command_interfaces_map.insert(std::make_pair(d.get_name(), d));
  }
}

}  // namespace hardware_interface
#endif  // HARDWARE_INTERFACE__COMPONENT_PARSER_HPP_
