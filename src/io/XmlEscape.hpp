#pragma once
// Private to the library: text escaped for double-quoted XML attribute values and for
// character data (apostrophes need no escape there).
#include <string>

namespace signorini::detail {

inline std::string xmlEscaped(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace signorini::detail
