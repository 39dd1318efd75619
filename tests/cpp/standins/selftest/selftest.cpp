// Self-test of the rhi-gen C++ stand-ins and rhi_fake hooks (run by tests/cpp/test_standins.py).
// Exercises every stand-in header and every hook with the real ROS 2 message headers, counts heap
// allocations on the hot paths, and checks the SDK struct layouts. Exit code 0 = all checks passed.
// The rosidl-generated vendor messages are checked by selftest_vendor_msgs.cpp (AimDK's need ../shared:
// tests/support/vendor_msgs.py), so this one builds and runs the same with or without ../shared.

// ---- headers as a generated driver includes them (stand-ins and real messages) ----
#include <builtin_interfaces/msg/duration.hpp>
#include <builtin_interfaces/msg/time.hpp>
#include <geometry_msgs/msg/quaternion.hpp>
#include <geometry_msgs/msg/vector3.hpp>
#include <hardware_interface/handle.hpp>
#include <hardware_interface/hardware_info.hpp>
#include <hardware_interface/system_interface.hpp>
#include <hardware_interface/types/hardware_interface_return_values.hpp>
#include <hardware_interface/types/hardware_interface_type_values.hpp>
#include <hardware_interface/types/lifecycle_state_names.hpp>
#include <hardware_interface/version.h>
#include <hardware_interface/visibility_control.h>
#include <lifecycle_msgs/msg/state.hpp>
#include <lifecycle_msgs/srv/change_state.hpp>
#include <lifecycle_msgs/srv/get_state.hpp>
#include <pluginlib/class_list_macros.hpp>
#include <rclcpp/client.hpp>
#include <rclcpp/clock.hpp>
#include <rclcpp/duration.hpp>
#include <rclcpp/executors.hpp>
#include <rclcpp/executors/multi_threaded_executor.hpp>
#include <rclcpp/executors/single_threaded_executor.hpp>
#include <rclcpp/future_return_code.hpp>
#include <rclcpp/logging.hpp>
#include <rclcpp/macros.hpp>
#include <rclcpp/node.hpp>
#include <rclcpp/node_interfaces/node_parameters_interface.hpp>
#include <rclcpp/parameter.hpp>
#include <rclcpp/parameter_value.hpp>
#include <rclcpp/qos.hpp>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp/service.hpp>
#include <rclcpp/time.hpp>
#include <rclcpp_lifecycle/node_interfaces/lifecycle_node_interface.hpp>
#include <rclcpp_lifecycle/state.hpp>
#include <sensor_msgs/msg/imu.hpp>
#include <sensor_msgs/msg/joint_state.hpp>
#include <std_msgs/msg/header.hpp>
#include <unitree/common/thread/recurrent_thread.hpp>
#include <unitree/common/thread/thread.hpp>
#include <unitree/idl/hg/HandCmd_.hpp>
#include <unitree/idl/hg/HandState_.hpp>
#include <unitree/idl/hg/IMUState_.hpp>
#include <unitree/idl/hg/LowCmd_.hpp>
#include <unitree/idl/hg/LowState_.hpp>
#include <unitree/idl/hg/MotorCmd_.hpp>
#include <unitree/idl/hg/MotorState_.hpp>
#include <unitree/idl/hg/PressSensorState_.hpp>
#include <unitree/idl/go2/BmsCmd_.hpp>
#include <unitree/idl/go2/BmsState_.hpp>
#include <unitree/idl/go2/IMUState_.hpp>
#include <unitree/idl/go2/LowCmd_.hpp>
#include <unitree/idl/go2/LowState_.hpp>
#include <unitree/idl/go2/MotorCmd_.hpp>
#include <unitree/idl/go2/MotorState_.hpp>
#include <unitree/robot/b2/motion_switcher/motion_switcher_client.hpp>
#include <unitree/robot/channel/channel_factory.hpp>
#include <unitree/robot/channel/channel_publisher.hpp>
#include <unitree/robot/channel/channel_subscriber.hpp>

// ---- test hooks ----
#include "rhi_fake/all.hpp"
#include "rhi_fake/hw.hpp"

#include "selftest_support.hpp"

// ============================================================== hardware_interface (per distro)
#if HARDWARE_INTERFACE_VERSION_MAJOR < 3
#include "hi_humble.inc"
#else
#include "hi_since_jazzy.inc"
#endif

// ============================================================== messages
static void test_messages()
{
  geometry_msgs::msg::Quaternion q;
  CHECK(q.x == 0.0 && q.y == 0.0 && q.z == 0.0 && q.w == 1.0);
  sensor_msgs::msg::Imu imu;
  static_assert(std::is_same<decltype(imu.orientation_covariance), std::array<double, 9>>::value, "cov");
  static_assert(std::is_same<decltype(imu.angular_velocity_covariance), std::array<double, 9>>::value, "cov");
  static_assert(std::is_same<decltype(imu.linear_acceleration_covariance), std::array<double, 9>>::value, "cov");
  CHECK(imu.orientation.w == 1.0 && imu.orientation_covariance[8] == 0.0);
  imu.header.frame_id = "imu_link";
  imu.header.stamp.sec = 3;
  sensor_msgs::msg::Imu::SharedPtr imu_ptr = std::make_shared<sensor_msgs::msg::Imu>(imu);
  sensor_msgs::msg::Imu::ConstSharedPtr imu_cptr = imu_ptr;
  CHECK(*imu_cptr == imu);
  imu_ptr->linear_acceleration.z = 9.81;
  CHECK(*imu_cptr != imu);
  sensor_msgs::msg::JointState js;
  js.name = {"a"};
  js.position = {1.0};
  CHECK(js.velocity.empty() && js.effort.empty());
  std_msgs::msg::Header h;
  builtin_interfaces::msg::Time t;
  builtin_interfaces::msg::Duration d;
  CHECK(h.stamp.sec == 0 && t.nanosec == 0u && d.sec == 0);

  static_assert(lifecycle_msgs::msg::State::PRIMARY_STATE_INACTIVE == 2, "INACTIVE");
  CHECK(std::string(rosidl_generator_traits::name<sensor_msgs::msg::Imu>()) == "sensor_msgs/msg/Imu");
  CHECK(std::string(rosidl_generator_traits::data_type<sensor_msgs::msg::JointState>()) ==
    "sensor_msgs::msg::JointState");
  static_assert(rosidl_generator_traits::is_message<std_msgs::msg::Header>::value, "msg");
  static_assert(!rosidl_generator_traits::is_message<int>::value, "not msg");
  static_assert(!std::is_convertible<rosidl_runtime_cpp::MessageInitialization, sensor_msgs::msg::Imu>::value,
    "explicit ctor");
  sensor_msgs::msg::Imu skip(rosidl_runtime_cpp::MessageInitialization::SKIP);
  (void)skip;
  auto set_result = std::make_shared<std_msgs::msg::Header>();
  set_result->set__frame_id("x");
  CHECK(set_result->frame_id == "x");
}

// ============================================================== time, duration, clock
static void test_time()
{
  rclcpp::Duration a(1, 500000000);
  CHECK(a.nanoseconds() == 1500000000LL);
  CHECK(std::fabs(a.seconds() - 1.5) < 1e-12);
  rclcpp::Duration b = std::chrono::milliseconds(2);
  CHECK(b.nanoseconds() == 2000000);
  CHECK(rclcpp::Duration::from_seconds(0.25).nanoseconds() == 250000000);
  CHECK(rclcpp::Duration::from_nanoseconds(7).nanoseconds() == 7);
  CHECK((a + b).nanoseconds() == 1502000000LL && (a - a).nanoseconds() == 0 && b < a);
  CHECK((b * 2.0).nanoseconds() == 4000000);
  CHECK(a.to_chrono<std::chrono::milliseconds>().count() == 1500);
  builtin_interfaces::msg::Duration dmsg = a;
  CHECK(dmsg.sec == 1 && dmsg.nanosec == 500000000u);

  rclcpp::Time t0(5, 0);
  CHECK(t0.get_clock_type() == RCL_SYSTEM_TIME && t0.nanoseconds() == 5000000000LL);
  rclcpp::Time t1 = t0 + a;
  CHECK((t1 - t0).nanoseconds() == 1500000000LL);
  CHECK(t1 > t0 && t0 < t1 && !(t0 == t1));
  rclcpp::Time ros_t(1, 0, RCL_ROS_TIME);
  CHECK_THROWS(std::runtime_error, (void)(ros_t < t0));
  CHECK_THROWS(std::runtime_error, (void)(ros_t - t0));
  builtin_interfaces::msg::Time tmsg = t1;
  CHECK(tmsg.sec == 6 && tmsg.nanosec == 500000000u);
  rclcpp::Time from_msg(tmsg);
  CHECK(from_msg.get_clock_type() == RCL_ROS_TIME && from_msg.nanoseconds() == t1.nanoseconds());
  CHECK_THROWS(std::runtime_error, rclcpp::Time(-1, 0));

  rclcpp::Clock clock(RCL_ROS_TIME);
  CHECK(clock.now().get_clock_type() == RCL_ROS_TIME);
  CHECK(clock.now().nanoseconds() > 1600000000LL * 1000000000LL);   // system time, after 2020
  rhi_fake::ros::set_time(42);
  CHECK(clock.now().nanoseconds() == 42);
  rhi_fake::ros::advance_time(std::chrono::nanoseconds(8));
  CHECK(clock.now().nanoseconds() == 50);
  CHECK_NO_ALLOC("Clock::now", (void)clock.now());
  rhi_fake::ros::use_system_time();
  CHECK(clock.now().nanoseconds() > 50);
  CHECK_NO_ALLOC("Clock::now (system)", (void)clock.now());
}

