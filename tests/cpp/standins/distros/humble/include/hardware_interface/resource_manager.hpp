// rhi-gen test stand-in (not the real ROS 2 code): hardware_interface::ResourceManager of
// ros2_control Humble (2.x), hardware_interface/include/hardware_interface/resource_manager.hpp.
//
// Same include path, namespace, constructors and signatures as Humble for the subset below
// (no claim_*_interface / Loaned*Interface, no import_component, no controller reference
// interfaces, no set_component_state / read / write). Like Humble: the URDF constructor is
// explicit and takes (urdf, validate_interfaces = true, activate_all = false); copying is
// deleted (and, as upstream declares no move operations, so is moving); get_components_status()
// is non-const; the header does not bring in lifecycle_state_names.hpp or rclcpp/rclcpp.hpp.
//
// Behaviour (a fake): NO plugin is loaded and no hardware code runs. The URDF is scanned
// minimally (no XML validation): every <ros2_control name=".." type=".."> block becomes one
// component that "exports" exactly the interfaces its <joint>/<sensor>/<gpio> children list
// ("<component>/<interface>" keys), so validate_interfaces can never fail here. Components are
// reported 'unconfigured' (as after a successful on_init()), or 'active' with activate_all.
// Like Humble's parser it throws std::runtime_error for an empty URDF, a URDF without <robot>
// and a URDF without <ros2_control>.
#ifndef HARDWARE_INTERFACE__RESOURCE_MANAGER_HPP_
#define HARDWARE_INTERFACE__RESOURCE_MANAGER_HPP_

#include <algorithm>
#include <cstddef>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "hardware_interface/hardware_component_info.hpp"
#include "hardware_interface/hardware_info.hpp"
#include "hardware_interface/types/hardware_interface_return_values.hpp"
#include "hardware_interface/visibility_control.h"
#include "rclcpp/duration.hpp"
#include "rclcpp/time.hpp"

namespace hardware_interface
{
struct HardwareReadWriteStatus
{
  bool ok;
  std::vector<std::string> failed_hardware_names;
};

class HARDWARE_INTERFACE_PUBLIC ResourceManager
{
public:
  /// Default constructor for the Resource Manager.
  ResourceManager() = default;

  /// Loads the URDF (see the file comment for what the stand-in does with it).
  explicit ResourceManager(
    const std::string & urdf, bool validate_interfaces = true, bool activate_all = false)
  {
    load_urdf(urdf, validate_interfaces);
    if (activate_all) {
      for (auto & entry : components_) {
        entry.second.state = rclcpp_lifecycle::State(
          lifecycle_msgs::msg::State::PRIMARY_STATE_ACTIVE, "active");
      }
    }
  }

  ResourceManager(const ResourceManager &) = delete;

  ~ResourceManager() = default;

  void load_urdf(
    const std::string & urdf, bool validate_interfaces = true,
    bool load_and_initialize_components = true)
  {
    (void)validate_interfaces;  // the fake exports exactly what the URDF lists
    is_urdf_loaded_ = true;
    parse(urdf, load_and_initialize_components);
  }

  bool is_urdf_already_loaded() const {return is_urdf_loaded_;}

  /// Returns all registered state interfaces keys.
  std::vector<std::string> state_interface_keys() const {return state_keys_;}

  /// Returns all available state interfaces keys (interfaces of inactive or active components).
  std::vector<std::string> available_state_interfaces() const
  {
    return available(&HardwareComponentInfo::state_interfaces);
  }

  bool state_interface_is_available(const std::string & name) const
  {
    const auto keys = available_state_interfaces();
    return std::find(keys.begin(), keys.end(), name) != keys.end();
  }

  /// Checks whether a command interface is already claimed (the stand-in never claims one).
  bool command_interface_is_claimed(const std::string & key) const
  {
    (void)key;
    return false;
  }

  /// Returns all registered command interfaces keys.
  std::vector<std::string> command_interface_keys() const {return command_keys_;}

  /// Returns all available command interfaces keys.
  std::vector<std::string> available_command_interfaces() const
  {
    return available(&HardwareComponentInfo::command_interfaces);
  }

  bool command_interface_is_available(const std::string & interface) const
  {
    const auto keys = available_command_interfaces();
    return std::find(keys.begin(), keys.end(), interface) != keys.end();
  }

  size_t actuator_components_size() const {return count_type("actuator");}
  size_t sensor_components_size() const {return count_type("sensor");}
  size_t system_components_size() const {return count_type("system");}

  /// Return status for all components.
  std::unordered_map<std::string, HardwareComponentInfo> get_components_status()
  {
    return components_;
  }

  /// Checks whether a command interface is registered under the given key.
  bool command_interface_exists(const std::string & key) const
  {
    return std::find(command_keys_.begin(), command_keys_.end(), key) != command_keys_.end();
  }

