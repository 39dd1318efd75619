// rhi-gen test stand-in internals: a small XML reader for the ResourceManager and URDF parsing
// stand-ins (upstream uses tinyxml2 and urdfdom). Elements, attributes, text, self-closing tags,
// comments, <?...?> and <!DOCTYPE>, CDATA, the five named entities and &#N; / &#xN; (ASCII).
// Malformed input throws std::runtime_error, as a failed tinyxml2 parse makes upstream throw.
#pragma once

#include <cctype>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rhi_fake {
namespace detail {
namespace xml {

struct Element
{
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::vector<std::unique_ptr<Element>> children;
  std::string text;  // concatenated character data directly inside this element

  const std::string * attribute(const std::string & key) const
  {
    for (const auto & a : attributes) {
      if (a.first == key) {return &a.second;}
    }
    return nullptr;
  }

  const Element * first(const std::string & child_name) const
  {
    for (const auto & c : children) {
      if (c->name == child_name) {return c.get();}
    }
    return nullptr;
  }

  std::vector<const Element *> all(const std::string & child_name) const
  {
    std::vector<const Element *> out;
    for (const auto & c : children) {
      if (c->name == child_name) {out.push_back(c.get());}
    }
    return out;
  }
};

class Parser
{
public:
  explicit Parser(const std::string & text)
  : s_(text) {}

  std::unique_ptr<Element> document()
  {
    skip_misc();
    if (!starts("<")) {fail("no root element");}
    auto root = element();
    skip_misc();
    if (i_ != s_.size()) {fail("content after the root element");}
    return root;
  }

private:
  [[noreturn]] void fail(const std::string & what) const
  {
    throw std::runtime_error("invalid XML at offset " + std::to_string(i_) + ": " + what);
  }

  bool starts(const char * p) const {return s_.compare(i_, std::char_traits<char>::length(p), p) == 0;}

  void skip_ws() {while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) {++i_;}}

  void skip_until(const char * end)
  {
    const std::size_t at = s_.find(end, i_);
    if (at == std::string::npos) {fail(std::string("missing '") + end + "'");}
    i_ = at + std::char_traits<char>::length(end);
  }

  // Whitespace, comments, processing instructions and DOCTYPE outside elements.
  void skip_misc()
  {
    for (;;) {
      skip_ws();
      if (starts("<!--")) {skip_until("-->");}
      else if (starts("<?")) {skip_until("?>");}
      else if (starts("<!DOCTYPE")) {skip_until(">");}
      else {return;}
    }
  }

  std::string name()
  {
    const std::size_t begin = i_;
    while (i_ < s_.size()) {
      const unsigned char c = static_cast<unsigned char>(s_[i_]);
      if (std::isalnum(c) || c == '_' || c == '-' || c == ':' || c == '.') {++i_;} else {break;}
    }
    if (i_ == begin) {fail("expected a name");}
    return s_.substr(begin, i_ - begin);
  }

  std::string decode(const std::string & raw) const
  {
    std::string out;
    for (std::size_t k = 0; k < raw.size(); ) {
      if (raw[k] != '&') {
        out += raw[k++];
        continue;
      }
      const std::size_t semi = raw.find(';', k);
      if (semi == std::string::npos) {throw std::runtime_error("invalid XML: unterminated entity");}
      const std::string ent = raw.substr(k + 1, semi - k - 1);
      if (ent == "amp") {out += '&';}
      else if (ent == "lt") {out += '<';}
      else if (ent == "gt") {out += '>';}
      else if (ent == "quot") {out += '"';}
      else if (ent == "apos") {out += '\'';}
      else if (ent.size() > 1 && ent[0] == '#') {
        const bool hex = ent[1] == 'x' || ent[1] == 'X';
        const long code = std::stol(ent.substr(hex ? 2 : 1), nullptr, hex ? 16 : 10);
        if (code <= 0 || code > 127) {throw std::runtime_error("invalid XML: non-ASCII character reference");}
        out += static_cast<char>(code);
      } else {
        throw std::runtime_error("invalid XML: unknown entity &" + ent + ";");
      }
      k = semi + 1;
    }
    return out;
  }

  std::unique_ptr<Element> element()
  {
    ++i_;  // '<'
    auto e = std::make_unique<Element>();
    e->name = name();
    for (;;) {
      skip_ws();
      if (starts("/>")) {
        i_ += 2;
        return e;
      }
      if (starts(">")) {
        ++i_;
        break;
      }
      std::string key = name();
      skip_ws();
      if (!starts("=")) {fail("expected '=' after attribute " + key);}
      ++i_;
      skip_ws();
      if (i_ >= s_.size() || (s_[i_] != '"' && s_[i_] != '\'')) {fail("expected a quoted value");}
      const char quote = s_[i_++];
      const std::size_t end = s_.find(quote, i_);
      if (end == std::string::npos) {fail("unterminated attribute value");}
      if (e->attribute(key) != nullptr) {fail("duplicate attribute " + key);}
      e->attributes.emplace_back(key, decode(s_.substr(i_, end - i_)));
      i_ = end + 1;
    }
    for (;;) {
      if (i_ >= s_.size()) {fail("unterminated element <" + e->name + ">");}
      if (starts("</")) {
        i_ += 2;
        if (name() != e->name) {fail("mismatched end tag for <" + e->name + ">");}
        skip_ws();
        if (!starts(">")) {fail("expected '>'");}
        ++i_;
        return e;
      }
      if (starts("<!--")) {skip_until("-->");}
      else if (starts("<?")) {skip_until("?>");}
      else if (starts("<![CDATA[")) {
        const std::size_t begin = i_ + 9;
        skip_until("]]>");
        e->text += s_.substr(begin, i_ - 3 - begin);
      } else if (starts("<")) {
        e->children.push_back(element());
      } else {
        const std::size_t end = s_.find('<', i_);
        if (end == std::string::npos) {fail("unterminated element <" + e->name + ">");}
        e->text += decode(s_.substr(i_, end - i_));
        i_ = end;
      }
    }
  }

  const std::string & s_;
  std::size_t i_ = 0;
};

/// The root element of `text`; throws std::runtime_error if it is not well-formed XML.
inline std::unique_ptr<Element> parse(const std::string & text) {return Parser(text).document();}

/// `text` without leading/trailing whitespace.
inline std::string trim(const std::string & text)
{
  const std::size_t b = text.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) {return "";}
  const std::size_t e = text.find_last_not_of(" \t\r\n");
  return text.substr(b, e - b + 1);
}

}  // namespace xml
}  // namespace detail
}  // namespace rhi_fake