// ============================================================== logging
static void test_logging(const rclcpp::Node::SharedPtr & node)
{
  rhi_fake::logs::clear();
  auto logger = node->get_logger();
  RCLCPP_DEBUG(logger, "debug %d", 1);
  RCLCPP_INFO(logger, "info %s", "two");
  RCLCPP_WARN(node->get_logger(), "warn %.1f", 3.0);
  RCLCPP_ERROR(rclcpp::get_logger("other"), "error");
  RCLCPP_FATAL(logger, "fatal %lu", 5ul);
  CHECK(rhi_fake::logs::count(rhi_fake::logs::Severity::Debug) == 1);
  CHECK(rhi_fake::logs::count(rhi_fake::logs::Severity::Info) == 1);
  CHECK(rhi_fake::logs::count(rhi_fake::logs::Severity::Warn) == 1);
  CHECK(rhi_fake::logs::count(rhi_fake::logs::Severity::Error) == 1);
  CHECK(rhi_fake::logs::count(rhi_fake::logs::Severity::Fatal) == 1);
  CHECK(rhi_fake::logs::count_all() == 5);
  CHECK(rhi_fake::logs::contains("info two"));
  CHECK(rhi_fake::logs::contains("warn 3.0", rhi_fake::logs::Severity::Warn));
  CHECK(!rhi_fake::logs::contains("debug 1", rhi_fake::logs::Severity::Info));
  auto lines = rhi_fake::logs::lines();
  CHECK(lines.size() == 5);
  CHECK(lines[3].logger == "other" && lines[3].text == "error" && lines[0].logger == node->get_name());
  CHECK(std::string(rhi_fake::logs::severity_name(lines[1].severity)) == "INFO");

  rhi_fake::logs::clear();
  for (int i = 0; i < 3; ++i) {
    RCLCPP_WARN_ONCE(logger, "once");
    RCLCPP_INFO_SKIPFIRST(logger, "skipfirst %d", i);
    RCLCPP_INFO_EXPRESSION(logger, i == 2, "expr %d", i);
  }
  CHECK(rhi_fake::logs::count_containing("once") == 1);
  CHECK(rhi_fake::logs::count_containing("skipfirst") == 2 && !rhi_fake::logs::contains("skipfirst 0"));
  CHECK(rhi_fake::logs::count_containing("expr") == 1 && rhi_fake::logs::contains("expr 2"));
  RCLCPP_ERROR_STREAM(logger, "stream " << 12 << "!");
  CHECK(rhi_fake::logs::contains("stream 12!", rhi_fake::logs::Severity::Error));

  // THROTTLE with a fake clock: takes the clock by reference, period in milliseconds
  rhi_fake::logs::clear();
  rhi_fake::ros::set_time(10LL * 1000000000LL);
  auto throttled = [&]() {RCLCPP_WARN_THROTTLE(logger, *node->get_clock(), 1000, "late by %d us", 7);};
  throttled();
  throttled();
  CHECK(rhi_fake::logs::count_containing("late by") == 1);
  rhi_fake::ros::advance_time(std::chrono::milliseconds(999));
  throttled();
  CHECK(rhi_fake::logs::count_containing("late by") == 1);
  rhi_fake::ros::advance_time(std::chrono::milliseconds(1));
  throttled();
  CHECK(rhi_fake::logs::count_containing("late by") == 2);
  rhi_fake::ros::use_system_time();

  // the printf-style macros never allocate
  rclcpp::Clock & clk = *node->get_clock();
  CHECK_NO_ALLOC("RCLCPP_WARN", RCLCPP_WARN(logger, "hot path %d %s", 1, "x"));
  CHECK_NO_ALLOC("RCLCPP_ERROR_THROTTLE", RCLCPP_ERROR_THROTTLE(logger, clk, 1000, "throttled %d", 2));
  CHECK_NO_ALLOC("RCLCPP_INFO_ONCE", RCLCPP_INFO_ONCE(logger, "once %d", 3));
  CHECK_NO_ALLOC("node->get_logger()", {auto l = node->get_logger(); (void)l;});
  CHECK_NO_ALLOC("RCLCPP_WARN_THROTTLE(node->get_logger(), *node->get_clock(), ...)",
    RCLCPP_WARN_THROTTLE(node->get_logger(), *node->get_clock(), 500, "x=%f", 1.0));
  CHECK_NO_ALLOC("node->now()", (void)node->now());

  // long lines are truncated, the ring keeps the newest lines
  std::string long_text(2000, 'x');
  RCLCPP_INFO(logger, "%s", long_text.c_str());
  CHECK(rhi_fake::logs::lines().back().truncated);
  for (int i = 0; i < 1500; ++i) {RCLCPP_DEBUG(logger, "spam %d", i);}
  auto ring = rhi_fake::logs::lines();
  CHECK(ring.size() == rhi_fake::detail::kLogRingSize && ring.back().text == "spam 1499");
  CHECK(rhi_fake::logs::wait_for("spam 1499", std::chrono::milliseconds(10)));
  rhi_fake::logs::clear();
  CHECK(rhi_fake::logs::count_all() == 0 && rhi_fake::logs::lines().empty());
}

// ============================================================== rclcpp graph, pub/sub, timers
struct CallbackCounters
{
  std::atomic<int> const_ref{0};
  std::atomic<int> by_value{0};
  std::atomic<int> shared_const{0};
  std::atomic<int> ref_shared_const{0};
  std::atomic<int> unique{0};
  std::atomic<int> bound{0};
  std::atomic<int> timer{0};
  std::atomic<int> timer_ref{0};
  double last_z = 0.0;
  std::shared_ptr<const sensor_msgs::msg::Imu> kept;
};

class BoundHandler
{
public:
  explicit BoundHandler(CallbackCounters & c)
  : c_(c) {}
  void on_state(const sensor_msgs::msg::JointState & msg) {c_.bound += static_cast<int>(msg.position.size());}
  void on_timer() {c_.timer++;}

private:
  CallbackCounters & c_;
};

