// rhi-gen test stand-in (not the real ROS 2 code): the string conversions of ros2_control 4.x+
// that the stand-ins use (stod, to_lower_case, parse_bool), header-only. Like upstream, stod
// accepts only a whole number in the "C" locale and throws std::invalid_argument otherwise.
#ifndef HARDWARE_INTERFACE__LEXICAL_CASTS_HPP_
#define HARDWARE_INTERFACE__LEXICAL_CASTS_HPP_

#include <algorithm>
#include <cctype>
#include <locale>
#include <sstream>
#include <stdexcept>
#include <string>

namespace hardware_interface
{
inline double stod(const std::string & s)
{
  std::istringstream stream(s);
  stream.imbue(std::locale::classic());
  double result = 0.0;
  stream >> result;
  if (stream.fail() || !stream.eof()) {
    throw std::invalid_argument("Failed converting string to real number");
  }
  return result;
}

inline std::string to_lower_case(const std::string & string)
{
  std::string lower = string;
  std::transform(
    lower.begin(), lower.end(), lower.begin(),
    [](unsigned char c) {return static_cast<char>(std::tolower(c));});
  return lower;
}

inline bool parse_bool(const std::string & bool_string)
{
  const std::string lower = to_lower_case(bool_string);
  if (lower == "true") {
    return true;
  }
  if (lower == "false") {
    return false;
  }
  throw std::invalid_argument(
          "Input string : '" + bool_string +
          "' is not a valid boolean value. Expected 'true' or 'false'.");
}
}  // namespace hardware_interface

#endif  // HARDWARE_INTERFACE__LEXICAL_CASTS_HPP_