  /// Checks whether a state interface is registered under the given key.
  bool state_interface_exists(const std::string & key) const
  {
    return std::find(state_keys_.begin(), state_keys_.end(), key) != state_keys_.end();
  }

private:
  static std::string unescape(const std::string & text)
  {
    static const std::pair<const char *, char> kEntities[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
    std::string out;
    for (std::size_t i = 0; i < text.size(); ) {
      bool replaced = false;
      if (text[i] == '&') {
        for (const auto & entity : kEntities) {
          const std::string name(entity.first);
          if (text.compare(i, name.size(), name) == 0) {
            out += entity.second;
            i += name.size();
            replaced = true;
            break;
          }
        }
      }
      if (!replaced) {
        out += text[i++];
      }
    }
    return out;
  }

  /// Value of attribute `attribute` of the start tag that begins at `tag_begin`.
  static std::string attribute(const std::string & xml, std::size_t tag_begin, const std::string & attr)
  {
    const std::size_t tag_end = xml.find('>', tag_begin);
    const std::string tag = xml.substr(tag_begin, tag_end - tag_begin);
    for (const char quote : {'"', '\''}) {
      const std::string key = " " + attr + "=" + quote;
      const std::size_t at = tag.find(key);
      if (at != std::string::npos) {
        const std::size_t begin = at + key.size();
        const std::size_t end = tag.find(quote, begin);
        if (end != std::string::npos) {
          return unescape(tag.substr(begin, end - begin));
        }
      }
    }
    return "";
  }

  /// Every start tag <tag ...> (not <tagsuffix ...>) in [begin, end).
  static std::vector<std::size_t> start_tags(
    const std::string & xml, const std::string & tag, std::size_t begin, std::size_t end)
  {
    std::vector<std::size_t> found;
    const std::string open = "<" + tag;
    for (std::size_t at = xml.find(open, begin); at != std::string::npos && at < end;
      at = xml.find(open, at + 1))
    {
      const char next = at + open.size() < xml.size() ? xml[at + open.size()] : '\0';
      if (next == ' ' || next == '>' || next == '/' || next == '\n' || next == '\t' || next == '\r') {
        found.push_back(at);
      }
    }
    return found;
  }

  void parse(const std::string & urdf, bool initialize)
  {
    if (urdf.empty()) {
      throw std::runtime_error("empty URDF passed to robot");
    }
    if (start_tags(urdf, "robot", 0, urdf.size()).empty()) {
      throw std::runtime_error("the robot tag is not root element in URDF");
    }
    const auto blocks = start_tags(urdf, "ros2_control", 0, urdf.size());
    if (blocks.empty()) {
      throw std::runtime_error("no ros2_control tag");
    }
    for (const std::size_t block : blocks) {
      const std::size_t block_end = urdf.find("</ros2_control>", block);
      if (block_end == std::string::npos) {
        throw std::runtime_error("unterminated ros2_control tag");
      }
      HardwareComponentInfo info;
      info.name = attribute(urdf, block, "name");
      info.type = attribute(urdf, block, "type");
      if (initialize) {
        info.state = rclcpp_lifecycle::State(
          lifecycle_msgs::msg::State::PRIMARY_STATE_UNCONFIGURED, "unconfigured");
      }
      for (const char * element : {"joint", "sensor", "gpio"}) {
        for (const std::size_t at : start_tags(urdf, element, block, block_end)) {
          const std::string prefix = attribute(urdf, at, "name");
          const std::size_t element_end = std::min(
            urdf.find(std::string("</") + element + ">", at), block_end);
          for (const std::size_t s : start_tags(urdf, "state_interface", at, element_end)) {
            info.state_interfaces.push_back(prefix + "/" + attribute(urdf, s, "name"));
          }
          for (const std::size_t c : start_tags(urdf, "command_interface", at, element_end)) {
            info.command_interfaces.push_back(prefix + "/" + attribute(urdf, c, "name"));
          }
        }
      }
      if (initialize) {
        state_keys_.insert(state_keys_.end(), info.state_interfaces.begin(), info.state_interfaces.end());
        command_keys_.insert(
          command_keys_.end(), info.command_interfaces.begin(), info.command_interfaces.end());
      }
      components_[info.name] = info;
    }
  }

  std::vector<std::string> available(
    std::vector<std::string> HardwareComponentInfo::* member) const
  {
    std::vector<std::string> keys;
    for (const auto & entry : components_) {
      const auto id = entry.second.state.id();
      if (id == lifecycle_msgs::msg::State::PRIMARY_STATE_INACTIVE ||
        id == lifecycle_msgs::msg::State::PRIMARY_STATE_ACTIVE)
      {
        const auto & list = entry.second.*member;
        keys.insert(keys.end(), list.begin(), list.end());
      }
    }
    return keys;
  }

  size_t count_type(const std::string & type) const
  {
    return static_cast<size_t>(std::count_if(
      components_.begin(), components_.end(),
      [&type](const auto & entry) {return entry.second.type == type;}));
  }

  std::unordered_map<std::string, HardwareComponentInfo> components_;
  std::vector<std::string> state_keys_;
  std::vector<std::string> command_keys_;
  bool is_urdf_loaded_ = false;
};

}  // namespace hardware_interface
#endif  // HARDWARE_INTERFACE__RESOURCE_MANAGER_HPP_
