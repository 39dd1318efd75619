// rhi-gen test hooks (test code only): classes registered with PLUGINLIB_EXPORT_CLASS.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>
#include <typeindex>
#include <vector>

#include "rhi_fake/detail/plugin_core.hpp"
#include "rhi_fake/detail/xml.hpp"

namespace rhi_fake {
namespace plugins {

struct PluginClass
{
  std::string derived;   // as written in PLUGINLIB_EXPORT_CLASS, e.g. "robot_hardware_interface::unitree::G1HardwareInterface"
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

/// Registers a plugin description entry, as pluginlib learns it from a package's plugin XML.
inline void add_description(
  const std::string & lookup_name, const std::string & type, const std::string & base)
{
  auto & reg = detail::plugin_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  reg.descriptions.push_back(detail::PluginDescription{lookup_name, type, base});
}

/// Registers every <class name type base_class_type> of a pluginlib description XML text
/// (<library> or <class_libraries> root). Throws std::runtime_error on malformed XML.
inline void load_description_xml(const std::string & xml_text)
{
  const auto root = detail::xml::parse(xml_text);
  std::vector<const detail::xml::Element *> libraries;
  if (root->name == "library") {
    libraries.push_back(root.get());
  } else {
    libraries = root->all("library");
  }
  for (const auto * library : libraries) {
    for (const auto * c : library->all("class")) {
      const std::string * type = c->attribute("type");
      const std::string * base = c->attribute("base_class_type");
      const std::string * name = c->attribute("name");
      if (type == nullptr || base == nullptr) {
        throw std::runtime_error("rhi_fake: plugin description <class> without type/base_class_type");
      }
      add_description(name != nullptr ? *name : *type, *type, *base);
    }
  }
}

/// The class type a lookup name stands for with that base (what pluginlib's ClassLoader resolves).
/// Descriptions come from add_description()/load_description_xml() and, on first use, from the
/// files listed in the environment variable RHI_FAKE_PLUGIN_XML (':'-separated), the stand-in for
/// pluginlib finding installed plugin descriptions through the ament index. Throws
/// std::out_of_range, naming the declared classes, for an unknown lookup name.
inline std::string resolve(const std::string & lookup_name, const std::string & base)
{
  auto & reg = detail::plugin_registry();
  bool load_env = false;
  {
    std::lock_guard<std::mutex> lock(reg.mutex);
    load_env = !reg.environment_loaded;
    reg.environment_loaded = true;
  }
  if (load_env) {
    if (const char * paths = std::getenv("RHI_FAKE_PLUGIN_XML")) {
      std::string list(paths);
      for (std::size_t begin = 0; begin <= list.size(); ) {
        const std::size_t end = std::min(list.find(':', begin), list.size());
        const std::string path = list.substr(begin, end - begin);
        if (!path.empty()) {
          std::ifstream in(path);
          if (!in) {throw std::runtime_error("rhi_fake: cannot read plugin description " + path);}
          std::stringstream text;
          text << in.rdbuf();
          load_description_xml(text.str());
        }
        begin = end + 1;
      }
    }
  }
  std::lock_guard<std::mutex> lock(reg.mutex);
  std::string declared;
  for (const auto & d : reg.descriptions) {
    if (d.base != base) {continue;}
    if (d.lookup_name == lookup_name) {return d.type;}
    declared += (declared.empty() ? "" : ", ") + d.lookup_name;
  }
  throw std::out_of_range(
          "According to the loaded plugin descriptions the class " + lookup_name +
          " with base class type " + base + " does not exist. Declared types are " + declared);
}

/// Forget the plugin descriptions (exported classes stay: they are registered at static init).
inline void reset_descriptions()
{
  auto & reg = detail::plugin_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  reg.descriptions.clear();
  reg.environment_loaded = false;
}

}  // namespace plugins
}  // namespace rhi_fake