static void test_rclcpp()
{
  CHECK(!rclcpp::ok());
  CHECK_THROWS(rclcpp::exceptions::RCLError, rclcpp::Node("too_early"));
  rclcpp::init(0, nullptr);
  CHECK(rclcpp::ok());
  CHECK_THROWS(rclcpp::ContextAlreadyInitialized, rclcpp::init(0, nullptr));

  CHECK_THROWS(rclcpp::exceptions::InvalidNodeNameError, rclcpp::Node("bad-name"));
  CHECK_THROWS(rclcpp::exceptions::InvalidNodeNameError, rclcpp::Node("1abc"));
  auto node = std::make_shared<rclcpp::Node>("g1_hardware_interface");
  CHECK(std::string(node->get_name()) == "g1_hardware_interface");
  CHECK(std::string(node->get_namespace()) == "/");
  CHECK(std::string(node->get_fully_qualified_name()) == "/g1_hardware_interface");
  CHECK(std::string(node->get_logger().get_name()) == "g1_hardware_interface");
  CHECK(node->now().get_clock_type() == RCL_ROS_TIME);
  CHECK(node->get_clock()->get_clock_type() == RCL_ROS_TIME);

  test_logging(node);

  // ---- QoS ----
  rclcpp::QoS q3(3);
  q3.best_effort().durability_volatile();
  CHECK(q3.reliability() == rclcpp::ReliabilityPolicy::BestEffort);
  CHECK(q3.durability() == rclcpp::DurabilityPolicy::Volatile && q3.depth() == 3);
  rclcpp::SensorDataQoS sensor;
  CHECK(sensor.reliability() == rclcpp::ReliabilityPolicy::BestEffort && sensor.depth() == 5);
  rclcpp::QoS reliable_tl = rclcpp::QoS(rclcpp::KeepLast(1)).reliable().transient_local();
  CHECK(reliable_tl.durability() == rclcpp::DurabilityPolicy::TransientLocal);
  rclcpp::QoS ten = 10;
  CHECK(ten.reliability() == rclcpp::ReliabilityPolicy::Reliable && ten.history() == rclcpp::HistoryPolicy::KeepLast);
  CHECK(rclcpp::QoS(rclcpp::KeepAll()).history() == rclcpp::HistoryPolicy::KeepAll);
  CHECK(rclcpp::QoS(1).keep_last(4).depth() == 4 && rclcpp::QoS(1).keep_all().history() == rclcpp::HistoryPolicy::KeepAll);
  CHECK(rclcpp::SystemDefaultsQoS().reliability() == rclcpp::ReliabilityPolicy::SystemDefault);
  CHECK(sensor == rclcpp::SensorDataQoS() && sensor != ten);

  // ---- publishers ----
  auto cmd_pub = node->create_publisher<sensor_msgs::msg::JointState>("/hardware/joint_command", q3);
  auto rel_pub = node->create_publisher<std_msgs::msg::Header>("relative/topic", 10);
  auto priv_pub = node->create_publisher<std_msgs::msg::Header>("~/private", rclcpp::QoS(rclcpp::KeepLast(2)));
  CHECK(std::string(cmd_pub->get_topic_name()) == "/hardware/joint_command");
  CHECK(std::string(rel_pub->get_topic_name()) == "/relative/topic");
  CHECK(std::string(priv_pub->get_topic_name()) == "/g1_hardware_interface/private");
  CHECK_THROWS(rclcpp::exceptions::InvalidTopicNameError, node->create_publisher<std_msgs::msg::Header>("bad topic", 1));
  CHECK_THROWS(rclcpp::exceptions::InvalidTopicNameError, node->create_publisher<std_msgs::msg::Header>("a//b", 1));
  CHECK_THROWS(rclcpp::exceptions::InvalidTopicNameError, node->create_publisher<std_msgs::msg::Header>("/1a", 1));
  CHECK_THROWS(std::logic_error, node->create_publisher<sensor_msgs::msg::Imu>("relative/topic", 1));

  sensor_msgs::msg::JointState jc;
  for (int i = 0; i < 24; ++i) {jc.name.push_back("joint_with_a_long_name_" + std::to_string(i));}
  jc.position.assign(24, 0.5);
  jc.velocity.assign(24, 0.0);
  jc.effort.assign(24, 40.0);
  CHECK(rhi_fake::ros::publish_count("/hardware/joint_command") == 0);
  CHECK(!rhi_fake::ros::last_published<sensor_msgs::msg::JointState>("/hardware/joint_command"));
  cmd_pub->publish(jc);   // first publish sizes the retained message
  jc.position[3] = 1.5;
  CHECK_NO_ALLOC("Publisher::publish (warm)", cmd_pub->publish(jc));
  CHECK(rhi_fake::ros::publish_count("/hardware/joint_command") == 2);
  CHECK(rhi_fake::ros::publish_count("hardware/joint_command") == 2);
  auto last = rhi_fake::ros::last_published<sensor_msgs::msg::JointState>("/hardware/joint_command");
  CHECK(last && last->position[3] == 1.5 && last->effort[23] == 40.0 && last->name[23] == "joint_with_a_long_name_23");
  sensor_msgs::msg::JointState out;
  CHECK(rhi_fake::ros::last_published("/hardware/joint_command", out) && out == jc);
  CHECK_THROWS(std::logic_error, rhi_fake::ros::last_published<sensor_msgs::msg::Imu>("/hardware/joint_command"));
  cmd_pub->publish(std::make_unique<sensor_msgs::msg::JointState>(jc));
  CHECK(rhi_fake::ros::publish_count("/hardware/joint_command") == 3);
  CHECK(rhi_fake::ros::publish_count("/nowhere") == 0);

  // ---- subscriptions: every supported callback form ----
  CallbackCounters c;
  using Imu = sensor_msgs::msg::Imu;
  auto s1 = node->create_subscription<Imu>(
    "/aima/hal/imu/torso/state", rclcpp::SensorDataQoS(),
    [&c](const Imu & m) {c.const_ref++; c.last_z = m.linear_acceleration.z;});
  auto s2 = node->create_subscription<Imu>(
    "/aima/hal/imu/torso/state", rclcpp::SensorDataQoS(),
    [&c](Imu::ConstSharedPtr m) {c.shared_const++; (void)m;});
  auto s3 = node->create_subscription<Imu>(
    "/aima/hal/imu/torso/state", rclcpp::SensorDataQoS(),
    [&c](const std::shared_ptr<const Imu> & m) {c.ref_shared_const++; (void)m;});
  auto s4 = node->create_subscription<Imu>(
    "/aima/hal/imu/torso/state", rclcpp::SensorDataQoS(),
    [&c](std::unique_ptr<Imu> m) {c.unique++; (void)m;});
  std::function<void(Imu)> by_value = [&c](Imu m) {c.by_value++; (void)m;};
  auto s5 = node->create_subscription<Imu>("/aima/hal/imu/torso/state", rclcpp::SensorDataQoS(), by_value);
  rclcpp::Subscription<Imu>::SharedPtr s6 = node->create_subscription<Imu>(
    "/aima/hal/imu/torso/state", 1, [&c](Imu::ConstSharedPtr m) {c.kept = m;});
  BoundHandler handler(c);
  auto s7 = node->create_subscription<sensor_msgs::msg::JointState>(
    "/hardware/joint_state", q3, std::bind(&BoundHandler::on_state, &handler, std::placeholders::_1));
  CHECK(std::string(s1->get_topic_name()) == "/aima/hal/imu/torso/state");
  CHECK(s1->get_publisher_count() == 0 && cmd_pub->get_subscription_count() == 0);

  Imu imu;
  imu.linear_acceleration.z = 9.81;
  CHECK(rhi_fake::ros::deliver("/aima/hal/imu/torso/state", imu) == 6);
  CHECK(c.const_ref == 1 && c.shared_const == 1 && c.ref_shared_const == 1 && c.unique == 1 && c.by_value == 1);
  CHECK(c.last_z == 9.81 && c.kept && c.kept->linear_acceleration.z == 9.81);
  auto imu_ptr = std::make_shared<const Imu>(imu);
  CHECK(rhi_fake::ros::deliver("aima/hal/imu/torso/state", imu_ptr) == 6);
  CHECK(c.kept == imu_ptr);   // shared_ptr callbacks get the test's pointer itself
  CHECK(rhi_fake::ros::deliver("/no/subscribers", imu) == 0);
  CHECK(rhi_fake::ros::deliver<sensor_msgs::msg::JointState>("/aima/hal/imu/torso/state", sensor_msgs::msg::JointState()) == 0);
  s4.reset();   // unique_ptr callbacks allocate by design
  s5.reset();   // by-value callbacks copy the message
  s6.reset();   // drops c.kept's producer
  c.kept.reset();
  rhi_fake::ros::deliver("/aima/hal/imu/torso/state", imu);   // warm the pooled shared_ptr
  CHECK_NO_ALLOC("deliver const& to const-ref + shared-const-ptr callbacks (warm)",
    rhi_fake::ros::deliver("/aima/hal/imu/torso/state", imu));
  CHECK_NO_ALLOC("deliver shared_ptr<const Imu>", rhi_fake::ros::deliver("/aima/hal/imu/torso/state", imu_ptr));

  sensor_msgs::msg::JointState js;
  js.position.assign(24, 0.0);
  CHECK(rhi_fake::ros::deliver("/hardware/joint_state", js) == 1 && c.bound == 24);
  CHECK_NO_ALLOC("deliver to std::bind member callback", rhi_fake::ros::deliver("/hardware/joint_state", js));

  // ---- graph / QoS report ----
  auto info = rhi_fake::ros::topic("/hardware/joint_command");
  CHECK(info && info->publishers.size() == 1 && info->subscriptions.empty());
  CHECK(info && info->publishers[0].reliability == rclcpp::ReliabilityPolicy::BestEffort);
  CHECK(info && info->publishers[0].durability == rclcpp::DurabilityPolicy::Volatile);
  CHECK(info && info->publishers[0].depth == 3 && info->publishers[0].history == rclcpp::HistoryPolicy::KeepLast);
  CHECK(info && info->publishers[0].node == "/g1_hardware_interface");
  CHECK(info && info->publishers[0].type_name == "sensor_msgs/msg/JointState");
  CHECK(info && info->publish_count == 3);
  auto imu_topic = rhi_fake::ros::topic("/aima/hal/imu/torso/state");
  CHECK(imu_topic && imu_topic->subscriptions.size() == 3 && imu_topic->publishers.empty());
  CHECK(imu_topic && imu_topic->subscriptions[0].depth == 5);
  CHECK(std::string(rhi_fake::ros::to_string(imu_topic->subscriptions[0].reliability)) == "best_effort");
  CHECK(std::string(rhi_fake::ros::to_string(rclcpp::DurabilityPolicy::TransientLocal)) == "transient_local");
  CHECK(std::string(rhi_fake::ros::to_string(rclcpp::HistoryPolicy::KeepAll)) == "keep_all");
  CHECK(rhi_fake::ros::topics().size() >= 5);
  CHECK(!rhi_fake::ros::topic("/nope"));
  CHECK(rel_pub->get_actual_qos().depth() == 10);
  auto state_sub_pub = node->create_publisher<sensor_msgs::msg::JointState>("/hardware/joint_state", 1);
  CHECK(s7->get_publisher_count() == 1 && state_sub_pub->get_subscription_count() == 1);

  // ---- timers ----
  auto timer = node->create_wall_timer(std::chrono::microseconds(2000), [&c]() {c.timer++;});
  rclcpp::TimerBase::SharedPtr timer2 = node->create_wall_timer(
    std::chrono::milliseconds(5), [&c](rclcpp::TimerBase & t) {c.timer_ref++; (void)t.is_canceled();});
  auto timer3 = node->create_wall_timer(std::chrono::seconds(1), std::bind(&BoundHandler::on_timer, &handler));
  auto periods = rhi_fake::ros::timer_periods();
  CHECK(periods.size() == 3 && periods[0] == std::chrono::microseconds(2000) && periods[1] == std::chrono::milliseconds(5));
  CHECK(rhi_fake::ros::fire_timers() == 3 && c.timer == 2 && c.timer_ref == 1);
  timer3->cancel();
  CHECK(timer3->is_canceled());
  CHECK(rhi_fake::ros::fire_timers() == 2 && c.timer == 3);
  CHECK_NO_ALLOC("fire_timers", rhi_fake::ros::fire_timers());
  timer3->reset();
  CHECK(!timer3->is_canceled() && rhi_fake::ros::timer_periods().size() == 3);
  timer3.reset();
  CHECK(rhi_fake::ros::timer_periods().size() == 2);
  CHECK_THROWS(std::invalid_argument, node->create_wall_timer(std::chrono::milliseconds(-1), []() {}));
  timer->execute_callback();
  CHECK(c.timer == 5);

  // ---- executor: spin blocks until cancel; real-time timers; Humble edge cases ----
  auto exec = std::make_shared<rclcpp::executors::SingleThreadedExecutor>();
  exec->add_node(node);
  CHECK_THROWS(std::runtime_error, exec->add_node(node));
  rclcpp::executors::SingleThreadedExecutor other;
  CHECK_THROWS(std::runtime_error, other.add_node(node));
  CHECK_THROWS(std::runtime_error, other.remove_node(node));
  CHECK(rhi_fake::ros::spinning_executors() == 0 && !rhi_fake::ros::is_spinning(*exec));
  std::atomic<bool> spin_returned{false};
  std::thread spinner([&]() {exec->spin(); spin_returned = true;});
  CHECK(rhi_fake::ros::wait_spinning_executors(1, std::chrono::milliseconds(10000)));
  CHECK(rhi_fake::ros::is_spinning(*exec));
  CHECK_THROWS(std::runtime_error, exec->spin());
  int before = c.timer.load();
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  CHECK(c.timer.load() == before);   // no real-time firing by default
  CHECK(!spin_returned);
  rhi_fake::ros::set_realtime_timers(true);
  CHECK(rhi_fake::ros::realtime_timers());
  CHECK(eventually([&]() {return c.timer.load() >= before + 5;}));
  // deliveries from the test thread interleave safely with timer callbacks on the spin thread
  for (int i = 0; i < 200; ++i) {rhi_fake::ros::deliver("/hardware/joint_state", js);}
  rhi_fake::ros::set_realtime_timers(false);
  CHECK(stop_spinning(*exec, spin_returned));
  spinner.join();
  CHECK(spin_returned && !rhi_fake::ros::is_spinning(*exec));
  CHECK(rhi_fake::ros::wait_spinning_executors(0, std::chrono::milliseconds(100)));

  // a cancel() issued before spin() starts is lost (Humble semantics)
  exec->cancel();
  spin_returned = false;
  std::thread late([&]() {exec->spin(); spin_returned = true;});
  CHECK(rhi_fake::ros::wait_spinning_executors(1, std::chrono::milliseconds(10000)));
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  CHECK(!spin_returned);
  CHECK(stop_spinning(*exec, spin_returned));
  late.join();
  CHECK(spin_returned);

  // spin_some does not block
  exec->spin_some();
  exec->remove_node(node);
  exec->add_node(node->get_node_base_interface());
  exec->remove_node(node->get_node_base_interface());

  // MultiThreadedExecutor: same contract; rclcpp::shutdown() ends spin()
  rclcpp::executors::MultiThreadedExecutor mt(rclcpp::ExecutorOptions(), 2);
  CHECK(mt.get_number_of_threads() == 2);
  mt.add_node(node);
  std::thread mt_spinner([&]() {mt.spin();});
  CHECK(rhi_fake::ros::wait_spinning_executors(1, std::chrono::milliseconds(10000)));
  CHECK(rclcpp::shutdown());
  mt_spinner.join();
  CHECK(!rclcpp::ok() && !rclcpp::shutdown());
  mt.remove_node(node);
  rclcpp::init(0, nullptr);   // init again after shutdown works, as in rclcpp

  // executor destruction releases its nodes
  {
    rclcpp::executors::SingleThreadedExecutor tmp;
    tmp.add_node(node);
  }
  exec->add_node(node);
  exec->remove_node(node);

  // rclcpp::spin(node) on a helper thread, ended by shutdown
  std::thread free_spin([&]() {rclcpp::spin(node);});
  CHECK(rhi_fake::ros::wait_spinning_executors(1, std::chrono::milliseconds(10000)));
  rclcpp::shutdown();
  free_spin.join();
  rclcpp::init(0, nullptr);
}

