#include "rollkin/io/svg/markup.hpp"

#include "rollkin/io/format.hpp"
#include "rollkin/io/input_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rollkin::io {

const std::vector<std::string>& default_palette() {
  static const std::vector<std::string> p = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                             "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  return p;
}

const std::string& palette_color(std::size_t i) { return default_palette()[i % default_palette().size()]; }

namespace {

/// Length of the valid UTF-8 character at text[i] that XML 1.0 allows (no U+FFFE, U+FFFF, surrogates),
/// or 0 if the bytes there are not one.
std::size_t xml_char_length(const std::string& text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u; };
  const unsigned c = byte(i);
  const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
  if (n == 0) return 0;
  unsigned long cp = n == 1 ? c : n == 2 ? (c & 0x1f) : n == 3 ? (c & 0x0f) : (c & 0x07);
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3f);
  }
  const unsigned long smallest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < smallest[n] || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff) || cp == 0xfffe || cp == 0xffff) return 0;
  return n;
}

}  // namespace

std::string xml_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    const std::size_t n = xml_char_length(text, i);
    // Control characters (not allowed in XML 1.0, even as references) and bytes that are not UTF-8 are
    // shown as escapes (\n, \x01, \xff) so that the document stays well-formed XML.
    if (n == 0 || static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      out += escaped_byte(static_cast<unsigned char>(c));
      ++i;
      continue;
    }
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out.append(text, i, n);
    }
    i += n;
  }
  return out;
}

std::string svg_pixel(double v) {
  if (!std::isfinite(v)) v = 0;
  v = std::clamp(v, -1e7, 1e7);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string s = buf;
  if (s == "-0.00") s = "0.00";
  return s;
}

std::string svg_size(double v) { return format_number(v, 4); }

std::string svg_document_open(int w, int h) {
  return std::string("<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n") +
         "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + std::to_string(w) + "\" height=\"" +
         std::to_string(h) + "\" viewBox=\"0 0 " + std::to_string(w) + " " + std::to_string(h) +
         "\" font-family=\"Helvetica, Arial, sans-serif\">\n";
}

}  // namespace rollkin::io
