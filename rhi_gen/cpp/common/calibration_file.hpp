// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__CALIBRATION_FILE_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__CALIBRATION_FILE_HPP_

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "robot_hardware_interface/common/hardware_parameters.hpp"

namespace robot_hardware_interface
{

// A joint's calibration: added to its generated zero offset, multiplied with its direction.
struct CalibrationEntry
{
  std::string joint;
  double offset{0.0};     // [rad or m]
  double direction{1.0};  // +1 or -1
  size_t line{0};
};

// The largest calibration offset accepted: one turn. More is a unit mistake (degrees, encoder
// ticks), never a re-zeroed motor.
constexpr double kMaxCalibrationOffset = 6.283185307179586;

// The `calibration_file` hardware parameter: per-joint offsets (and directions) read at
// on_configure, so that re-zeroing a motor needs no rebuild. The format is the YAML subset
//
//   # comment
//   left_knee_joint: {offset: 0.0123}
//   right_knee_joint:
//     offset: -0.004
//     direction: -1
//
// (top-level keys are joint names, plain or quoted). Anything else is refused with one line.
class CalibrationFile
{
public:
  // Reads `path`: false with error() set ("calibration_file '<path>' line <n>: ... -> <fix>").
  bool read(const std::string & path)
  {
    path_ = path;
    entries_.clear();
    std::ifstream file(path);
    if (!file) {
      return fail(0, "cannot be read", "give the path of a readable file, or no calibration_file");
    }
    std::string line;
    size_t number = 0;
    CalibrationEntry * block = nullptr;
    bool block_has_key = false;
    while (std::getline(file, line)) {
      ++number;
      std::string_view text = without_comment(line);
      if (trimmed(text).empty() || (number == 1 && trimmed(text) == "---")) {
        continue;
      }
      if (text.find('\t') != std::string_view::npos) {
        return fail(number, "a tab character", "indent with spaces (YAML forbids tabs)");
      }
      const size_t indent = text.find_first_not_of(' ');
      std::string key;
      std::string_view value;
      if (!split_key(trimmed(text), key, value)) {
        return fail(number, "expected '<joint>: {offset: <rad>, direction: <1|-1>}'",
                 "see docs/transmissions.md, Calibration without regeneration");
      }
      if (indent > 0) {
        if (block == nullptr) {
          return fail(number, "'" + key + "' is indented but belongs to no joint",
                   "start the line at column 1 with a joint name");
        }
        if (!set_value(*block, key, value, number)) {
          return false;
        }
        block_has_key = true;
        continue;
      }
      if (block != nullptr && !block_has_key) {
        return fail(block->line, "joint '" + block->joint + "' has no offset or direction",
                 "give it 'offset: <rad>' or remove it");
      }
      for (const CalibrationEntry & entry : entries_) {
        if (entry.joint == key) {
          return fail(number, "joint '" + key + "' is given twice (first on line " +
                   std::to_string(entry.line) + ")", "keep one entry per joint");
        }
      }
      entries_.push_back(CalibrationEntry{key, 0.0, 1.0, number});
      block = &entries_.back();
      block_has_key = false;
      if (value.empty()) {
        continue;
      }
      if (value.front() != '{' || value.back() != '}') {
        return fail(number, "joint '" + key + "': expected a mapping such as {offset: 0.01}",
                 "write '" + key + ": {offset: <rad>}'");
      }
      if (!read_flow(*block, value.substr(1, value.size() - 2), number)) {
        return false;
      }
      block_has_key = true;
    }
    if (block != nullptr && !block_has_key) {
      return fail(block->line, "joint '" + block->joint + "' has no offset or direction",
               "give it 'offset: <rad>' or remove it");
    }
    return true;
  }

  const std::vector<CalibrationEntry> & entries() const {return entries_;}
  const std::string & error() const {return error_;}

