// rhi-gen test stand-in (not the real ROS 2 code): hardware_interface::Handle, StateInterface and
// CommandInterface of ros2_control 4.x+ (Jazzy 4.46, Kilted 5.16, Rolling/Lyrical 6.8).
//
// As upstream:
//  * a handle owns its value (a variant typed by the description's data_type; NaN when no
//    initial_value is given) and a std::shared_mutex. get_optional<T>() / set_value(v) only
//    TRY the lock: get_optional() returns std::nullopt and set_value() returns false while another
//    thread holds it. Both are [[nodiscard]]. set_value(v) deduces T from v: set_value(0) is
//    set_value<int32_t> and throws std::runtime_error on a double handle, write set_value(0.0);
//  * Handle(prefix, name, double *) is [[deprecated]] (the value then lives in the caller's
//    double, the Humble way), so are Handle(name) and get_full_name() (4.x only);
//  * get_value() and get_value(T &) are [[deprecated]] on 4.x and REMOVED on 5.x+;
//  * 5.x+: get_optional<double>() of a bool handle casts it (and logs a warning once); 4.x throws;
//  * CommandInterface cannot be copied (moved only); SharedPtr / ConstSharedPtr aliases.
// Not here: introspection registration (pal_statistics) and the fmt-formatted messages.
#ifndef HARDWARE_INTERFACE__HANDLE_HPP_
#define HARDWARE_INTERFACE__HANDLE_HPP_

#include <algorithm>
#include <atomic>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <shared_mutex>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "hardware_interface/hardware_info.hpp"
#include "hardware_interface/lexical_casts.hpp"
#include "hardware_interface/macros.hpp"
#include "rhi_fake/detail/distro.hpp"
#if RHI_FAKE_HI_MAJOR >= 5
#include "rclcpp/logging.hpp"
#endif

namespace hardware_interface
{

class Handle
{
public:
  [[deprecated("Use InterfaceDescription for initializing the Interface")]]
  Handle(const std::string & prefix_name, const std::string & interface_name, double * value_ptr)
  : prefix_name_(prefix_name),
    interface_name_(interface_name),
    handle_name_(prefix_name_ + "/" + interface_name_),
    value_ptr_(value_ptr)
  {
  }

  explicit Handle(
    const std::string & prefix_name, const std::string & interface_name,
    const std::string & data_type = "double", const std::string & initial_value = "")
  : prefix_name_(prefix_name),
    interface_name_(interface_name),
    handle_name_(prefix_name_ + "/" + interface_name_),
    data_type_(data_type)
  {
    try {
      init_value(initial_value);
    } catch (const std::invalid_argument &) {
      throw std::invalid_argument(
              "Invalid initial value: '" + initial_value + "' parsed for interface: '" +
              handle_name_ + "' with type: '" + data_type_.to_string() + "'");
    }
  }

  explicit Handle(const InterfaceDescription & interface_description)
  : Handle(
      interface_description.get_prefix_name(), interface_description.get_interface_name(),
      interface_description.get_data_type_string(),
      interface_description.interface_info.initial_value)
  {
  }

  [[deprecated("Use InterfaceDescription for initializing the Interface")]]
  explicit Handle(const std::string & interface_name)
  : interface_name_(interface_name), handle_name_("/" + interface_name_), value_ptr_(nullptr)
  {
  }

  [[deprecated("Use InterfaceDescription for initializing the Interface")]]
  explicit Handle(const char * interface_name)
  : interface_name_(interface_name), handle_name_("/" + interface_name_), value_ptr_(nullptr)
  {
  }

  Handle(const Handle & other) noexcept {copy(other);}

  Handle & operator=(const Handle & other)
  {
    if (this != &other) {
      copy(other);
    }
    return *this;
  }

  Handle(Handle && other) noexcept {swap(*this, other);}

  Handle & operator=(Handle && other)
  {
    swap(*this, other);
    return *this;
  }

  virtual ~Handle() = default;

  /// True if the handle references a double (the deprecated raw-pointer form or a double value).
  inline operator bool() const {return value_ptr_ != nullptr;}

