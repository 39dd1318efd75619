// Shared by the stand-ins' self-tests (selftest.cpp, selftest_vendor_msgs.cpp): heap allocation counting,
// the tiny check framework and waiting helpers. Each self-test is a binary of its own and includes this
// once (it replaces operator new).
#ifndef RHI_SELFTEST_SUPPORT_HPP_
#define RHI_SELFTEST_SUPPORT_HPP_

#include <rclcpp/executor.hpp>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <future>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

// ============================================================== allocation counting
namespace alloc {
std::atomic<long> count{0};
thread_local bool counting = false;
}  // namespace alloc

// noinline: once GCC inlines a replacement operator delete that calls free(), it reports a false
// -Wmismatched-new-delete at -O1 and above.
__attribute__((noinline)) void * operator new(std::size_t n)
{
  if (alloc::counting) {alloc::count.fetch_add(1, std::memory_order_relaxed);}
  if (void * p = std::malloc(n ? n : 1)) {return p;}
  throw std::bad_alloc();
}
__attribute__((noinline)) void * operator new[](std::size_t n)
{
  if (alloc::counting) {alloc::count.fetch_add(1, std::memory_order_relaxed);}
  if (void * p = std::malloc(n ? n : 1)) {return p;}
  throw std::bad_alloc();
}
__attribute__((noinline)) void operator delete(void * p) noexcept {std::free(p);}
__attribute__((noinline)) void operator delete[](void * p) noexcept {std::free(p);}
__attribute__((noinline)) void operator delete(void * p, std::size_t) noexcept {std::free(p);}
__attribute__((noinline)) void operator delete[](void * p, std::size_t) noexcept {std::free(p);}

/// Allocations made by `fn` on this thread.
template<typename F>
long allocations_in(F && fn)
{
  alloc::count.store(0);
  alloc::counting = true;
  fn();
  alloc::counting = false;
  return alloc::count.load();
}

// ============================================================== tiny check framework
static int g_failures = 0;
static int g_checks = 0;

#define CHECK(cond) \
  do { \
    ++g_checks; \
    if (!(cond)) { \
      ++g_failures; \
      std::fprintf(stderr, "CHECK FAILED %s:%d: %s\n", __FILE__, __LINE__, #cond); \
    } \
  } while (0)

#define CHECK_THROWS(Type, expr) \
  do { \
    ++g_checks; \
    bool rhi_thrown = false; \
    try {expr;} catch (const Type &) {rhi_thrown = true;} catch (...) {} \
    if (!rhi_thrown) { \
      ++g_failures; \
      std::fprintf(stderr, "CHECK FAILED %s:%d: %s did not throw %s\n", __FILE__, __LINE__, #expr, \
        #Type); \
    } \
  } while (0)

#define CHECK_NO_ALLOC(what, body) \
  do { \
    ++g_checks; \
    long rhi_n = allocations_in([&]() {body;}); \
    if (rhi_n != 0) { \
      ++g_failures; \
      std::fprintf(stderr, "CHECK FAILED %s:%d: %s made %ld heap allocation(s)\n", __FILE__, \
        __LINE__, what, rhi_n); \
    } \
  } while (0)

template<typename Pred>
bool eventually(Pred pred, std::chrono::milliseconds timeout = std::chrono::milliseconds(10000))
{
  auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!pred()) {
    if (std::chrono::steady_clock::now() > deadline) {return false;}
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

/// Cancels `exec` until its spin() thread reports it returned (a cancel() that races the start of
/// spin() is lost), at most `timeout`; false if it never returned (the join would then hang).
static bool stop_spinning(
  rclcpp::Executor & exec, const std::atomic<bool> & returned,
  std::chrono::milliseconds timeout = std::chrono::milliseconds(10000))
{
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!returned.load()) {
    if (std::chrono::steady_clock::now() > deadline) {return false;}
    exec.cancel();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

#endif  // RHI_SELFTEST_SUPPORT_HPP_
