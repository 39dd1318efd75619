// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__DATA_BUFFER_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__DATA_BUFFER_HPP_

#include <array>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <type_traits>

namespace robot_hardware_interface
{

// Who calls set_data(): any number of threads (a mutex orders them), or one producer whose calls
// are already ordered with each other (a single callback thread: no mutex needed).
enum class Producers
{
  kMany,
  kOne,
};

// Zero-allocation hand-off of the newest complete frame from producer threads (SDK / topic
// callbacks, write()) to ONE consumer thread (read(), the command writer).
//
// A triple buffer: three pre-allocated slots, each owned by exactly one side at any time.
//   - back_   : the slot producers copy into (guarded by write_mutex_, which is held only for the
//               copy, so the consumer never waits on it);
//   - front_  : the slot the consumer is reading (owned by the consumer, never written by a
//               producer until the consumer calls get_data() again);
//   - middle_ : the newest complete frame, handed over with one atomic exchange.
// A producer publishes by swapping back_ with middle_; the consumer picks up a new frame by
// swapping front_ with middle_. The exchanges are acq_rel, so a slot's contents are fully written
// before the other side can see its index: no torn frames, no locks on the consumer side.
template<typename T, Producers kProducers = Producers::kMany>
class DataBuffer
{
  static_assert(std::is_copy_assignable<T>::value, "DataBuffer<T> copies frames by assignment");

public:
  DataBuffer() = default;
  DataBuffer(const DataBuffer &) = delete;
  DataBuffer & operator=(const DataBuffer &) = delete;

  // Producer side: copy `data` into the back slot and publish it as the newest frame.
  // Producers::kMany: any number of producer threads, serialised by a mutex held only for this
  // copy (or fill). Producers::kOne: the caller guarantees its calls never overlap.
  void set_data(const T & data)
  {
    if constexpr (kProducers == Producers::kMany) {
      std::lock_guard<std::mutex> lock(write_mutex_);
      slots_[back_] = data;
      publish();
    } else {
      slots_[back_] = data;
      publish();
    }
  }

  // Producer side, in place: `fill(slot)` writes the new frame straight into the back slot, which
  // is then published like a copy set_data() made (same ordering of producers). The slot holds an
  // older frame: `fill` must write all of it. Spares the copy of a frame built elsewhere.
  template<typename Fill>
  void fill_data(Fill && fill)
  {
    if constexpr (kProducers == Producers::kMany) {
      std::lock_guard<std::mutex> lock(write_mutex_);
      fill(slots_[back_]);
      publish();
    } else {
      fill(slots_[back_]);
      publish();
    }
  }

  // Consumer side (one thread only): the newest complete frame, or nullptr if set_data() was
  // never called. The pointed-to slot stays untouched by producers until the next get_data().
  const T * get_data()
  {
    if ((middle_.load(std::memory_order_relaxed) & kFreshBit) != 0U) {
      const uint8_t previous = middle_.exchange(front_, std::memory_order_acq_rel);
      front_ = static_cast<uint8_t>(previous & kIndexMask);
      has_data_ = true;
    }
    return has_data_ ? &slots_[front_] : nullptr;
  }

private:
  // Swap the back slot, just written, with the middle one (under the producers' ordering).
  void publish()
  {
    const auto published = static_cast<uint8_t>(back_ | kFreshBit);
    const uint8_t previous = middle_.exchange(published, std::memory_order_acq_rel);
    back_ = static_cast<uint8_t>(previous & kIndexMask);
  }

  static constexpr uint8_t kIndexMask = 0x3U;
  static constexpr uint8_t kFreshBit = 0x4U;  // set in middle_ when it holds an unread frame

  std::array<T, 3> slots_{};
  std::mutex write_mutex_;
  uint8_t back_{0};                 // producers only, under write_mutex_
  std::atomic<uint8_t> middle_{1};  // shared: slot index | kFreshBit
  uint8_t front_{2};                // consumer only
  bool has_data_{false};            // consumer only
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__DATA_BUFFER_HPP_
