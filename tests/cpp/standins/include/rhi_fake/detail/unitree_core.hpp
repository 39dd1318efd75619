// rhi-gen test stand-in (not the real unitree_sdk2). Process-wide state of the fake SDK:
// ChannelFactory init arguments, channels (writers' last message + count, readers' handlers),
// recurrent threads, MotionSwitcherClient behaviour. Guarded by mutexes; Write / delivery /
// ticking never allocate once warm.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <typeindex>
#include <typeinfo>
#include <vector>

namespace rhi_fake {
namespace detail {

constexpr std::size_t kMaxChannelReaders = 32;
constexpr std::size_t kMaxThreads = 64;

/// Last message written on a channel (type-erased base).
struct ChannelSlotBase
{
  explicit ChannelSlotBase(std::type_index t)
  : type(t) {}
  virtual ~ChannelSlotBase() = default;
  const std::type_index type;
  std::mutex mutex;
  std::uint64_t write_count = 0;   // under mutex
  bool has_value = false;          // under mutex
  // Test hook (rhi_fake::unitree::observe_writes): called with every message written, under mutex.
  std::function<void(const void *)> observer;
};

template<typename MSG>
struct ChannelSlot : ChannelSlotBase
{
  ChannelSlot()
  : ChannelSlotBase(std::type_index(typeid(MSG))) {}
  MSG last{};
};

/// One subscriber's receive endpoint.
struct ReaderEndpoint
{
  ReaderEndpoint(std::type_index t, std::function<void(const void *)> h, std::int64_t q)
  : type(t), handler(std::move(h)), queue_len(q) {}

  const std::type_index type;
  const std::function<void(const void *)> handler;   // may be empty (polling reader)
  const std::int64_t queue_len;
  /// Held while the handler runs; close() takes it, so no handler runs after close() returns.
  std::recursive_mutex mutex;
  bool open = true;                                  // under mutex
  std::shared_ptr<void> latest;                      // last delivered MSG (under mutex)
  bool has_latest = false;                           // under mutex
  std::int64_t last_data_time_us = 0;                // under mutex

  void close()
  {
    std::lock_guard<std::recursive_mutex> lock(mutex);
    open = false;
  }
};

struct ChannelRecord
{
  std::shared_ptr<ChannelSlotBase> slot;             // created by the first writer
  const char * type_name = "";
  std::size_t writers_created = 0;
  std::vector<std::weak_ptr<ReaderEndpoint>> readers;
};

/// One recurrent thread (CreateRecurrentThread[Ex]).
struct ThreadCore
{
  std::string name;
  std::int32_t cpu_id = -1;
  std::uint64_t interval_us = 0;
  bool real = false;
  std::function<void()> fn;
  std::recursive_mutex run_mutex;        // held while fn runs from a tick
  std::atomic<bool> stopped{false};
  std::atomic<std::uint64_t> runs{0};
  // real mode
  std::thread thread;
  std::mutex wait_mutex;
  std::condition_variable wait_cv;
  bool quit = false;                     // under wait_mutex
  bool finished = false;                 // under wait_mutex
  std::mutex join_mutex;                 // serializes join() between Wait() and the destructor
};

struct FactoryState
{
  std::uint64_t init_count = 0;
  bool inited = false;
  bool by_config_file = false;
  std::int32_t domain_id = -1;
  std::string network_interface;
  std::string config_file;
  std::uint64_t release_count = 0;
};

struct MotionSwitcherState
{
  std::string form;
  std::string name;
  std::int32_t check_result = 0;
  std::int32_t release_result = 0;
  bool release_clears_mode = true;
  std::uint64_t constructed = 0;
  std::uint64_t init_calls = 0;
  std::uint64_t set_timeout_calls = 0;
  double last_timeout_s = 0.0;
  std::uint64_t check_calls = 0;
  std::uint64_t release_calls = 0;
};

struct UnitreeRegistry
{
  std::mutex mutex;
  FactoryState factory;
  std::map<std::string, ChannelRecord, std::less<>> channels;
  std::vector<std::weak_ptr<ThreadCore>> threads;
  std::atomic<bool> real_threads{false};
  MotionSwitcherState motion;
};

inline UnitreeRegistry & unitree_registry()
{
  static UnitreeRegistry registry;
  return registry;
}

inline std::int64_t steady_now_us()
{
  return std::chrono::duration_cast<std::chrono::microseconds>(
    std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace detail
}  // namespace rhi_fake