  // One line naming the file, the line and the fix, for a problem the caller found in an entry.
  std::string describe(size_t line, const std::string & problem, const std::string & fix) const
  {
    std::ostringstream out;
    out << "calibration_file '" << path_ << "'";
    if (line > 0) {
      out << " line " << line;
    }
    out << ": " << problem << " -> " << fix;
    return out.str();
  }

private:
  bool fail(size_t line, const std::string & problem, const std::string & fix)
  {
    error_ = describe(line, problem, fix);
    return false;
  }

  // The line without a YAML comment ('#' at the start or after a space, outside quotes).
  static std::string_view without_comment(std::string_view line)
  {
    char quote = '\0';
    for (size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      if (quote != '\0') {
        quote = c == quote ? '\0' : quote;
      } else if (c == '\'' || c == '"') {
        quote = c;
      } else if (c == '#' && (i == 0 || line[i - 1] == ' ')) {
        return line.substr(0, i);
      }
    }
    const size_t end = line.find_last_not_of("\r");
    return end == std::string_view::npos ? std::string_view{} : line.substr(0, end + 1);
  }

  // "key: value" (the key plain or quoted); false when there is no such colon.
  static bool split_key(std::string_view text, std::string & key, std::string_view & value)
  {
    size_t colon = std::string_view::npos;
    if (!text.empty() && (text.front() == '\'' || text.front() == '"')) {
      const size_t close = text.find(text.front(), 1);
      if (close == std::string_view::npos || close + 1 >= text.size() || text[close + 1] != ':') {
        return false;
      }
      key = std::string(text.substr(1, close - 1));
      colon = close + 1;
    } else {
      colon = text.find(": ");
      if (colon == std::string_view::npos && !text.empty() && text.back() == ':') {
        colon = text.size() - 1;
      }
      if (colon == std::string_view::npos) {
        return false;
      }
      key = std::string(trimmed(text.substr(0, colon)));
    }
    value = trimmed(text.substr(colon + 1));
    return !key.empty();
  }

  bool read_flow(CalibrationEntry & entry, std::string_view items, size_t line)
  {
    while (!trimmed(items).empty()) {
      const size_t comma = items.find(',');
      const std::string_view item = trimmed(items.substr(0, comma));
      std::string key;
      std::string_view value;
      if (!split_key(item, key, value) || value.empty()) {
        return fail(line, "joint '" + entry.joint + "': '" + std::string(item) +
                 "' is not 'offset: <rad>' or 'direction: <1|-1>'", "write {offset: 0.01}");
      }
      if (!set_value(entry, key, value, line)) {
        return false;
      }
      items = comma == std::string_view::npos ? std::string_view{} : items.substr(comma + 1);
    }
    return true;
  }

  bool set_value(
    CalibrationEntry & entry, const std::string & key, std::string_view text, size_t line)
  {
    const std::string joint = "joint '" + entry.joint + "': ";
    double value = 0.0;
    if (key != "offset" && key != "direction") {
      return fail(line, joint + "unknown key '" + key + "'", "use offset and direction only");
    }
    if (!parse_number(text, value)) {
      return fail(line, joint + key + " '" + std::string(text) + "' is not a finite number",
               "write a number such as 0.01");
    }
    if (key == "direction") {
      if (value != 1.0 && value != -1.0) {
        return fail(line, joint + "direction " + std::string(text) + " is not 1 or -1",
                 "use -1 for a motor mounted the other way round, 1 otherwise");
      }
      entry.direction = value;
      return true;
    }
    if (std::fabs(value) > kMaxCalibrationOffset) {
      return fail(line, joint + "offset " + std::string(text) + " is beyond one turn (6.2832)",
               "give the offset in rad (or m), not degrees or encoder ticks");
    }
    entry.offset = value;
    return true;
  }

  static bool parse_number(std::string_view text, double & value)
  {
    const std::string number(trimmed(text));
    if (number.empty()) {
      return false;
    }
    char * end = nullptr;
    value = std::strtod(number.c_str(), &end);
    return end == number.c_str() + number.size() && std::isfinite(value);
  }

  std::string path_;
  std::vector<CalibrationEntry> entries_;
  std::string error_;
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__CALIBRATION_FILE_HPP_
