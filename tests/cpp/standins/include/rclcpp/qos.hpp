// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::QoS and presets (ROS 2 Humble API).
// As in rclcpp: QoS(size_t depth) is implicit (keep-last, reliable, volatile); the constructor from
// a QoSInitialization (KeepLast/KeepAll) is explicit, so `create_publisher<M>(t, rclcpp::KeepLast(1))`
// does not compile -- write `rclcpp::QoS(rclcpp::KeepLast(1))`. SensorDataQoS = keep last 5,
// best effort, volatile. ServicesQoS = keep last 10, reliable, volatile.
#ifndef RCLCPP__QOS_HPP_
#define RCLCPP__QOS_HPP_

#include <cstddef>

#include "rmw/qos_profiles.h"
#include "rmw/types.h"
#include "rclcpp/duration.hpp"
#include "rclcpp/visibility_control.hpp"

namespace rclcpp
{

enum class HistoryPolicy
{
  KeepLast = RMW_QOS_POLICY_HISTORY_KEEP_LAST,
  KeepAll = RMW_QOS_POLICY_HISTORY_KEEP_ALL,
  SystemDefault = RMW_QOS_POLICY_HISTORY_SYSTEM_DEFAULT,
  Unknown = RMW_QOS_POLICY_HISTORY_UNKNOWN,
};

enum class ReliabilityPolicy
{
  BestEffort = RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT,
  Reliable = RMW_QOS_POLICY_RELIABILITY_RELIABLE,
  SystemDefault = RMW_QOS_POLICY_RELIABILITY_SYSTEM_DEFAULT,
  Unknown = RMW_QOS_POLICY_RELIABILITY_UNKNOWN,
};

enum class DurabilityPolicy
{
  Volatile = RMW_QOS_POLICY_DURABILITY_VOLATILE,
  TransientLocal = RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL,
  SystemDefault = RMW_QOS_POLICY_DURABILITY_SYSTEM_DEFAULT,
  Unknown = RMW_QOS_POLICY_DURABILITY_UNKNOWN,
};

struct RCLCPP_PUBLIC QoSInitialization
{
  rmw_qos_history_policy_t history_policy;
  size_t depth;

  QoSInitialization(rmw_qos_history_policy_t history_policy_arg, size_t depth_arg)
  : history_policy(history_policy_arg), depth(depth_arg) {}

  static QoSInitialization from_rmw(const rmw_qos_profile_t & rmw_qos)
  {
    return QoSInitialization(rmw_qos.history, rmw_qos.depth);
  }
};

struct RCLCPP_PUBLIC KeepAll : public rclcpp::QoSInitialization
{
  KeepAll()
  : QoSInitialization(RMW_QOS_POLICY_HISTORY_KEEP_ALL, 0) {}
};

struct RCLCPP_PUBLIC KeepLast : public rclcpp::QoSInitialization
{
  explicit KeepLast(size_t history_depth)
  : QoSInitialization(RMW_QOS_POLICY_HISTORY_KEEP_LAST, history_depth) {}
};

class RCLCPP_PUBLIC QoS
{
public:
  explicit QoS(
    const QoSInitialization & qos_initialization,
    const rmw_qos_profile_t & initial_profile = rmw_qos_profile_default)
  : rmw_qos_profile_(initial_profile)
  {
    rmw_qos_profile_.history = qos_initialization.history_policy;
    rmw_qos_profile_.depth = qos_initialization.depth;
  }

  // implicit, as in rclcpp: `create_publisher<M>("t", 10)`
  QoS(size_t history_depth)  // NOLINT(runtime/explicit)
  : QoS(KeepLast(history_depth)) {}

  rmw_qos_profile_t & get_rmw_qos_profile() {return rmw_qos_profile_;}
  const rmw_qos_profile_t & get_rmw_qos_profile() const {return rmw_qos_profile_;}