  const std::string & get_name() const {return handle_name_;}

  const std::string & get_interface_name() const {return interface_name_;}

#if RHI_FAKE_HI_MAJOR < 5
  [[deprecated("Replaced by get_name method, which is semantically more correct")]]
  const std::string & get_full_name() const {return get_name();}
#endif

  const std::string & get_prefix_name() const {return prefix_name_;}

#if RHI_FAKE_HI_MAJOR < 5
  /// NaN while another thread holds the lock; throws on a handle without a double.
  [[deprecated(
    "Use std::optional<T> get_optional() instead to retrieve the value. This method will be "
    "removed by the ROS 2 Kilted Kaiju release.")]]
  double get_value() const
  {
    std::shared_lock<std::shared_mutex> lock(handle_mutex_, std::try_to_lock);
    if (!lock.owns_lock()) {
      return std::numeric_limits<double>::quiet_NaN();
    }
    THROW_ON_NULLPTR(value_ptr_);
    return *value_ptr_;
  }
#endif

  /// The value, or std::nullopt when the lock is held by another thread (never blocks).
  template<typename T = double>
  [[nodiscard]] std::optional<T> get_optional() const
  {
    std::shared_lock<std::shared_mutex> lock(handle_mutex_, std::try_to_lock);
    return get_optional<T>(lock);
  }

  template<typename T = double>
  [[nodiscard]] std::optional<T> get_optional(std::shared_lock<std::shared_mutex> & lock) const
  {
    if (!lock.owns_lock()) {
      return std::nullopt;
    }
    if constexpr (std::is_same_v<T, double>) {
      return as_double();
    } else {
      return typed<T>();
    }
  }

#if RHI_FAKE_HI_MAJOR < 5
  template<typename T>
  [[deprecated(
    "Use std::optional<T> get_optional() instead to retrieve the value. This method will be "
    "removed by the ROS 2 Kilted Kaiju release.")]] [[nodiscard]] bool
  get_value(T & value) const
  {
    std::shared_lock<std::shared_mutex> lock(handle_mutex_, std::try_to_lock);
    if (!lock.owns_lock()) {
      return false;
    }
    if constexpr (std::is_same_v<T, double>) {
      THROW_ON_NULLPTR(value_ptr_);
      value = *value_ptr_;
    } else {
      value = typed<T>();
    }
    return true;
  }
#endif

  /// Reads into `value`; with wait_for_lock the call blocks until the lock is free.
  template<
    typename T, typename = std::enable_if_t<
      !std::is_same_v<std::decay_t<T>, std::shared_lock<std::shared_mutex>>>>
  [[nodiscard]] bool get_value(T & value, bool wait_for_lock) const
  {
    if (wait_for_lock) {
      std::shared_lock<std::shared_mutex> lock(handle_mutex_);
      return get_value(lock, value);
    }
    std::shared_lock<std::shared_mutex> lock(handle_mutex_, std::try_to_lock);
    return get_value(lock, value);
  }

  template<typename T>
  [[nodiscard]] bool set_value(const T & value, bool wait_for_lock)
  {
    if (wait_for_lock) {
      std::unique_lock<std::shared_mutex> lock(handle_mutex_);
      return set_value(lock, value);
    }
    std::unique_lock<std::shared_mutex> lock(handle_mutex_, std::try_to_lock);
    return set_value(lock, value);
  }

  /// Writes `value`; false (nothing written) while another thread holds the lock.
  template<typename T>
  [[nodiscard]] bool set_value(const T & value)
  {
    std::unique_lock<std::shared_mutex> lock(handle_mutex_, std::try_to_lock);
    return set_value(lock, value);
  }

  template<typename T>
  [[nodiscard]] bool set_value(std::unique_lock<std::shared_mutex> & lock, const T & value)
  {
    if (!lock.owns_lock()) {
      return false;
    }
    if constexpr (std::is_same_v<T, double>) {
      THROW_ON_NULLPTR(value_ptr_);
      *value_ptr_ = value;
    } else {
      // Like upstream: T must be one of HANDLE_DATATYPE's types (int64_t does not compile).
      if (!std::holds_alternative<T>(value_)) {
        throw std::runtime_error(
                "Invalid data type access for interface: " + get_name() + " expected: '" +
                data_type_.to_string() + "'");
      }
      value_ = value;
    }
    return true;
  }

