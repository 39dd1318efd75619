// Self-test of the rosidl-generated vendor messages with the rhi-gen stand-ins and rhi_fake ROS hooks
// (run by tests/cpp/test_standins.py; AimDK's definitions come from ../shared, tests/support/vendor_msgs.py).
// Exit code 0 = all checks passed.

#include <aimdk_msgs/msg/common_state.hpp>
#include <aimdk_msgs/msg/domain_error_state.hpp>
#include <aimdk_msgs/msg/joint_command.hpp>
#include <aimdk_msgs/msg/joint_command_array.hpp>
#include <aimdk_msgs/msg/joint_state.hpp>
#include <aimdk_msgs/msg/joint_state_array.hpp>
#include <aimdk_msgs/msg/message_header.hpp>
#include <aimdk_msgs/msg/system_status.hpp>
#include <aimdk_msgs/srv/get_system_state.hpp>
#include <aimdk_msgs/srv/migrate_system_state.hpp>
#include <interface_protocol/msg/imu_info.hpp>
#include <interface_protocol/msg/joint_command.hpp>
#include <interface_protocol/msg/joint_state.hpp>
#include <interface_protocol/msg/parallel_parser_type.hpp>
#include <rclcpp/executors/single_threaded_executor.hpp>
#include <rclcpp/node.hpp>
#include <rclcpp/qos.hpp>
#include <rclcpp/rclcpp.hpp>

#include "rhi_fake/all.hpp"

#include "selftest_support.hpp"

