#pragma once
// Text in the SVG writers (private to io/): XML escaping and the number format of drawings.

#include <cstdio>
#include <string>

namespace penumbra::io {

// returns text with &, <, > and " escaped for XML content and attributes.
inline std::string escape_xml(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// returns a drawing coordinate or label with six significant digits ("%.6g").
inline std::string svg_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace penumbra::io
