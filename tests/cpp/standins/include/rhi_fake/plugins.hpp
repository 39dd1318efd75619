// rhi-gen test hooks (test code only): classes registered with PLUGINLIB_EXPORT_CLASS.
#pragma once

#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>
#include <typeindex>
#include <vector>

#include "rhi_fake/detail/plugin_core.hpp"

namespace rhi_fake {
namespace plugins {

struct PluginClass
{
  std::string derived;   // as written in PLUGINLIB_EXPORT_CLASS, e.g. "unitree::G1HardwareInterface"
  std::string base;      // e.g. "hardware_interface::SystemInterface"
};

/// All classes exported in this process (in registration order).
inline std::vector<PluginClass> classes()
{
  auto & reg = detail::plugin_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  std::vector<PluginClass> out;
  for (const auto & e : reg.entries) {out.push_back(PluginClass{e.derived, e.base});}
  return out;
}

/// New instance of the exported class `derived` (spelled as in the macro, a leading "::" is
/// ignored) as a shared_ptr<Base>. Throws std::out_of_range if no such class was exported with
/// that Base.
template<typename Base>
std::shared_ptr<Base> create(std::string_view derived)
{
  if (derived.substr(0, 2) == "::") {derived.remove_prefix(2);}
  std::function<std::shared_ptr<void>()> factory;
  {
    auto & reg = detail::plugin_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    for (const auto & e : reg.entries) {
      std::string_view name = e.derived;
      if (name.substr(0, 2) == "::") {name.remove_prefix(2);}
      if (name == derived && e.base_type == std::type_index(typeid(Base))) {
        factory = e.create;
        break;
      }
    }
  }
  if (!factory) {
    throw std::out_of_range("rhi_fake: no plugin class '" + std::string(derived) + "' exported");
  }
  return std::static_pointer_cast<Base>(factory());
}

}  // namespace plugins
}  // namespace rhi_fake