  std::shared_mutex & get_mutex() const {return handle_mutex_;}

  HandleDataType get_data_type() const {return data_type_;}

  bool is_castable_to_double() const {return data_type_.is_castable_to_double();}

  bool is_valid() const
  {
    return (value_ptr_ != nullptr) || !std::holds_alternative<std::monostate>(value_);
  }

protected:
  template<typename T>
  [[nodiscard]] bool get_value(std::shared_lock<std::shared_mutex> & lock, T & value) const
  {
    if (!lock.owns_lock()) {
      return false;
    }
    if constexpr (std::is_same_v<T, double>) {
      value = as_double();
    } else {
      value = typed<T>();
    }
    return true;
  }

  std::string prefix_name_;
  std::string interface_name_;
  std::string handle_name_;
  HANDLE_DATATYPE value_ = std::monostate{};
  HandleDataType data_type_ = HandleDataType::DOUBLE;
  double * value_ptr_ = nullptr;  // own double (value_) or, deprecated, the caller's
  mutable std::shared_mutex handle_mutex_;

private:
  void init_value(const std::string & initial)
  {
    const bool none = initial.empty();
    switch (data_type_) {
      case HandleDataType::DOUBLE:
        value_ = none ? std::numeric_limits<double>::quiet_NaN() : hardware_interface::stod(initial);
        value_ptr_ = std::get_if<double>(&value_);
        return;
      case HandleDataType::FLOAT32:
        value_ = none ? std::numeric_limits<float>::quiet_NaN() :
          static_cast<float>(hardware_interface::stod(initial));
        return;
      case HandleDataType::BOOL:
        value_ = none ? false : hardware_interface::parse_bool(initial);
        return;
      case HandleDataType::UINT8: init_integer<uint8_t>(initial); return;
      case HandleDataType::INT8: init_integer<int8_t>(initial); return;
      case HandleDataType::UINT16: init_integer<uint16_t>(initial); return;
      case HandleDataType::INT16: init_integer<int16_t>(initial); return;
      case HandleDataType::UINT32: init_integer<uint32_t>(initial); return;
      case HandleDataType::INT32: init_integer<int32_t>(initial); return;
      default:
        throw std::runtime_error(
                "Invalid data type: '" + data_type_.to_string() + "' for interface: " +
                handle_name_ + ". Check supported types.");
    }
  }

  // Integers start at their maximum without an initial value (as upstream).
  template<typename IntT>
  void init_integer(const std::string & initial)
  {
    if (initial.empty()) {
      value_ = std::numeric_limits<IntT>::max();
      return;
    }
    const double parsed = hardware_interface::stod(initial);
    if (parsed != static_cast<double>(static_cast<long long>(parsed)) ||  // NOLINT(runtime/int)
      parsed < static_cast<double>(std::numeric_limits<IntT>::min()) ||
      parsed > static_cast<double>(std::numeric_limits<IntT>::max()))
    {
      throw std::invalid_argument("out of range");
    }
    value_ = static_cast<IntT>(parsed);
  }

  double as_double() const
  {
    switch (data_type_) {
      case HandleDataType::DOUBLE:
        THROW_ON_NULLPTR(value_ptr_);
        return *value_ptr_;
#if RHI_FAKE_HI_MAJOR >= 5
      case HandleDataType::BOOL:
        if (!notified_.exchange(true)) {
          RCLCPP_WARN(
            rclcpp::get_logger(get_name()),
            "Casting bool to double for interface: %s. Better use get_optional<bool>().",
            get_name().c_str());
        }
        return static_cast<double>(std::get<bool>(value_));
#endif
      default:
        throw std::runtime_error(
                "Data type: '" + data_type_.to_string() + "' will not be casted to double for "
                "interface: " + get_name() + ". Use get_optional<" + data_type_.to_string() +
                ">() instead.");
    }
  }

