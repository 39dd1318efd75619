// The harness's own AimDK system-state manager (robots with transport_options.take_control, RHI_TAKE_CONTROL),
// written from tests/support/aimdk_facts.py, not from the generated fake robot: it plays the server of
// /aimdk_5Fmsgs/srv/MigrateSystemState and /aimdk_5Fmsgs/srv/GetSystemState through the stand-in's test
// servers (rhi_fake::services::serve), so every section can activate the driver. It starts in "Ready",
// accepts the documented states (or refuses every migration when told to), reports a migration IN_MOVE for
// one query and then IN_READY, and records every request with the number of joint commands published
// before it (the section take_control checks the order).
#pragma once

#include <aimdk_msgs/msg/common_state.hpp>
#include <aimdk_msgs/msg/system_status.hpp>
#include <aimdk_msgs/srv/get_system_state.hpp>
#include <aimdk_msgs/srv/migrate_system_state.hpp>

#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "rhi_fake/services.hpp"

namespace rhi_test {

class AimdkSystemStateServer {
public:
  using Migrate = aimdk_msgs::srv::MigrateSystemState;
  using GetState = aimdk_msgs::srv::GetSystemState;
  static constexpr const char* kMigrate = "/aimdk_5Fmsgs/srv/MigrateSystemState";
  static constexpr const char* kGetState = "/aimdk_5Fmsgs/srv/GetSystemState";

  struct Request {
    std::string service;   // kMigrate or kGetState
    std::string state;     // the state asked for (MigrateSystemState)
    uint64_t commands_before;  // joint commands published before the request
  };

  // `commands_published`: how many joint commands the driver has published so far.
  explicit AimdkSystemStateServer(std::function<uint64_t()> commands_published)
      : commands_published_(std::move(commands_published)) {}

  void serve() {
    rhi_fake::services::serve<Migrate>(kMigrate, [this](const Migrate::Request& rq, Migrate::Response& rs) {
      std::lock_guard<std::mutex> lock(mutex_);
      requests_.push_back({kMigrate, rq.state, commands_published_()});
      rs.header.header.code = 0;
      const bool known = rq.state == "Ready" || rq.state == "Develop_MC" || rq.state == "Develop_Nav" ||
                         rq.state == "Develop_Audio_Linux" || rq.state == "Develop_Audio_ROS";
      if (refuse_ || !known) {
        rs.header.status.value = aimdk_msgs::msg::CommonState::FAILURE;
        rs.header.message = "refused by the harness";
        return;
      }
      state_ = rq.state;
      in_move_ = 1;
      rs.header.status.value = aimdk_msgs::msg::CommonState::SUCCESS;
    });
    rhi_fake::services::serve<GetState>(kGetState, [this](const GetState::Request&, GetState::Response& rs) {
      std::lock_guard<std::mutex> lock(mutex_);
      requests_.push_back({kGetState, "", commands_published_()});
      rs.header.header.code = 0;
      rs.header.status.value = aimdk_msgs::msg::CommonState::SUCCESS;
      rs.cur_state = state_;
      rs.curr_status.value = in_move_ > 0 ? aimdk_msgs::msg::SystemStatus::IN_MOVE
                                          : aimdk_msgs::msg::SystemStatus::IN_READY;
      in_move_ = in_move_ > 0 ? in_move_ - 1 : 0;
    });
  }

  void refuse(bool on) {
    std::lock_guard<std::mutex> lock(mutex_);
    refuse_ = on;
  }
  std::string state() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return state_;
  }
  std::vector<Request> requests() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return requests_;
  }
  void clear() {
    std::lock_guard<std::mutex> lock(mutex_);
    requests_.clear();
  }

private:
  std::function<uint64_t()> commands_published_;
  mutable std::mutex mutex_;
  std::string state_{"Ready"};
  int in_move_{0};
  bool refuse_{false};
  std::vector<Request> requests_;
};

}  // namespace rhi_test
