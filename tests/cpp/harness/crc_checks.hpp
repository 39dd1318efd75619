// CRC checks both unitree families' fakes run (check_crc_functions): every field counts, and the
// generated CRC (its fast and its portable path) equals the independent reference on frames
// whose padding is garbage. `generated`, `portable` and `reference` are the message's CRC
// functions (crc_probe.cpp and the family's *_crc_reference.hpp).
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <random>
#include <utility>
#include <vector>

#include "check.hpp"
#include "crc32_core_reference.hpp"

namespace rhi_test {

template <typename Msg>
using FieldChanges = std::vector<std::pair<const char*, std::function<void(Msg&)>>>;

// Changing any one field of `base` (whose padding is garbage, kept by the byte copy) changes the
// CRC, and both generated paths still equal the reference.
template <typename Msg, typename Generated, typename Portable, typename Reference>
void check_every_field_counts(const char* message, const Msg& base, const FieldChanges<Msg>& fields,
                              Generated generated, Portable portable, Reference reference) {
  const uint32_t base_crc = generated(base);
  for (const auto& [field, change] : fields) {
    Msg m;
    std::memcpy(static_cast<void*>(&m), static_cast<const void*>(&base), sizeof(m));
    change(m);
    CHECK(generated(m) != base_crc, "%s CRC covers %s", message, field);
    CHECK_EQ(generated(m), reference(m), "generated = reference after changing %s.%s", message, field);
    CHECK_EQ(portable(m), reference(m), "portable = reference after changing %s.%s", message, field);
  }
}

// `frames` random images, padding included: both generated paths equal the reference on every
// one. Returns how many frames' padding the reference could not tell apart from hashing it raw
// (0 when the random padding is visible, so a padding bug would show).
template <typename Msg, typename Generated, typename Portable, typename Reference>
int check_random_frames(const char* message, std::mt19937& rng, int frames, Generated generated,
                        Portable portable, Reference reference) {
  int mismatches = 0;
  int padding_invisible = 0;
  for (int k = 0; k < frames; ++k) {
    Msg m;
    rhi_ref::fill_random(m, rng);
    const uint32_t expected = reference(m);
    mismatches += (generated(m) != expected ? 1 : 0) + (portable(m) != expected ? 1 : 0);
    padding_invisible += rhi_ref::raw_image_crc(m) == expected ? 1 : 0;
  }
  CHECK_EQ(mismatches, 0, "random %s frames where generated or portable != reference (of %d)", message, frames);
  return padding_invisible;
}

}  // namespace rhi_test