// ============================================================== thread-safety smoke (for TSan)
static void test_parameters()
{
  auto node = std::make_shared<rclcpp::Node>("parameters_node");
  CHECK(node->declare_parameter<std::string>("fault", "") == "");
  CHECK(node->declare_parameter<int64_t>("count", 3) == 3);
  CHECK_THROWS(rclcpp::exceptions::ParameterAlreadyDeclaredException,
    node->declare_parameter<std::string>("fault", "x"));
  CHECK_THROWS(rclcpp::exceptions::ParameterNotDeclaredException, node->get_parameter("nope"));
  CHECK_THROWS(rclcpp::ParameterTypeException, node->get_parameter("count").as_string());
  std::vector<std::string> seen;
  auto first = node->add_on_set_parameters_callback(
    [&seen](const std::vector<rclcpp::Parameter> & ps) {
      seen.push_back("first:" + ps.at(0).get_name());
      rcl_interfaces::msg::SetParametersResult r;
      r.successful = ps.at(0).get_name() != "fault" || ps.at(0).as_string() != "bad";
      r.reason = r.successful ? "" : "bad request";
      return r;
    });
  auto second = node->add_on_set_parameters_callback(
    [&seen](const std::vector<rclcpp::Parameter> & ps) {
      seen.push_back("second:" + ps.at(0).get_name());
      rcl_interfaces::msg::SetParametersResult r;
      r.successful = true;
      return r;
    });
  auto ok = node->set_parameter(rclcpp::Parameter("fault", "silent"));
  CHECK(ok.successful && node->get_parameter("fault").as_string() == "silent");
  CHECK(seen.size() == 2 && seen[0] == "second:fault" && seen[1] == "first:fault");  // newest first
  auto refused = node->set_parameter(rclcpp::Parameter("fault", "bad"));
  CHECK(!refused.successful && refused.reason == "bad request");
  CHECK(node->get_parameter("fault").as_string() == "silent");  // a refused value is not stored
  auto typed = node->set_parameter(rclcpp::Parameter("fault", 5));
  CHECK(!typed.successful && typed.reason.find("Wrong parameter type") != std::string::npos);
  first.reset();  // a dropped handle removes its callback
  seen.clear();
  CHECK(node->set_parameter(rclcpp::Parameter("fault", "bad")).successful && seen.size() == 1);
  CHECK_THROWS(rclcpp::exceptions::InvalidParameterValueException, [&node]() {
    auto refuse = node->add_on_set_parameters_callback([](const std::vector<rclcpp::Parameter> &) {
        rcl_interfaces::msg::SetParametersResult r;
        r.successful = false;
        return r;
      });
    node->declare_parameter<bool>("flag", false);
  }());
}