  QoS & history(rmw_qos_history_policy_t history)
  {
    rmw_qos_profile_.history = history;
    return *this;
  }
  QoS & history(HistoryPolicy history)
  {
    return this->history(static_cast<rmw_qos_history_policy_t>(history));
  }
  QoS & keep_last(size_t depth)
  {
    rmw_qos_profile_.history = RMW_QOS_POLICY_HISTORY_KEEP_LAST;
    rmw_qos_profile_.depth = depth;
    return *this;
  }
  QoS & keep_all()
  {
    rmw_qos_profile_.history = RMW_QOS_POLICY_HISTORY_KEEP_ALL;
    rmw_qos_profile_.depth = 0;
    return *this;
  }
  QoS & reliability(rmw_qos_reliability_policy_t reliability)
  {
    rmw_qos_profile_.reliability = reliability;
    return *this;
  }
  QoS & reliability(ReliabilityPolicy reliability)
  {
    return this->reliability(static_cast<rmw_qos_reliability_policy_t>(reliability));
  }
  QoS & reliable() {return reliability(RMW_QOS_POLICY_RELIABILITY_RELIABLE);}
  QoS & best_effort() {return reliability(RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT);}
  QoS & durability(rmw_qos_durability_policy_t durability)
  {
    rmw_qos_profile_.durability = durability;
    return *this;
  }
  QoS & durability(DurabilityPolicy durability)
  {
    return this->durability(static_cast<rmw_qos_durability_policy_t>(durability));
  }
  QoS & durability_volatile() {return durability(RMW_QOS_POLICY_DURABILITY_VOLATILE);}
  QoS & transient_local() {return durability(RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL);}
  QoS & deadline(rmw_time_t deadline)
  {
    rmw_qos_profile_.deadline = deadline;
    return *this;
  }
  QoS & deadline(const rclcpp::Duration & deadline) {return this->deadline(deadline.to_rmw_time());}
  QoS & lifespan(rmw_time_t lifespan)
  {
    rmw_qos_profile_.lifespan = lifespan;
    return *this;
  }
  QoS & lifespan(const rclcpp::Duration & lifespan) {return this->lifespan(lifespan.to_rmw_time());}
  QoS & avoid_ros_namespace_conventions(bool avoid)
  {
    rmw_qos_profile_.avoid_ros_namespace_conventions = avoid;
    return *this;
  }

  HistoryPolicy history() const {return static_cast<HistoryPolicy>(rmw_qos_profile_.history);}
  size_t depth() const {return rmw_qos_profile_.depth;}
  ReliabilityPolicy reliability() const
  {
    return static_cast<ReliabilityPolicy>(rmw_qos_profile_.reliability);
  }
  DurabilityPolicy durability() const
  {
    return static_cast<DurabilityPolicy>(rmw_qos_profile_.durability);
  }

private:
  rmw_qos_profile_t rmw_qos_profile_;
};

inline bool operator==(const QoS & left, const QoS & right)
{
  const auto & l = left.get_rmw_qos_profile();
  const auto & r = right.get_rmw_qos_profile();
  return l.history == r.history && l.depth == r.depth && l.reliability == r.reliability &&
         l.durability == r.durability && l.deadline.sec == r.deadline.sec &&
         l.deadline.nsec == r.deadline.nsec && l.lifespan.sec == r.lifespan.sec &&
         l.lifespan.nsec == r.lifespan.nsec && l.liveliness == r.liveliness &&
         l.avoid_ros_namespace_conventions == r.avoid_ros_namespace_conventions;
}

inline bool operator!=(const QoS & left, const QoS & right) {return !(left == right);}

class RCLCPP_PUBLIC SensorDataQoS : public QoS
{
public:
  explicit SensorDataQoS(
    const QoSInitialization & qos_initialization = (
      QoSInitialization::from_rmw(rmw_qos_profile_sensor_data)))
  : QoS(qos_initialization, rmw_qos_profile_sensor_data) {}
};

/// Keep last 10, reliable, volatile (rmw_qos_profile_services_default); every distro has it.
class RCLCPP_PUBLIC ServicesQoS : public QoS
{
public:
  explicit ServicesQoS(
    const QoSInitialization & qos_initialization = (
      QoSInitialization::from_rmw(rmw_qos_profile_services_default)))
  : QoS(qos_initialization, rmw_qos_profile_services_default) {}
};

class RCLCPP_PUBLIC SystemDefaultsQoS : public QoS
{
public:
  explicit SystemDefaultsQoS(
    const QoSInitialization & qos_initialization = (
      QoSInitialization::from_rmw(rmw_qos_profile_system_default)))
  : QoS(qos_initialization, rmw_qos_profile_system_default) {}
};

}  // namespace rclcpp

#endif  // RCLCPP__QOS_HPP_
