// rhi-gen test stand-in (not the real ROS 2 code): the HardwareInfo structures of ros2_control
// 4.x+ (Jazzy 4.46, Kilted 5.16, Rolling/Lyrical 6.8), same members, defaults and types.
//
// As upstream, some members have NO initializer: InterfaceInfo::size and ::enable_limits,
// HardwareInfo::rw_rate, ::is_async (and ::thread_priority on 4.x/5.x). Build descriptions with
// value-initialisation (`HardwareInfo info{};`, `InterfaceInfo i{};`): HardwareComponentInterface::
// init() reads is_async. `thread_priority` is gone on 6.x. Not here: the fmt-based messages.
#ifndef HARDWARE_INTERFACE__HARDWARE_INFO_HPP_
#define HARDWARE_INTERFACE__HARDWARE_INFO_HPP_

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

#include "joint_limits/joint_limits.hpp"
#include "rhi_fake/detail/distro.hpp"

#if RHI_FAKE_HI_MAJOR >= 6
// 6.x guards its MimicAttribute enumerators against Windows' TRUE/FALSE macros.
#ifdef TRUE
#undef TRUE
#endif
#ifdef FALSE
#undef FALSE
#endif
#endif

namespace hardware_interface
{
/// One <command_interface>/<state_interface> of a joint, sensor or GPIO.
struct InterfaceInfo
{
  std::string name;
  std::string min = "";
  std::string max = "";
  std::string initial_value = "";
  std::string data_type = "double";
  int size;  // no initializer upstream
  std::unordered_map<std::string, std::string> parameters;
  bool enable_limits;  // no initializer upstream
};

/// A joint that mimics another one (indices into HardwareInfo::joints).
struct MimicJoint
{
  std::size_t joint_index;
  std::size_t mimicked_joint_index;
  double multiplier = 1.0;
  double offset = 0.0;
};

enum class MimicAttribute
{
  NOT_SET,
  TRUE,
  FALSE
};

/// Joint, sensor or GPIO of a hardware component.
struct ComponentInfo
{
  std::string name;
  std::string type;
  MimicAttribute is_mimic = MimicAttribute::NOT_SET;
  bool enable_limits = true;
  std::vector<InterfaceInfo> command_interfaces;
  std::vector<InterfaceInfo> state_interfaces;
  std::unordered_map<std::string, std::string> parameters;
};

struct JointInfo
{
  std::string name;
  std::vector<std::string> state_interfaces;
  std::vector<std::string> command_interfaces;
  std::string role;
  double mechanical_reduction = 1.0;
  double offset = 0.0;
  bool read_only = false;
};

struct ActuatorInfo
{
  std::string name;
  std::vector<std::string> state_interfaces;
  std::vector<std::string> command_interfaces;
  std::string role;
  double mechanical_reduction = 1.0;
  double offset = 0.0;
  bool read_only = false;
};

struct TransmissionInfo
{
  std::string name;
  std::string type;
  std::vector<JointInfo> joints;
  std::vector<ActuatorInfo> actuators;
  std::unordered_map<std::string, std::string> parameters;
};

/// Value types a handle can hold.
using HANDLE_DATATYPE = std::variant<
  std::monostate, double, float, bool, uint8_t, int8_t, uint16_t, int16_t, uint32_t, int32_t>;

class HandleDataType
{
public:
  enum Value : int8_t
  {
    UNKNOWN = -1,
    DOUBLE,
    FLOAT32,
    BOOL,
    UINT8,
    INT8,
    UINT16,
    INT16,
    UINT32,
    INT32,
  };

  HandleDataType() = default;
  constexpr HandleDataType(Value value)  // NOLINT(runtime/explicit): implicit, as upstream
  : value_(value) {}

  explicit HandleDataType(const std::string & data_type)
  {
    static const std::pair<const char *, Value> kNames[] = {
      {"double", DOUBLE}, {"bool", BOOL}, {"float32", FLOAT32}, {"uint8", UINT8}, {"int8", INT8},
      {"uint16", UINT16}, {"int16", INT16}, {"uint32", UINT32}, {"int32", INT32}};
    for (const auto & entry : kNames) {
      if (data_type == entry.first) {
        value_ = entry.second;
      }
    }
  }

