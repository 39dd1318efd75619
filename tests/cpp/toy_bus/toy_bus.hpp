// A toy motor bus, in-process: the "vendor SDK" of the custom transport's worked example (README,
// "Bring your own SDK"). The driver side (the user regions of a custom robot's source file) opens
// the bus, subscribes a state and an IMU handler and sends command frames; the robot side (the
// tests' fake robot, tests/cpp/harness/transport_custom.hpp) delivers frames to the handlers and
// reads what was sent. One bus per process. Nothing here allocates after open().
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>

namespace toy_bus
{

constexpr size_t kMaxMotors = 64;

// One state frame of every motor of the bus.
struct StateFrame
{
  size_t motors{0};
  std::array<double, kMaxMotors> position{};
  std::array<double, kMaxMotors> velocity{};
  std::array<double, kMaxMotors> torque{};
};

struct ImuFrame
{
  std::array<double, 4> quaternion_wxyz{1.0, 0.0, 0.0, 0.0};
  std::array<double, 3> gyro{};
  std::array<double, 3> accel{};
};

// One command frame: a PD target with feed-forward torque per motor.
struct CommandFrame
{
  size_t motors{0};
  std::array<double, kMaxMotors> position{};
  std::array<double, kMaxMotors> velocity{};
  std::array<double, kMaxMotors> kp{};
  std::array<double, kMaxMotors> kd{};
  std::array<double, kMaxMotors> torque{};
};

class Bus
{
public:
  using StateHandler = void (*)(void * context, const StateFrame & frame);
  using ImuHandler = void (*)(void * context, const ImuFrame & frame);

  static Bus & instance()
  {
    static Bus bus;
    return bus;
  }

  // ---------------------------------------------------------------- driver side
  // Opens the bus on `interface` for `motors` motors; false when it is open already or too small.
  bool open(const std::string & interface, size_t motors)
  {
    std::lock_guard<std::mutex> lock(handler_mutex_);
    if (open_ || motors > kMaxMotors) {
      return false;
    }
    open_ = true;
    interface_ = interface;
    motors_ = motors;
    return true;
  }

  // The handlers run on the thread that delivers frames (the robot side), one at a time.
  void subscribe(void * context, StateHandler on_state, ImuHandler on_imu)
  {
    std::lock_guard<std::mutex> lock(handler_mutex_);
    context_ = context;
    on_state_ = on_state;
    on_imu_ = on_imu;
  }

  // Copies the frame onto the wire: no allocation, a short lock.
  void send(const CommandFrame & frame)
  {
    std::lock_guard<std::mutex> lock(command_mutex_);
    last_command_ = frame;
    has_command_ = true;
    ++sent_;
  }

  // Unsubscribes and closes: once it returns, no handler runs.
  void close()
  {
    std::lock_guard<std::mutex> lock(handler_mutex_);
    context_ = nullptr;
    on_state_ = nullptr;
    on_imu_ = nullptr;
    open_ = false;
  }

  // ---------------------------------------------------------------- robot side (tests)
  // Delivers a frame to the subscribed handler; returns how many handlers ran (0 or 1).
  size_t deliverState(const StateFrame & frame)
  {
    std::lock_guard<std::mutex> lock(handler_mutex_);
    if (!open_ || on_state_ == nullptr) {
      return 0;
    }
    on_state_(context_, frame);
    return 1;
  }

  size_t deliverImu(const ImuFrame & frame)
  {
    std::lock_guard<std::mutex> lock(handler_mutex_);
    if (!open_ || on_imu_ == nullptr) {
      return 0;
    }
    on_imu_(context_, frame);
    return 1;
  }

  bool lastCommand(CommandFrame & out) const
  {
    std::lock_guard<std::mutex> lock(command_mutex_);
    if (!has_command_) {
      return false;
    }
    out = last_command_;
    return true;
  }

  uint64_t sentCount() const
  {
    std::lock_guard<std::mutex> lock(command_mutex_);
    return sent_;
  }

  std::string interface() const
  {
    std::lock_guard<std::mutex> lock(handler_mutex_);
    return interface_;
  }

  bool isOpen() const
  {
    std::lock_guard<std::mutex> lock(handler_mutex_);
    return open_;
  }

  // Between test scenarios: forget what was sent (the bus stays as open or closed as it is).
  void reset()
  {
    std::lock_guard<std::mutex> lock(command_mutex_);
    last_command_ = CommandFrame{};
    has_command_ = false;
    sent_ = 0;
  }

private:
  Bus() = default;

  mutable std::mutex handler_mutex_;  // held while a handler runs and while (un)subscribing
  bool open_{false};
  std::string interface_;
  size_t motors_{0};
  void * context_{nullptr};
  StateHandler on_state_{nullptr};
  ImuHandler on_imu_{nullptr};

  mutable std::mutex command_mutex_;
  CommandFrame last_command_{};
  bool has_command_{false};
  uint64_t sent_{0};
};

}  // namespace toy_bus
