// SVG documents, what is drawn (document.hpp, "display and visibility"): an element's own display and
// visibility properties (SVG 1.1, 11.5), from its presentation attributes and its style attribute, and the
// check that no <style> sheet sets them.
#include "document.hpp"

#include <cctype>

namespace rollkin::io::svg_detail {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// The value of the last declaration of `name` in a CSS declaration list ("a: b; c: d"), lower case, trimmed,
/// without "!important"; nullopt when it declares none.
std::optional<std::string> css_value(const std::string& declarations, const std::string& name) {
  std::optional<std::string> value;
  std::size_t start = 0;
  const std::string text = lower(declarations);
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    const std::string declaration = text.substr(start, end - start);
    const std::size_t colon = declaration.find(':');
    if (colon != std::string::npos && trimmed(declaration.substr(0, colon)) == name) {
      std::string v = trimmed(declaration.substr(colon + 1));
      if (const std::size_t bang = v.find('!'); bang != std::string::npos) v = trimmed(v.substr(0, bang));
      value = v;
    }
    start = end + 1;
  }
  return value;
}

/// The element's value of a property and where it comes from: its style attribute over its attribute.
std::optional<std::pair<std::string, std::string>> property(const pugi::xml_node& n, const std::string& name) {
  if (const auto v = css_value(n.attribute("style").value(), name)) return std::make_pair(*v, "style=\"" + name + ":" + *v + "\"");
  if (const pugi::xml_attribute a = n.attribute(name.c_str()))
    return std::make_pair(lower(trimmed(a.value())), name + "=\"" + trimmed(a.value()) + "\"");
  return std::nullopt;
}

}  // namespace

OwnRendering own_rendering(const pugi::xml_node& n, const Document& doc) {
  OwnRendering r;
  if (const auto d = property(n, "display"); d && d->first == "none") {
    r.display_none = true;
    r.display_why = d->second + " on " + doc.location(n);
  }
  if (const auto v = property(n, "visibility")) {
    if (v->first == "visible") r.visible = true;
    else if (v->first == "hidden" || v->first == "collapse") r.visible = false;
    else if (v->first != "inherit")
      doc.where(n).fail("has " + v->second + "; visibility is visible, hidden, collapse or inherit");
    if (r.visible) r.visibility_why = v->second + " on " + doc.location(n);
  }
  return r;
}

std::string css_rendering_property(const std::string& sheet) {
  // the declaration blocks of the sheet: what stands between braces
  for (std::size_t open = sheet.find('{'); open != std::string::npos; open = sheet.find('{', open + 1)) {
    const std::size_t close = std::min(sheet.find('}', open), sheet.size());
    const std::string block = sheet.substr(open + 1, close - open - 1);
    if (const auto v = css_value(block, "display"); v && *v == "none") return "display: none";
    if (const auto v = css_value(block, "visibility"); v && *v != "inherit") return "visibility: " + *v;
  }
  return "";
}

}  // namespace rollkin::io::svg_detail