  operator Value() const {return value_;}
  explicit operator bool() const = delete;

  constexpr bool operator==(HandleDataType other) const {return value_ == other.value_;}
  constexpr bool operator!=(HandleDataType other) const {return value_ != other.value_;}
  constexpr bool operator==(Value other) const {return value_ == other;}
  constexpr bool operator!=(Value other) const {return value_ != other;}

  std::string to_string() const
  {
    switch (value_) {
      case DOUBLE: return "double";
      case BOOL: return "bool";
      case FLOAT32: return "float32";
      case UINT8: return "uint8";
      case INT8: return "int8";
      case UINT16: return "uint16";
      case INT16: return "int16";
      case UINT32: return "uint32";
      case INT32: return "int32";
      default: return "unknown";
    }
  }

  bool is_castable_to_double() const {return value_ != UNKNOWN;}

  double cast_to_double(const HANDLE_DATATYPE & value) const
  {
    switch (value_) {
      case DOUBLE: return std::get<double>(value);
      case FLOAT32: return static_cast<double>(std::get<float>(value));
      case BOOL: return static_cast<double>(std::get<bool>(value));
      case UINT8: return static_cast<double>(std::get<uint8_t>(value));
      case INT8: return static_cast<double>(std::get<int8_t>(value));
      case UINT16: return static_cast<double>(std::get<uint16_t>(value));
      case INT16: return static_cast<double>(std::get<int16_t>(value));
      case UINT32: return static_cast<double>(std::get<uint32_t>(value));
      case INT32: return static_cast<double>(std::get<int32_t>(value));
      default:
        throw std::runtime_error("Data type : '" + to_string() + "' cannot be casted to double.");
    }
  }

  HandleDataType from_string(const std::string & data_type) {return HandleDataType(data_type);}

private:
  Value value_ = UNKNOWN;
};

/// One interface the framework creates a handle for: "<prefix_name>/<interface_info.name>".
struct InterfaceDescription
{
  InterfaceDescription(const std::string & prefix_name_in, const InterfaceInfo & interface_info_in)
  : prefix_name(prefix_name_in),
    interface_info(interface_info_in),
    interface_name(prefix_name + "/" + interface_info.name)
  {
  }

  std::string prefix_name;
  InterfaceInfo interface_info;
  std::string interface_name;

  const std::string & get_prefix_name() const {return prefix_name;}
  const std::string & get_interface_name() const {return interface_info.name;}
  const std::string & get_name() const {return interface_name;}
  const std::string & get_data_type_string() const {return interface_info.data_type;}
  HandleDataType get_data_type() const {return HandleDataType(interface_info.data_type);}
};

struct HardwareAsyncParams
{
  int thread_priority = 50;
  std::string scheduling_policy = "synchronized";
  std::vector<int> cpu_affinity_cores = {};
  bool print_warnings = true;
};

/// A <ros2_control> block of the robot description.
struct HardwareInfo
{
  std::string name;
  std::string type;
  std::string group;
  unsigned int rw_rate;  // no initializer upstream
  bool is_async;  // no initializer upstream
#if RHI_FAKE_HI_MAJOR < 6
  int thread_priority;  // no initializer upstream; removed on 6.x (use async_params)
#endif
  HardwareAsyncParams async_params;
  /// The <plugin> (pluginlib lookup name); Humble called it hardware_class_type.
  std::string hardware_plugin_name;
  std::unordered_map<std::string, std::string> hardware_parameters;
  std::vector<ComponentInfo> joints;
  std::vector<MimicJoint> mimic_joints;
  std::vector<ComponentInfo> sensors;
  std::vector<ComponentInfo> gpios;
  std::vector<TransmissionInfo> transmissions;
  std::string original_xml;
  /// Joint limits parsed from the URDF (tightened by the interfaces' min/max), by joint name.
  std::unordered_map<std::string, joint_limits::JointLimits> limits;
  std::unordered_map<std::string, joint_limits::SoftJointLimits> soft_limits;
};

}  // namespace hardware_interface
#endif  // HARDWARE_INTERFACE__HARDWARE_INFO_HPP_
