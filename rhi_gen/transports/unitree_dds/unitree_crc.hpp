// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_CRC_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_CRC_HPP_

// CRC32 of unitree_sdk2's low-level messages, bit-exact with the SDK's Crc32Core(): polynomial
// 0x04C11DB7, initial value 0xFFFFFFFF, the message read as 32-bit words in host (little-endian)
// order, each processed most significant bit first; no reflection, no final XOR; every word but
// the trailing crc.
//
// The SDK runs it over the raw memory of its structs, `(uint32_t *)&msg`, padding included, and
// the robot computes it with zero padding. Here the message's bytes are read through unsigned
// char and memcpy (no type punning), two words per step with slicing-by-8 tables, and every word
// is ANDed with a mask that keeps the bytes of declared fields and zeroes the padding bytes, whose
// content in a C++ object is unspecified. Masks come from each message's documented layout.
//
// On x86-64 CPUs with PCLMULQDQ (checked at run time) the bulk of the message is folded 128 bits
// at a time with carry-less multiplications (the same masked words, the same polynomial: the
// result is identical); the last words and every other CPU use the slicing-by-8 tables.

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define ROBOT_HARDWARE_INTERFACE_UNITREE_CRC_CLMUL 1
#include <immintrin.h>
#endif

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "unitree_sdk2 messages are CRC-protected in little-endian word order"
#endif

