// rhi-gen test stand-in (not the real ROS 2 code): PLUGINLIB_EXPORT_CLASS(Derived, Base).
// Like the real macro (class_loader's registration proxy) it is used at namespace scope, needs
// Derived to be a complete, non-abstract, default-constructible class derived from Base (checked
// with static_asserts), and registers the class when the library is loaded (static init).
// Tests can instantiate registered classes with rhi_fake::plugins::create<Base>("ns::Derived").
#ifndef PLUGINLIB__CLASS_LIST_MACROS_HPP_
#define PLUGINLIB__CLASS_LIST_MACROS_HPP_

#include <type_traits>

#include "rhi_fake/detail/plugin_core.hpp"

#define RHI_PLUGINLIB_EXPORT_CLASS_HOP2(Derived, Base, UniqueID) \
  namespace \
  { \
  struct RhiPluginlibProxy ## UniqueID \
  { \
    using derived_t = Derived; \
    using base_t = Base; \
    static_assert( \
      std::is_base_of<base_t, derived_t>::value, \
      "PLUGINLIB_EXPORT_CLASS: " #Derived " must derive from " #Base); \
    static_assert( \
      !std::is_abstract<derived_t>::value, \
      "PLUGINLIB_EXPORT_CLASS: " #Derived " is abstract (a pure virtual function is not overridden)"); \
    static_assert( \
      std::is_default_constructible<derived_t>::value, \
      "PLUGINLIB_EXPORT_CLASS: " #Derived " must be default constructible"); \
    RhiPluginlibProxy ## UniqueID() \
    { \
      ::rhi_fake::detail::register_plugin<derived_t, base_t>(#Derived, #Base); \
    } \
  }; \
  static RhiPluginlibProxy ## UniqueID g_rhi_register_plugin_ ## UniqueID; \
  }  // namespace

#define RHI_PLUGINLIB_EXPORT_CLASS_HOP1(Derived, Base, UniqueID) \
  RHI_PLUGINLIB_EXPORT_CLASS_HOP2(Derived, Base, UniqueID)

#define PLUGINLIB_EXPORT_CLASS(class_type, base_class_type) \
  RHI_PLUGINLIB_EXPORT_CLASS_HOP1(class_type, base_class_type, __COUNTER__)

#endif  // PLUGINLIB__CLASS_LIST_MACROS_HPP_
