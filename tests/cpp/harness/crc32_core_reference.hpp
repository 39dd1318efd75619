// The SDK's Crc32Core, written independently of rhi-gen's templates (SDK_FACTS.md, sections A and
// D "CRC"): init 0xFFFFFFFF, polynomial 0x04C11DB7, 32-bit words MSB first, no reflection, no final
// XOR. Shared by the hg and go references (hg_crc_reference.hpp, go_crc_reference.hpp), plus the
// helpers their checks use: the CRC of a zero-padded mirror struct, of a message's raw bytes as
// they are (padding included), and message images filled with garbage or random bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <random>
#include <type_traits>

namespace rhi_ref {

inline uint32_t Crc32Core(const uint32_t* ptr, uint32_t len) {
  uint32_t xbit = 0;
  uint32_t data = 0;
  uint32_t CRC32 = 0xFFFFFFFF;
  const uint32_t dwPolynomial = 0x04c11db7;
  for (uint32_t i = 0; i < len; i++) {
    xbit = 1U << 31;
    data = ptr[i];
    for (uint32_t bits = 0; bits < 32; bits++) {
      if (CRC32 & 0x80000000U) {
        CRC32 <<= 1;
        CRC32 ^= dwPolynomial;
      } else {
        CRC32 <<= 1;
      }
      if (data & xbit) {
        CRC32 ^= dwPolynomial;
      }
      xbit >>= 1;
    }
  }
  return CRC32;
}

// Crc32Core over every 32-bit word of `raw` but the trailing crc (the SDK's `(sizeof >> 2) - 1`).
template <typename Raw>
inline uint32_t crc_of_raw(const Raw& raw) {
  static_assert(sizeof(Raw) % 4 == 0, "whole 32-bit words");
  uint32_t words[sizeof(Raw) / 4];
  std::memcpy(words, &raw, sizeof(Raw));
  return Crc32Core(words, static_cast<uint32_t>(sizeof(Raw) / 4 - 1));
}

// The CRC of a message's bytes exactly as they are in memory, padding included (what a CRC that
// forgets to zero the padding computes). Differs from the reference when the padding holds garbage.
template <typename Msg>
inline uint32_t raw_image_crc(const Msg& msg) {
  static_assert(std::is_trivially_copyable<Msg>::value, "raw message image");
  return crc_of_raw(msg);
}

// Fill every byte of `msg` (fields and padding) with `byte`: callers then set every field, so only
// the padding keeps the garbage. The messages are trivially copyable (stand-ins' static_asserts).
template <typename Msg>
inline void fill_garbage(Msg& msg, unsigned char byte = 0xA5) {
  static_assert(std::is_trivially_copyable<Msg>::value, "raw message image");
  std::memset(static_cast<void*>(&msg), byte, sizeof(Msg));
}

// Random bytes everywhere (fields and padding).
template <typename Msg>
inline void fill_random(Msg& msg, std::mt19937& rng) {
  static_assert(std::is_trivially_copyable<Msg>::value && sizeof(Msg) % 4 == 0, "raw message image");
  uint32_t words[sizeof(Msg) / 4];
  for (uint32_t& w : words) {
    w = static_cast<uint32_t>(rng());
  }
  std::memcpy(static_cast<void*>(&msg), words, sizeof(Msg));
}

}  // namespace rhi_ref
