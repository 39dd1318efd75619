// rhi-gen test stand-in (not the real ROS 2 code): hardware_interface handles as in Humble (2.x).
// StateInterface is copyable; CommandInterface is move-only (its copy constructor is deleted).
// Neither is assignable (the user-declared move constructor suppresses the assignments), so build
// vectors with emplace_back / push_back(std::move(...)).
#ifndef HARDWARE_INTERFACE__HANDLE_HPP_
#define HARDWARE_INTERFACE__HANDLE_HPP_

#include <string>
#include <utility>

#include "hardware_interface/macros.hpp"
#include "hardware_interface/visibility_control.h"

namespace hardware_interface
{

/// A handle used to get and set a value on a given interface.
class ReadOnlyHandle
{
public:
  ReadOnlyHandle(
    const std::string & prefix_name, const std::string & interface_name,
    double * value_ptr = nullptr)
  : prefix_name_(prefix_name), interface_name_(interface_name), value_ptr_(value_ptr)
  {
  }

  explicit ReadOnlyHandle(const std::string & interface_name)
  : interface_name_(interface_name), value_ptr_(nullptr)
  {
  }

  explicit ReadOnlyHandle(const char * interface_name)
  : interface_name_(interface_name), value_ptr_(nullptr)
  {
  }

  ReadOnlyHandle(const ReadOnlyHandle & other) = default;
  ReadOnlyHandle(ReadOnlyHandle && other) = default;
  ReadOnlyHandle & operator=(const ReadOnlyHandle & other) = default;
  ReadOnlyHandle & operator=(ReadOnlyHandle && other) = default;
  virtual ~ReadOnlyHandle() = default;

  /// Returns true if handle references a value.
  inline operator bool() const {return value_ptr_ != nullptr;}

  const std::string get_name() const {return prefix_name_ + "/" + interface_name_;}

  const std::string & get_interface_name() const {return interface_name_;}

  [[deprecated("Replaced by get_name method, which is semantically more correct")]]
  const std::string get_full_name() const
  {
    return get_name();
  }

  const std::string & get_prefix_name() const {return prefix_name_;}

  double get_value() const
  {
    THROW_ON_NULLPTR(value_ptr_);
    return *value_ptr_;
  }

protected:
  std::string prefix_name_;
  std::string interface_name_;
  double * value_ptr_;
};

class ReadWriteHandle : public ReadOnlyHandle
{
public:
  ReadWriteHandle(
    const std::string & prefix_name, const std::string & interface_name,
    double * value_ptr = nullptr)
  : ReadOnlyHandle(prefix_name, interface_name, value_ptr)
  {
  }

  explicit ReadWriteHandle(const std::string & interface_name)
  : ReadOnlyHandle(interface_name) {}

  explicit ReadWriteHandle(const char * interface_name)
  : ReadOnlyHandle(interface_name) {}

  ReadWriteHandle(const ReadWriteHandle & other) = default;
  ReadWriteHandle(ReadWriteHandle && other) = default;
  ReadWriteHandle & operator=(const ReadWriteHandle & other) = default;
  ReadWriteHandle & operator=(ReadWriteHandle && other) = default;
  virtual ~ReadWriteHandle() = default;

  void set_value(double value)
  {
    THROW_ON_NULLPTR(this->value_ptr_);
    *this->value_ptr_ = value;
  }
};

class StateInterface : public ReadOnlyHandle
{
public:
  StateInterface(const StateInterface & other) = default;

  StateInterface(StateInterface && other) = default;

  using ReadOnlyHandle::ReadOnlyHandle;
};

class CommandInterface : public ReadWriteHandle
{
public:
  /// CommandInterface copy constructor is actively deleted.
  /**
   * Command interfaces are having a unique ownership and thus
   * can't be copied in order to avoid simultaneous writes to
   * the same resource.
   */
  CommandInterface(const CommandInterface & other) = delete;

  CommandInterface(CommandInterface && other) = default;

  using ReadWriteHandle::ReadWriteHandle;
};

}  // namespace hardware_interface

#endif  // HARDWARE_INTERFACE__HANDLE_HPP_
