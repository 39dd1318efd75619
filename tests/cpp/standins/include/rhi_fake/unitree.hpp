// rhi-gen test hooks for the fake unitree_sdk2 (test code only; drivers never include this).
// All functions are thread-safe. See tests/cpp/standins/README.md for the full contract.
#pragma once

#include <cxxabi.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <typeindex>
#include <vector>

#include "rhi_fake/detail/unitree_core.hpp"
#include "unitree/common/thread/recurrent_thread.hpp"
#include "unitree/robot/b2/motion_switcher/motion_switcher_client.hpp"
#include "unitree/robot/channel/channel_factory.hpp"
#include "unitree/robot/channel/channel_publisher.hpp"
#include "unitree/robot/channel/channel_subscriber.hpp"

namespace rhi_fake {
namespace unitree {

// ------------------------------------------------------------------ channels

/// Call the handler of every open subscriber of type MSG on `channel` with &msg (as `const void*`),
/// now, on this thread; also makes `msg` the subscriber's ReadLatest() value. Returns the number
/// of subscribers reached. Never allocates.
template<typename MSG>
std::size_t deliver(std::string_view channel, const MSG & msg)
{
  std::array<std::shared_ptr<::rhi_fake::detail::ReaderEndpoint>, ::rhi_fake::detail::kMaxChannelReaders>
  readers;
  std::size_t n = 0;
  {
    auto & reg = ::rhi_fake::detail::unitree_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    auto it = reg.channels.find(channel);
    if (it == reg.channels.end()) {return 0;}
    for (auto & weak : it->second.readers) {
      auto r = weak.lock();
      if (!r || r->type != std::type_index(typeid(MSG))) {continue;}
      if (n == readers.size()) {throw std::length_error("rhi_fake: too many channel readers");}
      readers[n++] = std::move(r);
    }
  }
  std::size_t reached = 0;
  for (std::size_t i = 0; i < n; ++i) {
    auto & r = *readers[i];
    std::lock_guard<std::recursive_mutex> lock(r.mutex);
    if (r.open) {
      *static_cast<MSG *>(r.latest.get()) = msg;
      r.has_latest = true;
      r.last_data_time_us = ::rhi_fake::detail::steady_now_us();
      if (r.handler) {r.handler(static_cast<const void *>(&msg));}
      ++reached;
    }
    readers[i].reset();
  }
  return reached;
}

/// The written side of `channel` (nullptr while no publisher has opened it).
inline std::shared_ptr<::rhi_fake::detail::ChannelSlotBase> written_slot(std::string_view channel)
{
  auto & reg = ::rhi_fake::detail::unitree_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  auto it = reg.channels.find(channel);
  return it == reg.channels.end() ? nullptr : it->second.slot;
}

/// Copy of the last message written on `channel`; false if none. Throws std::logic_error if the
/// channel's writers use another type.
template<typename MSG>
bool last_written(std::string_view channel, MSG & out)
{
  const auto slot = written_slot(channel);
  if (!slot) {return false;}
  if (slot->type != std::type_index(typeid(MSG))) {
    throw std::logic_error("rhi_fake: channel '" + std::string(channel) + "' carries another type");
  }
  auto & typed = static_cast<::rhi_fake::detail::ChannelSlot<MSG> &>(*slot);
  std::lock_guard<std::mutex> lock(typed.mutex);
  if (!typed.has_value) {return false;}
  out = typed.last;
  return true;
}

template<typename MSG>
std::optional<MSG> last_written(std::string_view channel)
{
  MSG out{};
  if (!last_written<MSG>(channel, out)) {return std::nullopt;}
  return out;
}

/// Number of successful Write() calls on `channel` (all publishers together).
inline std::uint64_t write_count(std::string_view channel)
{
  const auto slot = written_slot(channel);
  if (!slot) {return 0;}
  std::lock_guard<std::mutex> lock(slot->mutex);
  return slot->write_count;
}

/// Call `observer` with every message written on `channel` from now on (as `const void*`, on the
/// writing thread, under the channel's lock: it must not write to the channel); an empty function
/// stops observing. False when no publisher has opened the channel yet. The call allocates nothing.
inline bool observe_writes(std::string_view channel, std::function<void(const void *)> observer)
{
  const auto slot = written_slot(channel);
  if (!slot) {return false;}
  std::lock_guard<std::mutex> lock(slot->mutex);
  slot->observer = std::move(observer);
  return true;
}

struct ChannelInfo
{
  std::string name;               // e.g. "rt/lowcmd"
  std::string type_name;          // demangled C++ type, e.g. "unitree_hg::msg::dds_::LowCmd_"
  std::size_t writers_created;    // InitChannel() calls of publishers
  std::size_t open_readers;       // subscribers currently open
  std::vector<std::int64_t> reader_queue_lengths;   // queuelen of each open subscriber
  std::uint64_t write_count;
};

inline std::string demangle(const char * mangled)
{
  int status = 0;
  char * d = abi::__cxa_demangle(mangled, nullptr, nullptr, &status);
  std::string out = (status == 0 && d) ? d : mangled;
  std::free(d);
  return out;
}

/// Every channel created so far, sorted by name.
inline std::vector<ChannelInfo> channels()
{
  std::vector<ChannelInfo> out;
  std::vector<std::shared_ptr<::rhi_fake::detail::ChannelSlotBase>> slots;
  std::vector<std::vector<std::shared_ptr<::rhi_fake::detail::ReaderEndpoint>>> readers;
  {
    auto & reg = ::rhi_fake::detail::unitree_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    for (const auto & [name, record] : reg.channels) {
      out.push_back(ChannelInfo{name, demangle(record.type_name), record.writers_created, 0, {}, 0});
      slots.push_back(record.slot);
      readers.emplace_back();
      for (const auto & weak : record.readers) {
        if (auto r = weak.lock()) {readers.back().push_back(std::move(r));}
      }
    }
  }
  // reader / slot locks are taken without the registry lock (a handler may use the registry)
  for (std::size_t i = 0; i < out.size(); ++i) {
    for (auto & r : readers[i]) {
      std::lock_guard<std::recursive_mutex> rl(r->mutex);
      if (r->open) {
        out[i].open_readers++;
        out[i].reader_queue_lengths.push_back(r->queue_len);
      }
    }
    if (slots[i]) {
      std::lock_guard<std::mutex> lock(slots[i]->mutex);
      out[i].write_count = slots[i]->write_count;
    }
  }
  return out;
}

// ------------------------------------------------------------------ ChannelFactory

struct FactoryInit
{
  std::uint64_t init_count;       // Init() calls (either overload)
  bool inited;                    // Init() called and not Release()d
  bool by_config_file;            // last Init() was Init(configFileName)
  std::int32_t domain_id;         // last Init(domainId, ...) (-1 if never)
  std::string network_interface;  // last Init(domainId, networkInterface)
  std::string config_file;        // last Init(configFileName)
  std::uint64_t release_count;
};

inline FactoryInit factory_init()
{
  auto & reg = ::rhi_fake::detail::unitree_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  const auto & f = reg.factory;
  return FactoryInit{f.init_count, f.inited, f.by_config_file, f.domain_id, f.network_interface,
    f.config_file, f.release_count};
}

// ------------------------------------------------------------------ recurrent threads

struct ThreadInfo
{
  std::string name;           // name given to CreateRecurrentThreadEx ("" for CreateRecurrentThread)
  std::int32_t cpu_id;
  std::uint64_t interval_us;
  bool real;                  // runs on its own std::thread
  bool stopped;               // Wait() called or destroyed
  std::uint64_t runs;         // times the function ran (ticks or real iterations)
};

/// Live recurrent threads (creation order).
inline std::vector<ThreadInfo> threads()
{
  std::vector<ThreadInfo> out;
  auto & reg = ::rhi_fake::detail::unitree_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  for (auto & weak : reg.threads) {
    if (auto t = weak.lock()) {
      out.push_back(ThreadInfo{t->name, t->cpu_id, t->interval_us, t->real, t->stopped.load(),
          t->runs.load()});
    }
  }
  return out;
}

namespace detail_ {
inline std::size_t tick_matching(std::string_view name, bool all)
{
  std::array<std::shared_ptr<::rhi_fake::detail::ThreadCore>, ::rhi_fake::detail::kMaxThreads> ts;
  std::size_t n = 0;
  {
    auto & reg = ::rhi_fake::detail::unitree_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    for (auto & weak : reg.threads) {
      auto t = weak.lock();
      if (!t || t->real || t->stopped.load()) {continue;}
      if (!all && std::string_view(t->name) != name) {continue;}
      if (n == ts.size()) {throw std::length_error("rhi_fake: too many threads");}
      ts[n++] = std::move(t);
    }
  }
  std::size_t ran = 0;
  for (std::size_t i = 0; i < n; ++i) {
    auto & t = *ts[i];
    std::lock_guard<std::recursive_mutex> lock(t.run_mutex);
    if (!t.stopped.load()) {
      t.fn();
      t.runs.fetch_add(1);
      ++ran;
    }
    ts[i].reset();
  }
  return ran;
}
}  // namespace detail_

/// Run once, on this thread, the function of every live, not stopped, ticked (non-real) thread
/// named `name`. Returns how many ran (0 if none). Never allocates.
inline std::size_t tick_thread(std::string_view name)
{
  return detail_::tick_matching(name, false);
}

/// Same for every ticked thread.
inline std::size_t tick_all_threads()
{
  return detail_::tick_matching(std::string_view(), true);
}

/// Threads created from now on run for real (own std::thread, every interval) when `on`;
/// when off (default) they only run when ticked. Existing threads keep their mode.
inline void use_real_threads(bool on)
{
  ::rhi_fake::detail::unitree_registry().real_threads.store(on);
}

// ------------------------------------------------------------------ MotionSwitcherClient

/// What CheckMode(form, name) reports (default "", "": no high-level controller active).
inline void set_motion_mode(const std::string & form, const std::string & name)
{
  auto & reg = ::rhi_fake::detail::unitree_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  reg.motion.form = form;
  reg.motion.name = name;
}

/// Return codes of CheckMode / ReleaseMode (default 0), and whether ReleaseMode clears the mode.
inline void set_motion_switcher_behaviour(
  std::int32_t check_result, std::int32_t release_result, bool release_clears_mode)
{
  auto & reg = ::rhi_fake::detail::unitree_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  reg.motion.check_result = check_result;
  reg.motion.release_result = release_result;
  reg.motion.release_clears_mode = release_clears_mode;
}

struct MotionSwitcherStats
{
  std::uint64_t constructed;
  std::uint64_t init_calls;
  std::uint64_t set_timeout_calls;
  double last_timeout_s;       // SetTimeout(float s) -> s; SetTimeout(int64_t us) -> us * 1e-6
  std::uint64_t check_calls;
  std::uint64_t release_calls;
  std::string form;            // current fake mode
  std::string name;
};

inline MotionSwitcherStats motion_switcher()
{
  auto & reg = ::rhi_fake::detail::unitree_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  const auto & m = reg.motion;
  return MotionSwitcherStats{m.constructed, m.init_calls, m.set_timeout_calls, m.last_timeout_s,
    m.check_calls, m.release_calls, m.form, m.name};
}

// ------------------------------------------------------------------ reset

/// Forget channels, threads (registry entries only -- live RecurrentThread objects keep running
/// until destroyed), factory init state and motion-switcher state; real threads off.
/// Call only when no driver is alive.
inline void reset()
{
  auto & reg = ::rhi_fake::detail::unitree_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  reg.factory = ::rhi_fake::detail::FactoryState{};
  reg.channels.clear();
  reg.threads.clear();
  reg.real_threads.store(false);
  reg.motion = ::rhi_fake::detail::MotionSwitcherState{};
}

}  // namespace unitree
}  // namespace rhi_fake