static void test_concurrency()
{
  auto node = std::make_shared<rclcpp::Node>("concurrency_node", "/ns");
  CHECK(std::string(node->get_fully_qualified_name()) == "/ns/concurrency_node");
  CHECK(std::string(node->get_logger().get_name()) == "ns.concurrency_node");
  auto pub = node->create_publisher<sensor_msgs::msg::JointState>("state_out", 1);
  CHECK(std::string(pub->get_topic_name()) == "/ns/state_out");
  std::atomic<long> received{0};
  long unguarded = 0;   // only touched inside callbacks: the node mutex must serialize them
  auto sub = node->create_subscription<sensor_msgs::msg::JointState>(
    "/ns/state_in", 10, [&](const sensor_msgs::msg::JointState & m) {received += static_cast<long>(m.position.size()); ++unguarded;});
  auto timer = node->create_wall_timer(std::chrono::microseconds(200), [&]() {++unguarded;});
  rclcpp::executors::SingleThreadedExecutor exec;
  exec.add_node(node);
  rhi_fake::ros::set_realtime_timers(true);
  std::atomic<bool> spin_returned{false};
  std::thread spinner([&]() {exec.spin(); spin_returned = true;});
  // A cancel() before spin() has started is lost (Humble semantics, kept by the stand-in): wait
  // until it spins. Under load the workers below can finish before the spinner is scheduled.
  CHECK(rhi_fake::ros::wait_spinning_executors(1, std::chrono::milliseconds(10000)));
  std::vector<std::thread> workers;
  for (int w = 0; w < 3; ++w) {
    workers.emplace_back([&, w]() {
        sensor_msgs::msg::JointState m;
        m.position.assign(3, static_cast<double>(w));
        for (int i = 0; i < 300; ++i) {
          rhi_fake::ros::deliver("/ns/state_in", m);
          pub->publish(m);
          RCLCPP_DEBUG(node->get_logger(), "worker %d iteration %d", w, i);
          (void)rhi_fake::ros::publish_count("/ns/state_out");
        }
      });
  }
  for (auto & t : workers) {t.join();}
  rhi_fake::ros::set_realtime_timers(false);
  CHECK(stop_spinning(exec, spin_returned));
  spinner.join();
  CHECK(received == 3 * 300 * 3);
  CHECK(rhi_fake::ros::publish_count("/ns/state_out") == 900);
  CHECK(unguarded >= 900);
  (void)rhi_fake::logs::lines();
}

