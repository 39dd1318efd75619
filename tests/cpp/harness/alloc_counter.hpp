// Counting replacements of the global operator new / delete. Include in exactly ONE translation
// unit of a test binary (it defines the replacement functions).
//
//   const uint64_t n = rhi_alloc::count_in([&] { hw->read(t, dt); });   // heap allocations made
//
// Counting is process-wide (every thread but the driver's /diagnostics thread) while armed, so an
// allocation a hot path hands to another thread is caught too. The replacements are noinline: once GCC inlines a replacement operator
// delete that calls free(), it reports a false -Wmismatched-new-delete at -O1 and above.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>

#include <pthread.h>

namespace rhi_alloc {

inline std::atomic<bool> armed{false};
inline std::atomic<uint64_t> allocations{0};

template <typename F>
uint64_t count_in(F&& f) {
  const uint64_t before = allocations.load(std::memory_order_relaxed);
  armed.store(true, std::memory_order_seq_cst);
  f();
  armed.store(false, std::memory_order_seq_cst);
  return allocations.load(std::memory_order_relaxed) - before;
}

// The driver's /diagnostics thread ("rhi_diagnostics", common/driver_diagnostics.hpp) builds and
// publishes its messages off the hot paths and may allocate: its allocations are not counted.
inline bool counted_thread() {
  thread_local int counted = -1;  // -1: not asked yet
  if (counted < 0) {
    char name[16] = {};
    counted = pthread_getname_np(pthread_self(), name, sizeof(name)) == 0 &&
                      std::strcmp(name, "rhi_diagnostics") == 0
                  ? 0
                  : 1;
  }
  return counted == 1;
}

inline void note() {
  if (armed.load(std::memory_order_relaxed) && counted_thread()) {
    allocations.fetch_add(1, std::memory_order_relaxed);
  }
}

inline void* allocate(std::size_t n) {
  note();
  return std::malloc(n != 0 ? n : 1);
}

inline void* allocate_aligned(std::size_t n, std::size_t alignment) {
  note();
  void* p = nullptr;
  if (alignment < sizeof(void*)) {
    alignment = sizeof(void*);
  }
  if (posix_memalign(&p, alignment, n != 0 ? n : 1) != 0) {
    return nullptr;
  }
  return p;
}

}  // namespace rhi_alloc

__attribute__((noinline)) void* operator new(std::size_t n) {
  if (void* p = rhi_alloc::allocate(n)) {
    return p;
  }
  throw std::bad_alloc();
}
__attribute__((noinline)) void* operator new[](std::size_t n) {
  if (void* p = rhi_alloc::allocate(n)) {
    return p;
  }
  throw std::bad_alloc();
}
__attribute__((noinline)) void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  return rhi_alloc::allocate(n);
}
__attribute__((noinline)) void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  return rhi_alloc::allocate(n);
}
__attribute__((noinline)) void* operator new(std::size_t n, std::align_val_t a) {
  if (void* p = rhi_alloc::allocate_aligned(n, static_cast<std::size_t>(a))) {
    return p;
  }
  throw std::bad_alloc();
}
__attribute__((noinline)) void* operator new[](std::size_t n, std::align_val_t a) {
  if (void* p = rhi_alloc::allocate_aligned(n, static_cast<std::size_t>(a))) {
    return p;
  }
  throw std::bad_alloc();
}
__attribute__((noinline)) void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return rhi_alloc::allocate_aligned(n, static_cast<std::size_t>(a));
}
__attribute__((noinline)) void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return rhi_alloc::allocate_aligned(n, static_cast<std::size_t>(a));
}
__attribute__((noinline)) void operator delete(void* p) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete[](void* p) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete(void* p, std::size_t) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
