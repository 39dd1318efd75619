// A tiny check framework for the C++ harnesses (no gtest on these machines).
//
//   rhi_check::Section s("interfaces");        // groups the counts printed at the end
//   CHECK(cond, "printf format", args...);     // counts a pass or a failure (never aborts)
//   CHECK_EQ(a, b, "what");                    // numbers, bools, enums; prints both values
//   return rhi_check::summary();               // "rhi-check: N passed, M failed"; exit 1 if M > 0
//
// Output lines the pytest side parses:
//   "FAIL [section] file:line: message"      one per failed check
//   "section <name>: <p> passed, <f> failed"
//   "rhi-check: <p> passed, <f> failed"
// Checks never allocate when they pass (the message is only formatted on failure), so they may
// run right after an allocation-counting region without disturbing it.
#pragma once

#include <cinttypes>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <type_traits>

namespace rhi_check {

struct SectionStats {
  char name[48]{};
  uint64_t passed{0};
  uint64_t failed{0};
};

struct Registry {
  SectionStats sections[32];
  int count{0};
  int current{-1};
  uint64_t passed{0};
  uint64_t failed{0};
  int max_failures_printed{200};
};

inline Registry& registry() {
  static Registry r;
  return r;
}

inline void begin_section(const char* name) {
  Registry& r = registry();
  for (int i = 0; i < r.count; ++i) {
    if (std::strcmp(r.sections[i].name, name) == 0) {
      r.current = i;
      return;
    }
  }
  if (r.count < 32) {
    std::snprintf(r.sections[r.count].name, sizeof(r.sections[r.count].name), "%s", name);
    r.current = r.count++;
  }
  std::printf("--- %s\n", name);
  std::fflush(stdout);
}

inline const char* section_name() {
  const Registry& r = registry();
  return r.current >= 0 ? r.sections[r.current].name : "main";
}

// RAII: the section is current for the scope; the previous one is restored afterwards.
class Section {
public:
  explicit Section(const char* name) : previous_(registry().current) { begin_section(name); }
  ~Section() { registry().current = previous_; }
  Section(const Section&) = delete;
  Section& operator=(const Section&) = delete;

private:
  int previous_;
};

inline void pass() {
  Registry& r = registry();
  ++r.passed;
  if (r.current >= 0) {
    ++r.sections[r.current].passed;
  }
}

__attribute__((format(printf, 3, 4))) inline void fail(const char* file, int line, const char* fmt, ...) {
  Registry& r = registry();
  ++r.failed;
  if (r.current >= 0) {
    ++r.sections[r.current].failed;
  }
  if (r.failed > static_cast<uint64_t>(r.max_failures_printed)) {
    return;
  }
  const char* base = std::strrchr(file, '/');
  std::printf("FAIL [%s] %s:%d: ", section_name(), base ? base + 1 : file, line);
  va_list args;
  va_start(args, fmt);
  std::vprintf(fmt, args);
  va_end(args);
  std::printf("\n");
  std::fflush(stdout);
}

inline bool check(bool ok) {
  if (ok) {
    pass();
  }
  return ok;
}

// Value printing for CHECK_EQ (numbers, bools, enums, C strings).
inline void format_value(char* out, size_t n, double v) { std::snprintf(out, n, "%.17g", v); }
inline void format_value(char* out, size_t n, float v) { std::snprintf(out, n, "%.9g (float)", static_cast<double>(v)); }
inline void format_value(char* out, size_t n, bool v) { std::snprintf(out, n, "%s", v ? "true" : "false"); }
inline void format_value(char* out, size_t n, const char* v) { std::snprintf(out, n, "\"%s\"", v ? v : "(null)"); }
template <typename T>
inline void format_value(char* out, size_t n, const T& v) {
  if constexpr (std::is_enum<T>::value) {
    std::snprintf(out, n, "%lld (enum)", static_cast<long long>(v));
  } else if constexpr (std::is_signed<T>::value) {
    std::snprintf(out, n, "%lld", static_cast<long long>(v));
  } else {
    std::snprintf(out, n, "%llu (0x%llx)", static_cast<unsigned long long>(v), static_cast<unsigned long long>(v));
  }
}

template <typename A, typename B>
inline bool equal(const A& a, const B& b) {
  if constexpr (std::is_floating_point<A>::value || std::is_floating_point<B>::value) {
    // Exact comparison on purpose: values travel through known conversions only.
    return static_cast<double>(a) == static_cast<double>(b) ||
           (std::isnan(static_cast<double>(a)) && std::isnan(static_cast<double>(b)));
  } else if constexpr (std::is_enum<A>::value || std::is_enum<B>::value) {
    return a == b;
  } else if constexpr (std::is_integral<A>::value && std::is_integral<B>::value) {
    return static_cast<long double>(a) == static_cast<long double>(b);
  } else {
    return a == b;
  }
}

inline int summary() {
  const Registry& r = registry();
  for (int i = 0; i < r.count; ++i) {
    std::printf("section %s: %" PRIu64 " passed, %" PRIu64 " failed\n", r.sections[i].name,
                r.sections[i].passed, r.sections[i].failed);
  }
  std::printf("rhi-check: %" PRIu64 " passed, %" PRIu64 " failed\n", r.passed, r.failed);
  std::fflush(stdout);
  return r.failed == 0 && r.passed > 0 ? 0 : 1;
}

}  // namespace rhi_check

#define CHECK(cond, ...)                                   \
  do {                                                     \
    if (!::rhi_check::check(static_cast<bool>(cond))) {    \
      ::rhi_check::fail(__FILE__, __LINE__, __VA_ARGS__);  \
    }                                                      \
  } while (0)

#define CHECK_EQ(actual, expected, ...)                                                       \
  do {                                                                                        \
    const auto& rhi_a_ = (actual);                                                            \
    const auto& rhi_e_ = (expected);                                                          \
    if (!::rhi_check::check(::rhi_check::equal(rhi_a_, rhi_e_))) {                            \
      char rhi_as_[64];                                                                       \
      char rhi_es_[64];                                                                       \
      ::rhi_check::format_value(rhi_as_, sizeof(rhi_as_), rhi_a_);                            \
      ::rhi_check::format_value(rhi_es_, sizeof(rhi_es_), rhi_e_);                            \
      char rhi_what_[256];                                                                    \
      std::snprintf(rhi_what_, sizeof(rhi_what_), __VA_ARGS__);                               \
      ::rhi_check::fail(__FILE__, __LINE__, "%s: got %s, expected %s", rhi_what_, rhi_as_,    \
                        rhi_es_);                                                             \
    }                                                                                         \
  } while (0)