// ============================================================== services (clients and servers)
// Real service types from the wheels (lifecycle_msgs/srv), so this runs on every machine; the AimDK
// system-state services are in test_vendor_messages().
namespace srv_test {
using ChangeState = lifecycle_msgs::srv::ChangeState;
using GetState = lifecycle_msgs::srv::GetState;

static ChangeState::Request::SharedPtr change(uint8_t id, const char * label)
{
  auto request = std::make_shared<ChangeState::Request>();
  request->transition.id = id;
  request->transition.label = label;
  return request;
}

template<typename FutureT>
static bool is_ready(const FutureT & future)
{
  return future.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

// The server callback forms rclcpp::AnyServiceCallback accepts, as a free function and a member.
static void plain_callback(
  const std::shared_ptr<ChangeState::Request> request, std::shared_ptr<ChangeState::Response> response)
{
  response->success = request->transition.id == 3;
}

struct Deferring
{
  std::mutex mutex;
  std::vector<std::pair<rmw_request_id_t, std::shared_ptr<ChangeState::Request>>> waiting;
  void on_request(
    std::shared_ptr<rmw_request_id_t> header, std::shared_ptr<ChangeState::Request> request)
  {
    std::lock_guard<std::mutex> lock(mutex);
    waiting.emplace_back(*header, std::move(request));
  }
};
}  // namespace srv_test

static void test_services()
{
  using namespace srv_test;
  using namespace std::chrono_literals;
  rhi_fake::reset_all();
  rclcpp::init(0, nullptr);

  // ---- QoS presets and the distro's create_* overloads ----
  rclcpp::ServicesQoS services_qos;
  CHECK(services_qos.depth() == 10 && services_qos.reliability() == rclcpp::ReliabilityPolicy::Reliable);
  CHECK(services_qos.durability() == rclcpp::DurabilityPolicy::Volatile);
  CHECK(rmw_qos_profile_services_default.depth == 10);
  CHECK(rclcpp::to_string(rclcpp::FutureReturnCode::SUCCESS) == "SUCCESS (0)");
  CHECK(rclcpp::to_string(rclcpp::FutureReturnCode::TIMEOUT) == "TIMEOUT (2)");

  auto server_node = std::make_shared<rclcpp::Node>("srv_server", "/robot");
  auto client_node = std::make_shared<rclcpp::Node>("srv_client", "/robot");
  CHECK_THROWS(
    rclcpp::exceptions::InvalidServiceNameError,
    client_node->create_client<ChangeState>("bad name"));
  CHECK_THROWS(
    rclcpp::exceptions::InvalidServiceNameError,
    server_node->create_service<ChangeState>("1bad", &plain_callback));

  // A client first: no server yet.
#if HARDWARE_INTERFACE_VERSION_MAJOR < 3
  auto client = client_node->create_client<ChangeState>("change_state", rmw_qos_profile_services_default);
#else
  auto client = client_node->create_client<ChangeState>("change_state", rclcpp::ServicesQoS());
#endif
  CHECK(std::string(client->get_service_name()) == "/robot/change_state");
  CHECK(client->get_request_publisher_actual_qos().depth() == 10);
  CHECK(!client->service_is_ready() && !client->wait_for_service(0s));
  const auto t0 = std::chrono::steady_clock::now();
  CHECK(!client->wait_for_service(30ms));
  CHECK(std::chrono::steady_clock::now() - t0 >= 25ms);
  // a request without a server is lost (rmw sends it to nobody), but it is counted
  auto lost = client->async_send_request(change(3, "activate"));
  CHECK(lost.request_id == 1 && !is_ready(lost));
  CHECK(rhi_fake::services::call_count("/robot/change_state") == 1);
  CHECK(client->remove_pending_request(lost) && !client->remove_pending_request(lost.request_id));

  auto server = server_node->create_service<ChangeState>("change_state", &plain_callback);
  CHECK(std::string(server->get_service_name()) == "/robot/change_state");
  CHECK(client->service_is_ready() && client->wait_for_service(std::chrono::seconds(1)));
  auto other_type = client_node->create_client<GetState>("change_state");
  CHECK(!other_type->service_is_ready());   // a server of another type does not match
  auto private_client = client_node->create_client<GetState>("~/get_state");
  CHECK(std::string(private_client->get_service_name()) == "/robot/srv_client/get_state");

  // ---- the request waits for the server's node, the response for the client's node ----
  rclcpp::executors::SingleThreadedExecutor server_exec;
  rclcpp::executors::SingleThreadedExecutor client_exec;
  server_exec.add_node(server_node);
  client_exec.add_node(client_node);
  auto result = client->async_send_request(change(3, "activate"));
  static_assert(
    std::is_same<decltype(result), rclcpp::Client<ChangeState>::FutureAndRequestId>::value, "result");
  static_assert(
    std::is_same<decltype(result.future), std::future<ChangeState::Response::SharedPtr>>::value,
    ".future is a std::future");
  CHECK(result.request_id == 2 && result.valid());
  client_exec.spin_some();
  CHECK(!is_ready(result));            // the server's node has not been spun
  server_exec.spin_some();
  CHECK(!is_ready(result));            // answered, but the client's node has not been spun
  client_exec.spin_some();
  CHECK(is_ready(result));
  CHECK(result.get()->success);
  auto requests = rhi_fake::services::requests<ChangeState>("robot/change_state");
  CHECK(requests.size() == 2 && requests[1].transition.label == "activate");

  // ---- spin_until_future_complete: the executor's and rclcpp's; share(); timeouts ----
  auto second = client->async_send_request(change(4, "deactivate"));
  rclcpp::Client<ChangeState>::SharedFuture shared = second.share();
  server_exec.spin_some();
  CHECK(client_exec.spin_until_future_complete(shared, 1s) == rclcpp::FutureReturnCode::SUCCESS);
  CHECK(!shared.get()->success);
  CHECK(client_exec.spin_until_future_complete(shared) == rclcpp::FutureReturnCode::SUCCESS);   // ready
  auto nobody = client->async_send_request(change(3, "activate"));   // the server's node is not spun
  CHECK(client_exec.spin_until_future_complete(nobody, 20ms) == rclcpp::FutureReturnCode::TIMEOUT);
  CHECK_THROWS(std::runtime_error, rclcpp::spin_until_future_complete(client_node, nobody, 20ms));
  client_exec.remove_node(client_node);
  server_exec.spin_some();
  CHECK(rclcpp::spin_until_future_complete(client_node, nobody, 1s) == rclcpp::FutureReturnCode::SUCCESS);
  CHECK(nobody.future.get()->success);

  // ---- the driver pattern: the client's node spins on its own thread, the caller waits ----
  std::atomic<bool> server_returned{false};
  std::atomic<bool> client_returned{false};
  std::thread server_spin([&]() {server_exec.spin(); server_returned = true;});
  client_exec.add_node(client_node);
  std::thread client_spin([&]() {client_exec.spin(); client_returned = true;});
  CHECK(rhi_fake::ros::wait_spinning_executors(2, 10000ms));
  auto waited = client->async_send_request(change(3, "activate"));
  CHECK(waited.wait_for(5s) == std::future_status::ready && waited.get()->success);

  // callback forms: SharedFuture, SharedFutureWithRequest (run on the client's spin thread)
  std::promise<bool> got_plain;
  auto with_cb = client->async_send_request(
    change(3, "activate"),
    [&got_plain](rclcpp::Client<ChangeState>::SharedFuture future) {got_plain.set_value(future.get()->success);});
  static_assert(
    std::is_same<decltype(with_cb), rclcpp::Client<ChangeState>::SharedFutureAndRequestId>::value, "cb");
  CHECK(got_plain.get_future().wait_for(5s) == std::future_status::ready);
  CHECK(with_cb.future.get()->success);
  std::promise<std::string> got_pair;
  auto with_req = client->async_send_request(
    change(4, "deactivate"),
    [&got_pair](rclcpp::Client<ChangeState>::SharedFutureWithRequest future) {
      got_pair.set_value(future.get().first->transition.label + (future.get().second->success ? "+" : "-"));
    });
  auto pair_future = got_pair.get_future();
  CHECK(pair_future.wait_for(5s) == std::future_status::ready && pair_future.get() == "deactivate-");
  CHECK(with_req.future.get().first->transition.id == 4);

  // many requests from several threads (TSan): every future completes
  {
    std::vector<std::thread> senders;
    std::atomic<int> ok{0};
    for (int t = 0; t < 3; ++t) {
      senders.emplace_back([&]() {
          for (int i = 0; i < 50; ++i) {
            auto f = client->async_send_request(change(3, "activate"));
            if (f.wait_for(10s) == std::future_status::ready && f.get()->success) {++ok;}
          }
        });
    }
    for (auto & t : senders) {t.join();}
    CHECK(ok == 150);
  }
  CHECK(stop_spinning(server_exec, server_returned));
  server_spin.join();

  // ---- server forms: request header; deferred responses (also with the service handle) ----
  std::atomic<int64_t> seen_sequence{-1};
  auto with_header = server_node->create_service<ChangeState>(
    "with_header",
    [&seen_sequence](
      const std::shared_ptr<rmw_request_id_t> header, const std::shared_ptr<ChangeState::Request> request,
      std::shared_ptr<ChangeState::Response> response) {
      seen_sequence = header->sequence_number;
      response->success = request->transition.id == 1;
    });
  auto header_client = client_node->create_client<ChangeState>("with_header");
  Deferring deferring;
  auto deferred = server_node->create_service<ChangeState>(
    "deferred",
    std::bind(&Deferring::on_request, &deferring, std::placeholders::_1, std::placeholders::_2));
  auto deferred_client = client_node->create_client<ChangeState>("deferred");
  std::atomic<int> handle_calls{0};
  auto deferred_handle = server_node->create_service<ChangeState>(
    "deferred_handle",
    [&handle_calls](
      std::shared_ptr<rclcpp::Service<ChangeState>> service, std::shared_ptr<rmw_request_id_t> header,
      std::shared_ptr<ChangeState::Request> request) {
      ++handle_calls;
      ChangeState::Response response;
      response.success = request->transition.id == 7;
      service->send_response(*header, response);   // answered at once, through the handle
    });
  auto handle_client = client_node->create_client<ChangeState>("deferred_handle");
  // a server callback taking a const request (callable as exactly one form) is accepted too
  auto const_request = server_node->create_service<GetState>(
    "get_state",
    [](std::shared_ptr<const GetState::Request>, std::shared_ptr<GetState::Response> response) {
      response->current_state.id = lifecycle_msgs::msg::State::PRIMARY_STATE_ACTIVE;
    });
  server_returned = false;
  std::thread server_spin2([&]() {server_exec.spin(); server_returned = true;});
  CHECK(rhi_fake::ros::wait_spinning_executors(2, 10000ms));

  auto h1 = header_client->async_send_request(change(1, "configure"));
  CHECK(h1.wait_for(5s) == std::future_status::ready && h1.get()->success);
  CHECK(seen_sequence == h1.request_id);
  auto d1 = deferred_client->async_send_request(change(9, "later"));
  CHECK(eventually([&]() {std::lock_guard<std::mutex> lock(deferring.mutex); return deferring.waiting.size() == 1;}));
  CHECK(d1.wait_for(20ms) == std::future_status::timeout);   // no response until send_response()
  {
    std::lock_guard<std::mutex> lock(deferring.mutex);
    ChangeState::Response late;
    late.success = deferring.waiting[0].second->transition.label == "later";
    deferred->send_response(deferring.waiting[0].first, late);   // from the test's thread
  }
  CHECK(d1.wait_for(5s) == std::future_status::ready && d1.get()->success);
  auto d2 = handle_client->async_send_request(change(7, "handle"));
  CHECK(d2.wait_for(5s) == std::future_status::ready && d2.get()->success && handle_calls == 1);
  auto g1 = private_client->async_send_request(std::make_shared<GetState::Request>());
  CHECK(g1.wait_for(20ms) == std::future_status::timeout);   // "~/get_state" is another name
  auto state_client = client_node->create_client<GetState>("get_state");
  auto g2 = state_client->async_send_request(std::make_shared<GetState::Request>());
  CHECK(g2.wait_for(5s) == std::future_status::ready);
  CHECK(g2.get()->current_state.id == lifecycle_msgs::msg::State::PRIMARY_STATE_ACTIVE);

  // ---- the test plays a server: answer, hold (timeouts), unserve ----
  const std::string remote = "/system/get_state";
  auto remote_client = client_node->create_client<GetState>(remote);
  CHECK(!remote_client->service_is_ready());
  std::thread late_server([&]() {
      std::this_thread::sleep_for(30ms);
      lifecycle_msgs::msg::State active;
      active.id = 3;
      active.label = "active";
      GetState::Response canned;
      canned.current_state = active;
      rhi_fake::services::serve<GetState>(remote, canned);
    });
  CHECK(remote_client->wait_for_service(5s));   // woken when the server appears
  late_server.join();
  auto r1 = remote_client->async_send_request(std::make_shared<GetState::Request>());
  CHECK(r1.wait_for(5s) == std::future_status::ready && r1.get()->current_state.label == "active");
  std::atomic<int> handled{0};
  rhi_fake::services::serve<ChangeState>(
    "/system/change_state",
    [&handled](const ChangeState::Request & request, ChangeState::Response & response) {
      ++handled;
      response.success = request.transition.label == "configure";
    });
  auto remote_change = client_node->create_client<ChangeState>("/system/change_state");
  auto r2 = remote_change->async_send_request(change(1, "configure"));
  CHECK(r2.wait_for(5s) == std::future_status::ready && r2.get()->success && handled == 1);

  rhi_fake::services::hold("/system/change_state");
  CHECK(remote_change->service_is_ready());
  auto held1 = remote_change->async_send_request(change(1, "configure"));
  auto held2 = remote_change->async_send_request(change(2, "cleanup"));
  CHECK(held1.wait_for(30ms) == std::future_status::timeout);   // what a driver's timeout sees
  CHECK(rhi_fake::services::held_count("/system/change_state") == 2);
  CHECK(remote_change->remove_pending_request(held2));           // the caller gave up on it
  ChangeState::Response yes;
  yes.success = true;
  CHECK_THROWS(std::logic_error, rhi_fake::services::answer_held<GetState>("/system/change_state", GetState::Response()));
  CHECK(rhi_fake::services::answer_held<ChangeState>("/system/change_state", yes) == 2);
  CHECK(held1.wait_for(5s) == std::future_status::ready && held1.get()->success);
  // removed: its response is ignored, and its promise went with it (a broken promise, as in rclcpp)
  CHECK(held2.wait_for(0s) == std::future_status::ready);
  CHECK_THROWS(std::future_error, held2.future.get());
  CHECK(rhi_fake::services::held_count("/system/change_state") == 0);
  auto sent = rhi_fake::services::requests<ChangeState>("/system/change_state");
  CHECK(sent.size() == 3 && sent[2].transition.label == "cleanup");
  CHECK(rhi_fake::services::call_count("/system/change_state") == 3);
  CHECK_THROWS(std::logic_error, rhi_fake::services::requests<GetState>("/system/change_state"));
  auto listed = rhi_fake::services::info("/system/change_state");
  CHECK(listed && listed->fake == "hold" && listed->clients.size() == 1 && listed->servers.empty());
  CHECK(listed->clients[0].node == "/robot/srv_client" && listed->clients[0].type_name == "lifecycle_msgs/srv/ChangeState");
  auto own = rhi_fake::services::info("/robot/change_state");
  CHECK(own && own->servers.size() == 1 && own->servers[0].node == "/robot/srv_server" && own->fake.empty());
  rhi_fake::services::unserve("/system/change_state");
  CHECK(!remote_change->service_is_ready() && !remote_change->wait_for_service(10ms));

  // prune: pending requests sent before a time point, then all
  rhi_fake::services::hold("/system/change_state");
  auto p1 = remote_change->async_send_request(change(1, "a"));
  const auto cut = std::chrono::system_clock::now() + 1s;
  auto p2 = remote_change->async_send_request(change(1, "b"));
  std::vector<int64_t> pruned;
  CHECK(remote_change->prune_requests_older_than(cut, &pruned) == 2 && pruned.size() == 2);
  auto p3 = remote_change->async_send_request(change(1, "c"));
  CHECK(remote_change->prune_pending_requests() == 1 && remote_change->prune_pending_requests() == 0);
  CHECK_THROWS(std::future_error, p1.future.get());
  CHECK(rhi_fake::services::answer_held<ChangeState>("/system/change_state", yes) == 3);   // ignored

  // rhi_fake::services::call: the test calls an in-process server now, on this thread
  auto called = rhi_fake::services::call<ChangeState>("/robot/change_state", *change(3, "activate"));
  CHECK(called && called->success);
  CHECK(!rhi_fake::services::call<ChangeState>("/robot/deferred", *change(1, "x")));   // deferred
  CHECK(!rhi_fake::services::call<ChangeState>("/nobody", *change(1, "x")));

  // a destroyed client breaks its pending futures (its promises go away)
  auto doomed_client = client_node->create_client<ChangeState>("/system/change_state");
  auto doomed = doomed_client->async_send_request(change(1, "doomed"));
  doomed_client.reset();
  CHECK_THROWS(std::future_error, doomed.future.get());
  CHECK(rhi_fake::services::answer_held<ChangeState>("/system/change_state", yes) == 0);   // client gone

  // INTERRUPTED: cancel() while spin_until_future_complete waits
  CHECK(stop_spinning(client_exec, client_returned));
  client_spin.join();
  std::promise<void> never;
  auto never_future = never.get_future().share();
  std::atomic<bool> interrupted{false};
  std::thread waiter([&]() {
      interrupted = client_exec.spin_until_future_complete(never_future) == rclcpp::FutureReturnCode::INTERRUPTED;
    });
  CHECK(rhi_fake::ros::wait_spinning_executors(2, 10000ms));
  CHECK(stop_spinning(client_exec, interrupted));
  waiter.join();
  CHECK(interrupted);

  CHECK(stop_spinning(server_exec, server_returned));
  server_spin2.join();
  (void)p2; (void)p3;
  rhi_fake::reset_all();
  CHECK(rhi_fake::services::list().empty());
}

// ============================================================== unitree_sdk2
namespace g1 {
using LowCmd = unitree_hg::msg::dds_::LowCmd_;
using LowState = unitree_hg::msg::dds_::LowState_;

class MiniDriver
{
public:
  void Init(const std::string & nic)
  {
    unitree::robot::ChannelFactory::Instance()->Init(0, nic);
    pub_.reset(new unitree::robot::ChannelPublisher<LowCmd>("rt/lowcmd"));
    pub_->InitChannel();
    sub_.reset(new unitree::robot::ChannelSubscriber<LowState>("rt/lowstate"));
    sub_->InitChannel(std::bind(&MiniDriver::StateHandler, this, std::placeholders::_1), 1);
    thread_ = unitree::common::CreateRecurrentThreadEx("command_writer", UT_CPU_ID_NONE, 2000, &MiniDriver::CommandWriter, this);
  }
  void Stop()
  {
    if (thread_) {
      thread_->Wait();
      thread_.reset();
    }
    sub_->CloseChannel();
    pub_->CloseChannel();
  }
  void StateHandler(const void * message)
  {
    const auto & state = *static_cast<const LowState *>(message);
    mode_machine_ = state.mode_machine();
    q0_ = state.motor_state()[0].q();
    states_++;
  }
  void CommandWriter()
  {
    cmd_.mode_machine() = mode_machine_.load();
    cmd_.motor_cmd().at(0).q() = q0_.load();
    cmd_.motor_cmd()[1].mode(1);
    pub_->Write(cmd_);
    writes_++;
  }

