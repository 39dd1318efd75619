// rhi-gen test stand-in (not the real ROS 2 code): registry filled by PLUGINLIB_EXPORT_CLASS.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <typeindex>
#include <vector>

namespace rhi_fake {
namespace detail {

struct PluginEntry
{
  std::string derived;      // e.g. "robot_hardware_interface::unitree::G1HardwareInterface" (as written in the macro)
  std::string base;         // e.g. "hardware_interface::SystemInterface"
  std::type_index base_type;
  std::function<std::shared_ptr<void>()> create;   // returns shared_ptr<Base> as shared_ptr<void>
};

// One <class name=".." type=".." base_class_type=".."> of a pluginlib plugin description.
struct PluginDescription
{
  std::string lookup_name;  // e.g. "robot_hardware_interface/agibot/X2HardwareInterface" (what a <plugin> tag names)
  std::string type;         // e.g. "robot_hardware_interface::agibot::X2HardwareInterface"
  std::string base;         // e.g. "hardware_interface::SystemInterface"
};

struct PluginRegistry
{
  std::mutex mutex;
  std::vector<PluginEntry> entries;
  std::vector<PluginDescription> descriptions;
  bool environment_loaded = false;  // RHI_FAKE_PLUGIN_XML read (see rhi_fake/plugins.hpp)
};

inline PluginRegistry & plugin_registry()
{
  static PluginRegistry registry;
  return registry;
}

template<typename Derived, typename Base>
inline void register_plugin(const char * derived_name, const char * base_name)
{
  auto & reg = plugin_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  reg.entries.push_back(
    PluginEntry{derived_name, base_name, std::type_index(typeid(Base)),
      []() -> std::shared_ptr<void> {
        std::shared_ptr<Base> p = std::make_shared<Derived>();
        return p;
      }});
}

}  // namespace detail
}  // namespace rhi_fake