// ============================================================== vendor messages (rosidl-generated)
// Fields, defaults and constants as listed in shared/upstream/SDK_FACTS.md (§B AimDK v1.0.0, §C
// interface_protocol), and the rhi_fake ROS hooks with these types.
static void test_vendor_messages()
{
  aimdk_msgs::msg::JointCommandArray cmd;
  cmd.joints.resize(2);
  cmd.joints[0].name = "left_hip_pitch_joint";
  cmd.joints[0].stiffness = 40.0;
  cmd.header.sequence = 7;
  CHECK(cmd.joints[1].damping == 0.0 && cmd.header.meas_stamp.sec == 0);
  aimdk_msgs::msg::JointCommand jc;
  CHECK(jc.position == 0.0 && jc.velocity == 0.0 && jc.effort == 0.0 && jc.name.empty());
  aimdk_msgs::msg::JointStateArray st;
  st.joints.resize(1);
  st.joints[0].error_code = 5;
  static_assert(std::is_same<decltype(st.joints[0].error_code), uint16_t>::value, "error_code");
  CHECK(st.state.value == aimdk_msgs::msg::DomainErrorState::NONE);
  static_assert(aimdk_msgs::msg::DomainErrorState::DAMPING == 1, "DAMPING");
  static_assert(aimdk_msgs::msg::DomainErrorState::DISCONNECT == 4, "DISCONNECT");
  aimdk_msgs::msg::JointState ajs;
  aimdk_msgs::msg::MessageHeader mh;
  CHECK(ajs.effort == 0.0 && mh.sequence == 0u);

  interface_protocol::msg::JointCommand ic;
  ic.position.assign(24, 0.0);
  ic.parallel_parser_type = interface_protocol::msg::ParallelParserType::RL_PARSER;
  static_assert(interface_protocol::msg::ParallelParserType::CLASSIC_PARSER == 0, "CLASSIC");
  static_assert(interface_protocol::msg::ParallelParserType::RL_PARSER == 1, "RL");
  CHECK(ic.feed_forward_torque.empty() && ic.torque.empty() && ic.stiffness.empty() && ic.damping.empty());
  interface_protocol::msg::JointState ijs;
  interface_protocol::msg::ImuInfo ii;
  interface_protocol::msg::ParallelParserType ppt;
  CHECK(ijs.torque.empty() && ii.quaternion.w == 1.0 && ii.rpy.x == 0.0 && ppt.structure_needs_at_least_one_member == 0);
  CHECK(ii.linear_acceleration.z == 0.0 && ii.angular_velocity.y == 0.0);
  static_assert(std::is_same<decltype(jc.stiffness), double>::value && std::is_same<decltype(ajs.position), double>::value,
    "AimDK float64");
  static_assert(std::is_same<decltype(ic.torque), std::vector<double>>::value, "interface_protocol float64[]");
  static_assert(std::is_same<decltype(ic.parallel_parser_type), uint8_t>::value, "uint8");
  static_assert(std::is_same<decltype(mh.sequence), uint32_t>::value, "uint32");

  CHECK(std::string(rosidl_generator_traits::data_type<aimdk_msgs::msg::JointCommandArray>()) ==
    "aimdk_msgs::msg::JointCommandArray");
  CHECK(std::string(rosidl_generator_traits::name<interface_protocol::msg::JointCommand>()) ==
    "interface_protocol/msg/JointCommand");
  static_assert(rosidl_generator_traits::is_message<interface_protocol::msg::ImuInfo>::value, "msg");
  static_assert(!std::is_convertible<rosidl_runtime_cpp::MessageInitialization, aimdk_msgs::msg::JointStateArray>::value,
    "explicit ctor");

  rclcpp::init(0, nullptr);
  auto node = std::make_shared<rclcpp::Node>("vendor_node");
  rclcpp::QoS q3(3);
  q3.best_effort().durability_volatile();
  auto cmd_pub = node->create_publisher<interface_protocol::msg::JointCommand>("/hardware/joint_command", q3);
  interface_protocol::msg::JointCommand ip_cmd;
  ip_cmd.position.assign(24, 0.5);
  ip_cmd.velocity.assign(24, 0.0);
  ip_cmd.feed_forward_torque.assign(24, 0.0);
  ip_cmd.torque.assign(24, 0.0);
  ip_cmd.stiffness.assign(24, 40.0);
  ip_cmd.damping.assign(24, 1.0);
  ip_cmd.parallel_parser_type = interface_protocol::msg::ParallelParserType::RL_PARSER;
  cmd_pub->publish(ip_cmd);   // first publish sizes the retained message
  ip_cmd.position[3] = 1.5;
  CHECK_NO_ALLOC("Publisher::publish interface_protocol JointCommand (warm)", cmd_pub->publish(ip_cmd));
  auto last = rhi_fake::ros::last_published<interface_protocol::msg::JointCommand>("/hardware/joint_command");
  CHECK(last && last->position[3] == 1.5 && last->stiffness[23] == 40.0 && last->parallel_parser_type == 1);
  auto info = rhi_fake::ros::topic("/hardware/joint_command");
  CHECK(info && info->publishers.size() == 1 && info->publishers[0].type_name == "interface_protocol/msg/JointCommand");

  aimdk_msgs::msg::JointCommandArray arr;
  arr.joints.resize(12);
  for (size_t i = 0; i < arr.joints.size(); ++i) {arr.joints[i].name = "left_long_joint_name_" + std::to_string(i);}
  auto arr_pub = node->create_publisher<aimdk_msgs::msg::JointCommandArray>("/aima/hal/joint/leg/command", rclcpp::SensorDataQoS());
  arr_pub->publish(arr);
  arr.joints[2].position = 0.3;
  CHECK_NO_ALLOC("Publisher::publish JointCommandArray (warm)", arr_pub->publish(arr));
  auto arr_last = rhi_fake::ros::last_published<aimdk_msgs::msg::JointCommandArray>("/aima/hal/joint/leg/command");
  CHECK(arr_last && arr_last->joints[2].position == 0.3 && arr_last->joints[11].name == "left_long_joint_name_11");

  auto arr_info = rhi_fake::ros::topic("/aima/hal/joint/leg/command");
  CHECK(arr_info && arr_info->publishers[0].type_name == "aimdk_msgs/msg/JointCommandArray");

  int received = 0;
  auto sub = node->create_subscription<aimdk_msgs::msg::JointStateArray>(
    "/aima/hal/joint/leg/state", rclcpp::SensorDataQoS(),
    [&received](aimdk_msgs::msg::JointStateArray::ConstSharedPtr m) {received += static_cast<int>(m->joints.size());});
  aimdk_msgs::msg::JointStateArray state;
  state.joints.resize(12);
  auto state_ptr = std::make_shared<const aimdk_msgs::msg::JointStateArray>(state);
  CHECK(rhi_fake::ros::deliver("/aima/hal/joint/leg/state", state_ptr) == 1 && received == 12);
  CHECK_NO_ALLOC("deliver shared_ptr<const JointStateArray>",
    rhi_fake::ros::deliver("/aima/hal/joint/leg/state", state_ptr));
  auto sub_info = rhi_fake::ros::topic("/aima/hal/joint/leg/state");
  CHECK(sub_info && sub_info->subscriptions[0].type_name == "aimdk_msgs/msg/JointStateArray");
  CHECK(rhi_fake::ros::deliver("/aima/hal/joint/leg/state", interface_protocol::msg::JointState()) == 0);

  // ---- the AimDK system-state services (what an X2 driver calls on activation/deactivation) ----
  using Migrate = aimdk_msgs::srv::MigrateSystemState;
  using GetSystemState = aimdk_msgs::srv::GetSystemState;
  static_assert(rosidl_generator_traits::is_service<Migrate>::value, "srv");
  static_assert(std::is_same<decltype(Migrate::Request().state), std::string>::value, "state");
  static_assert(std::is_same<decltype(Migrate::Response().header.status.value), int32_t>::value, "status");
  static_assert(std::is_same<decltype(Migrate::Response().header.header.code), int64_t>::value, "code");
  static_assert(aimdk_msgs::msg::CommonState::SUCCESS == 1 && aimdk_msgs::msg::CommonState::RUNNING == 400, "CommonState");
  static_assert(aimdk_msgs::msg::SystemStatus::IN_READY == 1 && aimdk_msgs::msg::SystemStatus::IN_FALLBACK_MOVE == 5, "SystemStatus");
  CHECK(std::string(rosidl_generator_traits::name<Migrate>()) == "aimdk_msgs/srv/MigrateSystemState");
  const std::string migrate_name = "/aimdk_5Fmsgs/srv/MigrateSystemState";
  const std::string get_name = "/aimdk_5Fmsgs/srv/GetSystemState";
  auto migrate = node->create_client<Migrate>(migrate_name);
  auto get_state = node->create_client<GetSystemState>(get_name);
  CHECK(std::string(migrate->get_service_name()) == migrate_name && !migrate->wait_for_service(std::chrono::milliseconds(0)));
  // the test plays the AimDK system-state manager (another process on the robot)
  rhi_fake::services::serve<Migrate>(
    migrate_name, [](const Migrate::Request & request, Migrate::Response & response) {
      response.header.status.value = request.state.empty() ?
        aimdk_msgs::msg::CommonState::INVALID : aimdk_msgs::msg::CommonState::SUCCESS;
      response.header.header.stamp.sec = 12;
    });
  GetSystemState::Response ready;
  ready.cur_state = "state_a";
  ready.curr_status.value = aimdk_msgs::msg::SystemStatus::IN_READY;
  rhi_fake::services::serve<GetSystemState>(get_name, ready);
  CHECK(migrate->wait_for_service(std::chrono::milliseconds(100)) && get_state->service_is_ready());
  rclcpp::executors::SingleThreadedExecutor exec;
  exec.add_node(node);
  std::atomic<bool> spin_returned{false};
  std::thread spinner([&]() {exec.spin(); spin_returned = true;});
  CHECK(rhi_fake::ros::wait_spinning_executors(1, std::chrono::milliseconds(10000)));
  auto request = std::make_shared<Migrate::Request>();
  request->header.header.stamp.sec = 11;
  request->state = "state_b";
  auto migrated = migrate->async_send_request(request);
  CHECK(migrated.wait_for(std::chrono::seconds(5)) == std::future_status::ready);
  auto migrated_response = migrated.get();
  CHECK(migrated_response->header.status.value == aimdk_msgs::msg::CommonState::SUCCESS);
  CHECK(migrated_response->header.header.stamp.sec == 12);
  auto status = get_state->async_send_request(std::make_shared<GetSystemState::Request>());
  CHECK(status.wait_for(std::chrono::seconds(5)) == std::future_status::ready);
  auto status_response = status.get();
  CHECK(status_response->cur_state == "state_a" &&
    status_response->curr_status.value == aimdk_msgs::msg::SystemStatus::IN_READY);
  auto sent = rhi_fake::services::requests<Migrate>(migrate_name);
  CHECK(sent.size() == 1 && sent[0].state == "state_b" && sent[0].header.header.stamp.sec == 11);
  // the manager does not answer: the driver's wait times out
  rhi_fake::services::hold(migrate_name);
  auto unanswered = migrate->async_send_request(request);
  CHECK(unanswered.wait_for(std::chrono::milliseconds(30)) == std::future_status::timeout);
  CHECK(migrate->remove_pending_request(unanswered) && rhi_fake::services::held_count(migrate_name) == 1);
  CHECK(rhi_fake::services::call_count(migrate_name) == 2);
  CHECK(stop_spinning(exec, spin_returned));
  spinner.join();

  sub.reset();
  cmd_pub.reset();
  arr_pub.reset();
  migrate.reset();
  get_state.reset();
  node.reset();
  rhi_fake::reset_all();
}

int main()
{
  test_vendor_messages();
  if (g_failures != 0) {
    std::fprintf(stderr, "selftest: %d of %d checks FAILED\n", g_failures, g_checks);
    return 1;
  }
  std::printf("selftest: vendor messages checked\n");
  std::printf("selftest: all %d checks passed\n", g_checks);
  return 0;
}
