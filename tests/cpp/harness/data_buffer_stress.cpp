// The generated DataBuffer<T> (common/data_buffer.hpp), on its own:
//   - contract: nullptr before the first set_data(); the newest frame afterwards; the frame a
//     consumer holds is never written by a producer until that consumer calls get_data() again;
//     no heap allocation in set_data()/get_data(); not copyable;
//   - stress: producers hand over RHI_STRESS_FRAMES frames (default 10^6) whose last field is a
//     checksum of the rest while one consumer takes them; the consumer re-verifies each frame
//     after holding it for a while. Torn frames (bad checksum), frames changed while held and
//     frames going backwards are counted: all must be zero. Run once with one producer and once
//     with two (the driver's command buffer has two: write() and the first-state callback).
// Meant to run under -fsanitize=thread (and plain / ASan+UBSan).
#include <atomic>
#include <chrono>
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <type_traits>
#include <vector>

#include "alloc_counter.hpp"
#include "check.hpp"
#include "robot_hardware_interface/common/data_buffer.hpp"

namespace {

using robot_hardware_interface::DataBuffer;
using robot_hardware_interface::Producers;

constexpr size_t kPayload = 30;

struct Frame {
  uint64_t seq{0};
  uint64_t producer{0};
  uint64_t payload[kPayload]{};
  uint64_t checksum{0};
};

uint64_t mix(uint64_t x) {
  x ^= x >> 33;
  x *= 0xff51afd7ed558ccdULL;
  x ^= x >> 33;
  x *= 0xc4ceb9fe1a85ec53ULL;
  x ^= x >> 33;
  return x;
}

uint64_t checksum_of(const Frame& f) {
  uint64_t h = mix(f.seq ^ (f.producer << 56));
  for (uint64_t v : f.payload) {
    h = mix(h ^ v);
  }
  return h;
}

void fill(Frame& f, uint64_t producer, uint64_t seq) {
  f.seq = seq;
  f.producer = producer;
  for (size_t i = 0; i < kPayload; ++i) {
    f.payload[i] = mix(seq * 131 + producer * 7 + i);
  }
  f.checksum = checksum_of(f);
}

bool intact(const Frame& f) {
  if (f.checksum != checksum_of(f)) {
    return false;
  }
  for (size_t i = 0; i < kPayload; ++i) {
    if (f.payload[i] != mix(f.seq * 131 + f.producer * 7 + i)) {
      return false;
    }
  }
  return true;
}

void test_contract() {
  rhi_check::Section section("contract");
  static_assert(!std::is_copy_constructible<DataBuffer<Frame>>::value, "DataBuffer must not be copyable");
  static_assert(!std::is_copy_assignable<DataBuffer<Frame>>::value, "DataBuffer must not be copy-assignable");
  static_assert(!std::is_copy_constructible<DataBuffer<Frame, Producers::kOne>>::value,
                "a single-producer DataBuffer must not be copyable either");
  auto buffer = std::make_unique<DataBuffer<Frame>>();
  CHECK(buffer->get_data() == nullptr, "get_data() before any set_data() is nullptr");
  CHECK(buffer->get_data() == nullptr, "still nullptr on the second call");

  Frame a, b, c, d;
  fill(a, 1, 1);
  fill(b, 1, 2);
  fill(c, 1, 3);
  fill(d, 1, 4);
  buffer->set_data(a);
  const Frame* p = buffer->get_data();
  CHECK(p != nullptr && p->seq == 1, "get_data() returns the frame written");
  const Frame* again = buffer->get_data();
  CHECK(again != nullptr && again->seq == 1 && intact(*again), "without new data get_data() keeps returning it");

  // The frame a consumer holds is not touched by any number of writes.
  const Frame* held = buffer->get_data();
  const Frame copy = *held;
  buffer->set_data(b);
  buffer->set_data(c);
  buffer->set_data(d);
  CHECK(std::memcmp(held, &copy, sizeof(Frame)) == 0, "three set_data() calls leave the held frame untouched");
  const Frame* newest = buffer->get_data();
  CHECK(newest != nullptr && newest->seq == 4 && intact(*newest), "get_data() then returns the newest frame");
  const Frame copy4 = *newest;
  buffer->set_data(a);
  CHECK(std::memcmp(newest, &copy4, sizeof(Frame)) == 0, "a write after get_data() leaves the new frame untouched");
  CHECK(buffer->get_data()->seq == 1, "and the next get_data() sees it");

  // No heap allocation on either side.
  const uint64_t allocs = rhi_alloc::count_in([&] {
    for (int i = 0; i < 1000; ++i) {
      buffer->set_data((i % 2) != 0 ? b : c);
      (void)buffer->get_data();
    }
  });
  CHECK_EQ(allocs, 0U, "heap allocations in 1000 set_data()/get_data()");
}

struct StressResult {
  uint64_t produced{0};
  uint64_t consumed{0};
  uint64_t torn{0};
  uint64_t changed_while_held{0};
  uint64_t backwards{0};
  uint64_t null_after_data{0};
};

// Buffer: DataBuffer<Frame> (any number of producers) or DataBuffer<Frame, Producers::kOne> (the
// state and IMU hand-offs: one producer thread, no mutex).
template <typename Buffer>
StressResult stress(int producers, uint64_t frames) {
  auto buffer = std::make_unique<Buffer>();
  std::atomic<int> done{0};
  std::atomic<uint64_t> produced{0};
  StressResult r;
  std::vector<std::thread> threads;
  const uint64_t per_producer = frames / static_cast<uint64_t>(producers);
  for (int p = 0; p < producers; ++p) {
    threads.emplace_back([&, p] {
      Frame f;
      for (uint64_t seq = 1; seq <= per_producer; ++seq) {
        fill(f, static_cast<uint64_t>(p), seq);
        buffer->set_data(f);
        produced.fetch_add(1, std::memory_order_relaxed);
      }
      done.fetch_add(1);
    });
  }
  std::vector<uint64_t> last_seq(static_cast<size_t>(producers), 0);
  bool seen_any = false;
  uint64_t last_frame_seq = 0;
  uint64_t last_frame_producer = ~0ULL;
  uint64_t spins = 0;
  while (true) {
    const bool finished = done.load() == producers;
    const Frame* f = buffer->get_data();
    if (f == nullptr) {
      r.null_after_data += seen_any ? 1U : 0U;
    } else {
      seen_any = true;
      const uint64_t seq = f->seq;
      const uint64_t producer = f->producer;
      const bool ok = intact(*f);
      const bool fresh = seq != last_frame_seq || producer != last_frame_producer;
      last_frame_seq = seq;
      last_frame_producer = producer;
      if (!ok) {
        ++r.torn;
      } else if (producer < last_seq.size()) {
        if (seq < last_seq[producer]) {
          ++r.backwards;
        }
        last_seq[producer] = seq;
      }
      r.consumed += fresh ? 1U : 0U;
      // Hold the frame for a while (every 8th one longer) and check nobody wrote into it.
      const int hold = (spins++ % 8) == 0 ? 2000 : 50;
      for (volatile int i = 0; i < hold; i = i + 1) {
      }
      if (ok && (f->seq != seq || f->producer != producer || !intact(*f))) {
        ++r.changed_while_held;
      }
    }
    if (finished) {
      break;
    }
  }
  for (auto& t : threads) {
    t.join();
  }
  // After the producers are done the newest frame is the last one of some producer.
  const Frame* last = buffer->get_data();
  bool last_ok = last != nullptr && intact(*last) && last->seq == per_producer;
  CHECK(last_ok, "after all producers finished, get_data() returns a final frame");
  r.produced = produced.load();
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  uint64_t frames = 1000000;
  if (const char* env = std::getenv("RHI_STRESS_FRAMES")) {
    frames = std::strtoull(env, nullptr, 10);
  }
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--frames=", 9) == 0) {
      frames = std::strtoull(argv[i] + 9, nullptr, 10);
    }
  }
  test_contract();
  for (int producers : {1, 2}) {
    rhi_check::Section section(producers == 1 ? "stress_1_producer" : "stress_2_producers");
    const auto start = std::chrono::steady_clock::now();
    const StressResult r = producers == 1 ? stress<DataBuffer<Frame, Producers::kOne>>(producers, frames)
                                          : stress<DataBuffer<Frame>>(producers, frames);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("stress %d producer(s): %" PRIu64 " hand-offs, %" PRIu64 " distinct frames consumed, torn %" PRIu64
                ", changed while held %" PRIu64 ", out of order %" PRIu64 " (%.0f ms)\n",
                producers, r.produced, r.consumed, r.torn, r.changed_while_held, r.backwards, ms);
    CHECK_EQ(r.produced, frames / static_cast<uint64_t>(producers) * static_cast<uint64_t>(producers),
             "frames handed over");
    CHECK(r.consumed > 0, "the consumer received frames");
    CHECK_EQ(r.torn, 0U, "torn frames (checksum mismatch)");
    CHECK_EQ(r.changed_while_held, 0U, "frames overwritten while the consumer held them");
    CHECK_EQ(r.backwards, 0U, "frames older than one already consumed (per producer)");
    CHECK_EQ(r.null_after_data, 0U, "nullptr after a frame had been delivered");
  }
  return rhi_check::summary();
}