namespace robot_hardware_interface
{
namespace unitree_crc
{

constexpr uint32_t kPolynomial = 0x04C11DB7U;
constexpr uint32_t kInitialValue = 0xFFFFFFFFU;

// Bytes of declared fields: `count` runs of `length` bytes, `stride` apart, from `offset`.
struct FieldBytes
{
  size_t offset;
  size_t length;
  size_t count;
  size_t stride;
};

// Per CRC word, the bits of declared fields (host order: byte k of a word is bits 8k..8k+7).
template<size_t Words, size_t Fields>
constexpr std::array<uint32_t, Words> word_masks(const std::array<FieldBytes, Fields> & fields)
{
  std::array<uint32_t, Words> masks{};
  for (const FieldBytes & field : fields) {
    for (size_t run = 0; run < field.count; ++run) {
      for (size_t byte = 0; byte < field.length; ++byte) {
        const size_t at = field.offset + run * field.stride + byte;
        if (at < 4 * Words) {
          masks[at / 4] |= 0xFFU << (8 * (at % 4));
        }
      }
    }
  }
  return masks;
}

// Slicing-by-8 tables (MSB-first): kTables[k][b] is byte b carried over k + 1 bytes. Four tables
// advance the CRC by one 32-bit word, all eight by two.
constexpr std::array<std::array<uint32_t, 256>, 8> make_tables()
{
  std::array<std::array<uint32_t, 256>, 8> tables{};
  for (uint32_t byte = 0; byte < 256U; ++byte) {
    uint32_t crc = byte << 24;
    for (int bit = 0; bit < 8; ++bit) {
      crc = (crc & 0x80000000U) != 0U ? (crc << 1) ^ kPolynomial : (crc << 1);
    }
    tables[0][byte] = crc;
  }
  for (size_t k = 1; k < 8; ++k) {
    for (size_t byte = 0; byte < 256U; ++byte) {
      const uint32_t previous = tables[k - 1][byte];
      tables[k][byte] = (previous << 8) ^ tables[0][previous >> 24];
    }
  }
  return tables;
}

inline constexpr std::array<std::array<uint32_t, 256>, 8> kTables = make_tables();

inline uint32_t load_word(const unsigned char * bytes)
{
  uint32_t word = 0;
  std::memcpy(&word, bytes, sizeof(word));
  return word;
}

// The CRC continued from `crc` (the value after words [0, first)) over words [first, Words) of
// `bytes`, each ANDed with its mask: the portable slicing-by-8 implementation.
template<size_t Words>
uint32_t masked_crc_portable(
  uint32_t crc, const unsigned char * bytes, const std::array<uint32_t, Words> & masks,
  size_t first)
{
  const auto & t = kTables;
  size_t i = first;
  for (; i + 1 < Words; i += 2) {
    const uint32_t x = crc ^ (load_word(bytes + 4 * i) & masks[i]);
    const uint32_t y = load_word(bytes + 4 * i + 4) & masks[i + 1];
    crc = t[7][x >> 24] ^ t[6][(x >> 16) & 0xFFU] ^ t[5][(x >> 8) & 0xFFU] ^ t[4][x & 0xFFU] ^
      t[3][y >> 24] ^ t[2][(y >> 16) & 0xFFU] ^ t[1][(y >> 8) & 0xFFU] ^ t[0][y & 0xFFU];
  }
  if (i < Words) {
    const uint32_t x = crc ^ (load_word(bytes + 4 * i) & masks[i]);
    crc = t[3][x >> 24] ^ t[2][(x >> 16) & 0xFFU] ^ t[1][(x >> 8) & 0xFFU] ^ t[0][x & 0xFFU];
  }
  return crc;
}

#if defined(ROBOT_HARDWARE_INTERFACE_UNITREE_CRC_CLMUL)
// x^n mod the polynomial (32-bit remainder, MSB-first like the tables).
constexpr uint32_t power_of_x_mod(size_t n)
{
  uint32_t r = 1U;
  for (size_t k = 0; k < n; ++k) {
    r = (r & 0x80000000U) != 0U ? (r << 1) ^ kPolynomial : (r << 1);
  }
  return r;
}

inline constexpr std::array<uint32_t, 4> kAllBits{0xFFFFFFFFU, 0xFFFFFFFFU, 0xFFFFFFFFU,
  0xFFFFFFFFU};

inline bool cpu_has_clmul()
{
  static const bool has = (__builtin_cpu_init(), __builtin_cpu_supports("pclmul") != 0);
  return has;
}

// The same CRC with PCLMULQDQ: the message is the polynomial M (word 0 first, each word MSB
// first, word 0 XORed with the initial value) and the CRC is M * x^32 mod P. Blocks of four
// masked words (word 0 in the top 32 bits) are folded by Horner's rule, A <- A * x^128 + B,
// with A * x^128 = A_hi * x^192 + A_lo * x^128 replaced by the congruent
// A_hi * (x^192 mod P) + A_lo * (x^128 mod P). The folded A is then reduced by running its four
// words through the tables from 0, and the words after the last block continue from there.
template<size_t Words>
__attribute__((target("pclmul,sse2")))
uint32_t masked_crc_clmul(const unsigned char * bytes, const std::array<uint32_t, Words> & masks)
{
  constexpr size_t kBlocks = Words / 4;
  const __m128i fold = _mm_set_epi64x(
    static_cast<long long>(power_of_x_mod(128)),  // NOLINT(runtime/int): the intrinsic's type
    static_cast<long long>(power_of_x_mod(192)));  // NOLINT(runtime/int)
  const auto * data = reinterpret_cast<const __m128i *>(bytes);
  const auto * mask = reinterpret_cast<const __m128i *>(masks.data());
  // Lanes 0..3 hold words 0..3; 0x1B reverses them so that word 0 is the top 32 bits.
  __m128i acc = _mm_shuffle_epi32(
    _mm_and_si128(_mm_loadu_si128(data), _mm_loadu_si128(mask)), 0x1B);
  acc = _mm_xor_si128(acc, _mm_set_epi32(static_cast<int>(kInitialValue), 0, 0, 0));
  for (size_t b = 1; b < kBlocks; ++b) {
    const __m128i next = _mm_shuffle_epi32(
      _mm_and_si128(_mm_loadu_si128(data + b), _mm_loadu_si128(mask + b)), 0x1B);
    acc = _mm_xor_si128(
      _mm_xor_si128(_mm_clmulepi64_si128(acc, fold, 0x01), _mm_clmulepi64_si128(acc, fold, 0x10)),
      next);
  }
  std::array<uint32_t, 4> lanes{};
  _mm_storeu_si128(reinterpret_cast<__m128i *>(lanes.data()), acc);
  const std::array<uint32_t, 4> top_first{lanes[3], lanes[2], lanes[1], lanes[0]};
  const uint32_t crc = masked_crc_portable<4>(
    0U, reinterpret_cast<const unsigned char *>(top_first.data()), kAllBits, 0);
  return masked_crc_portable<Words>(crc, bytes, masks, 4 * kBlocks);
}
#endif

// CRC over the first Words 32-bit words of `bytes`, each ANDed with its mask.
template<size_t Words>
uint32_t masked_crc(const unsigned char * bytes, const std::array<uint32_t, Words> & masks)
{
#if defined(ROBOT_HARDWARE_INTERFACE_UNITREE_CRC_CLMUL)
  if (Words >= 8 && cpu_has_clmul()) {
    return masked_crc_clmul<Words>(bytes, masks);
  }
#endif
  return masked_crc_portable<Words>(kInitialValue, bytes, masks, 0);
}

// The value the trailing `crc` word of `message` must hold (the crc word itself is not covered).
template<typename Message, size_t Words>
uint32_t message_crc(const Message & message, const std::array<uint32_t, Words> & masks)
{
  static_assert(std::is_trivially_copyable<Message>::value, "the CRC covers the raw message");
  static_assert(std::is_standard_layout<Message>::value, "the CRC covers the raw message");
  static_assert(sizeof(Message) == 4 * (Words + 1), "the crc is the message's last 32-bit word");
  return masked_crc(reinterpret_cast<const unsigned char *>(&message), masks);
}

}  // namespace unitree_crc
}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_CRC_HPP_