  template<typename T>
  T typed() const
  {
    if (const T * v = std::get_if<T>(&value_)) {
      return *v;
    }
    throw std::runtime_error(
            "Invalid data type access for interface: " + get_name() + " expected: '" +
            data_type_.to_string() + "'");
  }

  void copy(const Handle & other) noexcept
  {
    std::scoped_lock lock(other.handle_mutex_, handle_mutex_);
    prefix_name_ = other.prefix_name_;
    interface_name_ = other.interface_name_;
    handle_name_ = other.handle_name_;
    value_ = other.value_;
    data_type_ = other.data_type_;
    value_ptr_ = std::holds_alternative<std::monostate>(value_) ? other.value_ptr_ :
      std::get_if<double>(&value_);
  }

  static void swap(Handle & first, Handle & second) noexcept
  {
    std::scoped_lock lock(first.handle_mutex_, second.handle_mutex_);
    std::swap(first.prefix_name_, second.prefix_name_);
    std::swap(first.interface_name_, second.interface_name_);
    std::swap(first.handle_name_, second.handle_name_);
    std::swap(first.value_, second.value_);
    std::swap(first.data_type_, second.data_type_);
    std::swap(first.value_ptr_, second.value_ptr_);
    // Upstream swaps value_ptr_ as is, leaving a moved handle pointing into the other one's
    // variant; the stand-in re-points own doubles so a moved handle stays valid.
    for (Handle * h : {&first, &second}) {
      if (!std::holds_alternative<std::monostate>(h->value_)) {
        h->value_ptr_ = std::get_if<double>(&h->value_);
      }
    }
  }

#if RHI_FAKE_HI_MAJOR >= 5
  mutable std::atomic<bool> notified_{false};
#endif
};

class StateInterface : public Handle
{
public:
  explicit StateInterface(const InterfaceDescription & interface_description)
  : Handle(interface_description)
  {
  }

  StateInterface(const StateInterface & other) = default;

  StateInterface(StateInterface && other) = default;

#if RHI_FAKE_HI_MAJOR < 5
  // 4.x silences the deprecation here (so emplace_back(prefix, name, &value) into a vector does
  // not warn; constructing one directly does); 5.x+ does not.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
  using Handle::Handle;
#pragma GCC diagnostic pop
#else
  using Handle::Handle;
#endif

  using SharedPtr = std::shared_ptr<StateInterface>;
  using ConstSharedPtr = std::shared_ptr<const StateInterface>;
};

class CommandInterface : public Handle
{
public:
  explicit CommandInterface(const InterfaceDescription & interface_description)
  : Handle(interface_description)
  {
  }

  /// Command interfaces have a unique owner: no copies.
  CommandInterface(const CommandInterface & other) = delete;

  CommandInterface(CommandInterface && other) = default;

  void set_on_set_command_limiter(std::function<double(double, bool &)> on_set_command_limiter)
  {
    on_set_command_limiter_ = on_set_command_limiter;
  }

  /// set_value() through the limiter the framework installed (identity by default).
  template<typename T>
  [[nodiscard]] bool set_limited_value(const T & value)
  {
    if constexpr (std::is_same_v<T, double>) {
      return set_value(on_set_command_limiter_(value, is_command_limited_));
    } else {
      return set_value(value);
    }
  }

  const bool & is_limited() const {return is_command_limited_;}

#if RHI_FAKE_HI_MAJOR < 5
  // 4.x silences the deprecation here (so emplace_back(prefix, name, &value) into a vector does
  // not warn; constructing one directly does); 5.x+ does not.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
  using Handle::Handle;
#pragma GCC diagnostic pop
#else
  using Handle::Handle;
#endif

  using SharedPtr = std::shared_ptr<CommandInterface>;

private:
  bool is_command_limited_ = false;
  std::function<double(double, bool &)> on_set_command_limiter_ =
    [](double value, bool & is_limited) {
      is_limited = false;
      return value;
    };
};

}  // namespace hardware_interface

#endif  // HARDWARE_INTERFACE__HANDLE_HPP_