  unitree::robot::ChannelPublisherPtr<LowCmd> pub_;
  unitree::robot::ChannelSubscriberPtr<LowState> sub_;
  unitree::common::ThreadPtr thread_;
  LowCmd cmd_;
  std::atomic<uint8_t> mode_machine_{0};
  std::atomic<float> q0_{0.0f};
  std::atomic<int> states_{0};
  std::atomic<int> writes_{0};
};
}  // namespace g1

static void test_unitree()
{
  using namespace unitree_hg::msg::dds_;
  static_assert(sizeof(MotorCmd_) == 28, "MotorCmd_");
  static_assert(sizeof(MotorState_) == 56, "MotorState_");
  static_assert(sizeof(IMUState_) == 56, "IMUState_");
  static_assert(sizeof(LowCmd_) == 1004, "LowCmd_");
  static_assert(sizeof(LowState_) == 2092, "LowState_");
  LowCmd_ cmd;
  CHECK(cmd.mode_pr() == 0 && cmd.motor_cmd().size() == 35 && cmd.reserve().size() == 4 && cmd.crc() == 0);
  cmd.mode_machine(5);
  cmd.motor_cmd()[3].kp() = 60.0f;
  cmd.crc() = 0xFE172F9Fu;
  const LowCmd_ & ccmd = cmd;
  CHECK(ccmd.mode_machine() == 5 && ccmd.motor_cmd()[3].kp() == 60.0f && ccmd.crc() == 0xFE172F9Fu);
  uint32_t last_word = 0;
  std::memcpy(&last_word, reinterpret_cast<const unsigned char *>(&cmd) + 1000, 4);
  CHECK(last_word == 0xFE172F9Fu);   // crc is the trailing 32-bit word
  LowState_ st;
  st.imu_state().quaternion() = {1.0f, 0.0f, 0.0f, 0.0f};
  st.motor_state()[28].temperature()[1] = 40;
  st.wireless_remote()[39] = 1;
  st.crc(7);
  std::memcpy(&last_word, reinterpret_cast<const unsigned char *>(&st) + 2088, 4);
  CHECK(last_word == 7u && st.version().size() == 2 && st.tick() == 0);
  MotorState_ ms;
  CHECK(ms.tau_est() == 0.0f && ms.motorstate() == 0u && ms.sensor().size() == 2 && ms.vol() == 0.0f);
  IMUState_ imu;
  CHECK(imu.temperature() == 0 && imu.rpy().size() == 3 && imu.gyroscope()[2] == 0.0f && imu.accelerometer()[0] == 0.0f);
  MotorCmd_ mc(1, 0.5f, 0.0f, 0.0f, 10.0f, 1.0f, 0u);
  CHECK(mc.mode() == 1 && mc.q() == 0.5f && mc.kd() == 1.0f && mc.dq() == 0.0f && mc.tau() == 0.0f && mc.reserve() == 0u);
  CHECK(LowCmd_() == LowCmd_() && cmd != LowCmd_());
  // Dex3-1 hand messages: IDL sequences (empty until sized), no crc
  static_assert(sizeof(PressSensorState_) == 104, "PressSensorState_");
  HandCmd_ hand_cmd;
  CHECK(hand_cmd.motor_cmd().empty() && hand_cmd.reserve().size() == 4);
  hand_cmd.motor_cmd().resize(7);
  hand_cmd.motor_cmd()[6].mode() = 0x16;
  HandState_ hand_state;
  CHECK(hand_state.motor_state().empty() && hand_state.press_sensor_state().empty() && hand_state.error().size() == 2);
  hand_state.press_sensor_state().resize(9);
  CHECK(hand_state.press_sensor_state()[8].pressure().size() == 12 && hand_state.power_v() == 0.0f);
  CHECK(hand_cmd != HandCmd_() && hand_cmd.motor_cmd()[6].mode() == 0x16);

  // channels before ChannelFactory::Init: Write false, InitChannel throws (the SDK would crash)
  unitree::robot::ChannelPublisher<LowCmd_> early("rt/lowcmd");
  CHECK(!early.Write(cmd));
  CHECK_THROWS(std::logic_error, early.InitChannel());

  // motion switcher release loop, as in the SDK example
  rhi_fake::unitree::set_motion_mode("normal", "ai");
  {
    auto msc = std::make_shared<unitree::robot::b2::MotionSwitcherClient>();
    msc->SetTimeout(5.0f);
    msc->Init();
    std::string form, name;
    int loops = 0;
    while (msc->CheckMode(form, name), !name.empty()) {
      CHECK(msc->ReleaseMode() == 0);
      if (++loops > 5) {break;}
    }
    CHECK(loops == 1);
    msc->SetTimeout(static_cast<int64_t>(2000000));
    bool silent = true;
    CHECK(msc->GetSilent(silent) == 0 && !silent && msc->SetSilent(true) == 0 && msc->SelectMode("ai") == 0);
  }
  auto ms_stats = rhi_fake::unitree::motion_switcher();
  CHECK(ms_stats.constructed == 1 && ms_stats.init_calls == 1 && ms_stats.set_timeout_calls == 2);
  CHECK(ms_stats.check_calls == 2 && ms_stats.release_calls == 1 && std::fabs(ms_stats.last_timeout_s - 2.0) < 1e-9);
  CHECK(ms_stats.name == "ai");
  rhi_fake::unitree::set_motion_switcher_behaviour(3, 4, false);
  {
    unitree::robot::b2::MotionSwitcherClient m2;
    std::string form, name;
    CHECK(m2.CheckMode(form, name) == 3 && name == "ai" && m2.ReleaseMode() == 4);
    CHECK(m2.CheckMode(form, name) == 3 && name == "ai");
  }

  // ticked recurrent thread (default mode)
  g1::MiniDriver drv;
  drv.Init("lo");
  auto fi = rhi_fake::unitree::factory_init();
  CHECK(fi.init_count == 1 && fi.inited && !fi.by_config_file && fi.domain_id == 0 && fi.network_interface == "lo");
  auto threads = rhi_fake::unitree::threads();
  CHECK(threads.size() == 1 && threads[0].name == "command_writer" && threads[0].interval_us == 2000);
  CHECK(threads[0].cpu_id == UT_CPU_ID_NONE && !threads[0].real && !threads[0].stopped && threads[0].runs == 0);
  CHECK(drv.writes_ == 0);   // nothing runs by itself
  CHECK(rhi_fake::unitree::tick_thread("command_writer") == 1 && drv.writes_ == 1);
  CHECK(rhi_fake::unitree::tick_thread("other") == 0);
  CHECK(rhi_fake::unitree::tick_all_threads() == 1 && drv.writes_ == 2);
  CHECK(rhi_fake::unitree::write_count("rt/lowcmd") == 2);

  LowState_ state;
  state.mode_machine() = 5;
  state.motor_state()[0].q() = 0.75f;
  CHECK(rhi_fake::unitree::deliver("rt/lowstate", state) == 1 && drv.states_ == 1 && drv.mode_machine_ == 5);
  CHECK(drv.sub_->GetLastDataAvailableTime() > 0);
  LowState_ latest;
  CHECK(drv.sub_->ReadLatest(latest) && latest.motor_state()[0].q() == 0.75f && drv.sub_->Read(latest));
  rhi_fake::unitree::tick_thread("command_writer");
  LowCmd_ written;
  CHECK(rhi_fake::unitree::last_written("rt/lowcmd", written));
  CHECK(written.mode_machine() == 5 && written.motor_cmd()[0].q() == 0.75f && written.motor_cmd()[1].mode() == 1);
  CHECK(rhi_fake::unitree::last_written<LowCmd_>("rt/lowcmd")->mode_machine() == 5);
  CHECK(!rhi_fake::unitree::last_written<LowCmd_>("rt/none"));
  CHECK_THROWS(std::logic_error, rhi_fake::unitree::last_written<LowState_>("rt/lowcmd"));
  CHECK_NO_ALLOC("unitree deliver", rhi_fake::unitree::deliver("rt/lowstate", state));
  CHECK_NO_ALLOC("unitree tick + Write", rhi_fake::unitree::tick_thread("command_writer"));
  CHECK_NO_ALLOC("ChannelPublisher::Write", drv.pub_->Write(written));
  CHECK(rhi_fake::unitree::write_count("rt/lowcmd") == 5);

  auto chans = rhi_fake::unitree::channels();
  CHECK(chans.size() == 2);
  CHECK(chans[0].name == "rt/lowcmd" && chans[0].type_name == "unitree_hg::msg::dds_::LowCmd_" && chans[0].writers_created == 1);
  CHECK(chans[1].name == "rt/lowstate" && chans[1].open_readers == 1 && chans[1].reader_queue_lengths[0] == 1);
  CHECK(drv.pub_->GetChannelName() == "rt/lowcmd" && drv.sub_->GetChannelName() == "rt/lowstate");

  drv.Stop();
  CHECK(rhi_fake::unitree::tick_thread("command_writer") == 0);
  CHECK(rhi_fake::unitree::deliver("rt/lowstate", state) == 0 && drv.states_ == 2);
  CHECK(!drv.pub_->Write(written));
  CHECK(drv.sub_->GetLastDataAvailableTime() == -1);

  // a polling subscriber (no handler) still sees ReadLatest()
  unitree::robot::ChannelSubscriber<LowState_> poller("rt/lowstate");
  poller.InitChannel();
  LowState_ polled;
  CHECK(!poller.ReadLatest(polled));
  rhi_fake::unitree::deliver("rt/lowstate", state);
  CHECK(poller.ReadLatest(polled) && polled.mode_machine() == 5);

  // real threads: run every interval on their own std::thread until Wait()
  rhi_fake::unitree::use_real_threads(true);
  std::atomic<int> ticks{0};
  auto counter = [&ticks]() {ticks++;};
  unitree::common::ThreadPtr real = unitree::common::CreateRecurrentThreadEx("real_writer", 2, 1000, counter);
  CHECK(eventually([&]() {return ticks.load() >= 5;}));
  CHECK(rhi_fake::unitree::tick_thread("real_writer") == 0);   // real threads are not ticked
  auto rinfo = rhi_fake::unitree::threads();
  CHECK(!rinfo.empty() && rinfo.back().real && rinfo.back().cpu_id == 2);
  CHECK(real->Wait());
  int after_wait = ticks.load();
  std::this_thread::sleep_for(std::chrono::milliseconds(10));
  CHECK(ticks.load() == after_wait);
  real.reset();
  // destruction without Wait() also stops it; CreateRecurrentThread (no name) works
  {
    auto anon = unitree::common::CreateRecurrentThread(500, counter);
    CHECK(eventually([&]() {return ticks.load() >= after_wait + 3;}));
  }
  int after_destroy = ticks.load();
  std::this_thread::sleep_for(std::chrono::milliseconds(10));
  CHECK(ticks.load() == after_destroy);
  // the real-mode driver: writer thread and state deliveries race (for TSan)
  {
    g1::MiniDriver live;
    live.Init("eth0");
    for (int i = 0; i < 200; ++i) {rhi_fake::unitree::deliver("rt/lowstate", state);}
    CHECK(eventually([&]() {return live.writes_.load() >= 3;}));
    live.Stop();
  }
  rhi_fake::unitree::use_real_threads(false);

  unitree::robot::ChannelFactory::Instance()->Init("config.json");
  fi = rhi_fake::unitree::factory_init();
  CHECK(fi.by_config_file && fi.config_file == "config.json" && fi.init_count == 3);
  unitree::robot::ChannelFactory::Instance()->Release();
  CHECK(rhi_fake::unitree::factory_init().release_count == 1 && !rhi_fake::unitree::factory_init().inited);
}

// ============================================================== reset
static void test_reset()
{
  rhi_fake::reset_all();
  CHECK(!rclcpp::ok());
  CHECK(rhi_fake::ros::topics().empty() && rhi_fake::ros::timer_periods().empty());
  CHECK(rhi_fake::unitree::channels().empty() && rhi_fake::unitree::threads().empty());
  CHECK(rhi_fake::unitree::factory_init().init_count == 0);
  CHECK(rhi_fake::logs::count_all() == 0);
  CHECK(!rhi_fake::ros::realtime_timers());
  rclcpp::init(0, nullptr);
  CHECK(rclcpp::ok());
  rclcpp::shutdown();
}


int main()
{
  test_hardware_interface();
  test_messages();
  test_time();
  test_rclcpp();
  test_parameters();
  test_concurrency();
  test_services();
  test_unitree();
  test_reset();
  if (g_failures != 0) {
    std::fprintf(stderr, "selftest: %d of %d checks FAILED\n", g_failures, g_checks);
    return 1;
  }
  std::printf("selftest: all %d checks passed\n", g_checks);
  return 0;
}
