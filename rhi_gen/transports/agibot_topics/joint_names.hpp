// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__JOINT_NAMES_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__JOINT_NAMES_HPP_

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace robot_hardware_interface
{

// The joint name every motor slot drives, for transports whose messages name their entries
// (AimDK's JointStateArray): "is this entry's name the joint of that slot?", answered in place
// without allocating or calling the library for names of typical length.
template<size_t N>
class JointNames
{
public:
  // Fixed once (configure()): `names[slot]` is the slot's joint name, "" where it drives none.
  void assign(const std::array<const char *, N> & names)
  {
    for (size_t slot = 0; slot < N; ++slot) {
      names_[slot] = names[slot];
      lengths_[slot] = std::strlen(names[slot]);
    }
  }

  // The slot drives a URDF joint.
  bool drives(size_t slot) const {return lengths_[slot] != 0U;}

  // `name` is the joint driven in `slot`: lengths first, then every byte, compared in place a
  // word at a time (first word, middle words, last word overlapping).
  bool matches(const std::string & name, size_t slot) const
  {
    const size_t size = name.size();
    if (size != lengths_[slot]) {
      return false;
    }
    const char * a = name.data();
    const char * b = names_[slot];
    if (size < sizeof(uint64_t)) {
      return std::memcmp(a, b, size) == 0;
    }
    const size_t last = size - sizeof(uint64_t);
    uint64_t difference =
      (load_word(a) ^ load_word(b)) | (load_word(a + last) ^ load_word(b + last));
    if (size > 2 * sizeof(uint64_t)) {  // the second word; typical joint names end within 24 bytes
      difference |= load_word(a + sizeof(uint64_t)) ^ load_word(b + sizeof(uint64_t));
      for (size_t i = 2 * sizeof(uint64_t); i < last; i += sizeof(uint64_t)) {
        difference |= load_word(a + i) ^ load_word(b + i);
      }
    }
    return difference == 0U;
  }

private:
  static uint64_t load_word(const char * bytes)
  {
    uint64_t word;
    std::memcpy(&word, bytes, sizeof(word));  // any alignment, no aliasing question
    return word;
  }

  std::array<const char *, N> names_{};  // each slot's joint name ("": not driven)
  std::array<size_t, N> lengths_{};      // strlen of each name (0: not driven)
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__JOINT_NAMES_HPP_
