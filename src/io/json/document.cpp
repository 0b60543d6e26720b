#include "rollkin/io/json/document.hpp"
#include "rollkin/io/text_position.hpp"

#include "access.hpp"

#include <algorithm>
#include <iterator>
#include <unordered_set>
#include <utility>
#include <vector>

namespace rollkin::io {
namespace {

using json = nlohmann::ordered_json;

/// A char iterator over the text that publishes how far nlohmann's lexer has read, so that SAX events
/// (which carry no position) can be located: after an event, `*read_to` is one past the last character
/// the lexer consumed (the '{' or '[' of a start event, the closing quote of a key).
class TrackingIterator {
 public:
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  TrackingIterator(const char* at, const char** read_to) : at_(at), read_to_(read_to) {}
  reference operator*() const { return *at_; }
  TrackingIterator& operator++() {
    *read_to_ = ++at_;
    return *this;
  }
  TrackingIterator operator++(int) {
    TrackingIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const TrackingIterator& o) const { return at_ == o.at_; }
  bool operator!=(const TrackingIterator& o) const { return at_ != o.at_; }

 private:
  const char* at_;
  const char** read_to_;
};

/// 1-based "line:column" of the last character read when `consumed` characters have been read.
std::string line_column(const std::string& text, std::size_t consumed) {
  const auto [line, column] = line_column_at(text, consumed > 0 ? consumed - 1 : 0);
  return std::to_string(line) + ":" + std::to_string(column);
}

/// nlohmann's message without its "[json.exception...] parse error at line L, column C: " prefix.
std::string without_prefix(const std::string& what) {
  const std::size_t column = what.find("column ");
  const std::size_t from = column == std::string::npos ? what.find("] ") : what.find(": ", column);
  return from == std::string::npos ? what : what.substr(from + 2);
}

/// SAX handler building the document (the shape of nlohmann's own DOM builder: one pointer per open
/// container, values placed into the innermost one) with the JSON path, duplicate keys and depth tracked.
class DocumentBuilder {
 public:
  DocumentBuilder(const std::string& text, const std::string& file, std::size_t max_depth, const char* const& read_to,
                  const std::string& format)
      : text_(text), file_(file), format_(format), max_depth_(max_depth), read_to_(read_to) {}

  bool null() { return place(json(nullptr)); }
  bool boolean(bool b) { return place(json(b)); }
  bool number_integer(json::number_integer_t v) { return place(json(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return place(json(v)); }
  bool number_float(json::number_float_t v, const std::string& /*text*/) { return place(json(v)); }
  bool string(std::string& s) { return place(json(std::move(s))); }
  bool binary(json::binary_t& b) { return place(json::binary(std::move(b))); }  // not produced by JSON text

  bool start_object(std::size_t /*elements*/) { return open(json::value_t::object); }
  bool start_array(std::size_t /*elements*/) { return open(json::value_t::array); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(std::string& k) {
    Level& level = levels_.back();
    level.key = k;
    if (!level.keys.insert(k).second)
      fail(here(), "duplicate key \"" + excerpt(k) + "\" at " + path_of_next_value() +
                       "; each key may appear only once in an object");
    // Unique (checked above): append without ordered_map's linear search, which would make an object
    // of n keys cost n^2.
    auto& members = static_cast<std::vector<std::pair<const std::string, json>>&>(level.container->get_ref<json::object_t&>());
    members.emplace_back(std::move(k), json());
    element_ = &members.back().second;
    return true;
  }

  template <class Exception>
  bool parse_error(std::size_t position, const std::string& token, const Exception& e) {
    const std::string where = path_of_next_value();
    if (e.id == 406)  // nlohmann: out_of_range.406, a number that overflows a double
      fail(line_column(text_, position), "number " + excerpt(token) + (where.empty() ? "" : " at " + where) +
                                             " is out of the range of a double (magnitude above 1.8e308); expected "
                                             "a finite number (" + format_ + ")");
    fail(line_column(text_, position), "malformed JSON: " + excerpt(without_prefix(e.what()), 200) +
                                           (where.empty() ? "" : " (in " + where + ")") +
                                           "; expected valid JSON as described in " + format_);
  }

  json take() { return std::move(root_); }

 private:
  struct Level {
    json* container;
    std::string key;                        // objects: the key of the value being read
    std::unordered_set<std::string> keys;   // objects: keys seen so far
  };

  [[noreturn]] void fail(const std::string& location, const std::string& message) const {
    throw InputError(file_, location, message);
  }

  std::string here() const { return line_column(text_, static_cast<std::size_t>(read_to_ - text_.data())); }

  /// The JSON path of the value about to be placed, e.g. "links[1].contours[0].radius".
  std::string path_of_next_value() const {
    std::string path;
    for (std::size_t i = 0; i < levels_.size(); ++i) {
      const json& c = *levels_[i].container;
      const bool innermost = i + 1 == levels_.size();
      if (c.is_array())
        path += "[" + std::to_string(innermost ? c.size() : c.size() - 1) + "]";
      else
        path += (path.empty() ? "" : ".") + levels_[i].key;
    }
    return path;
  }

  /// Where the next value goes: the root, the slot a key made, or a new array element.
  json* slot() {
    if (levels_.empty()) return &root_;
    json& c = *levels_.back().container;
    if (c.is_array()) {
      c.get_ref<json::array_t&>().emplace_back();
      return &c.get_ref<json::array_t&>().back();
    }
    return element_;
  }

  bool place(json&& v) {
    *slot() = std::move(v);
    return true;
  }

  bool open(json::value_t type) {
    if (levels_.size() + 1 > max_depth_)
      fail(here(), "arrays and objects nested deeper than " + std::to_string(max_depth_) + " levels at " +
                       excerpt(path_of_next_value()) + "; expected a scene nested a few levels deep");
    json* c = slot();
    *c = json(type);
    levels_.push_back(Level{c, {}, {}});
    return true;
  }

  bool close() {
    levels_.pop_back();
    return true;
  }

  const std::string& text_;
  const std::string& file_;
  const std::string& format_;  // the document describing the format, for messages
  std::size_t max_depth_;
  const char* const& read_to_;
  json root_;
  json* element_ = nullptr;
  std::vector<Level> levels_;
};

}  // namespace

nlohmann::ordered_json parse_json_document(const std::string& text, const std::string& file, std::size_t max_depth,
                                           const std::string& format) {
  const char* read_to = text.data();
  DocumentBuilder builder(text, file, max_depth, read_to, format);
  const TrackingIterator first(text.data(), &read_to), last(text.data() + text.size(), &read_to);
  json::sax_parse(first, last, &builder);  // errors throw from the builder
  return builder.take();
}

namespace {

/// One step of a JSON path: a key of an object, or an index of an array.
struct PathStep {
  bool is_index = false;
  std::string key;
  std::size_t index = 0;
};

/// The steps of "a.b[2][0].c"; an empty vector when the path is malformed.
std::vector<PathStep> path_steps(const std::string& path) {
  std::vector<PathStep> steps;
  std::size_t i = 0;
  const std::size_t n = path.size();
  while (i < n) {
    if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos || close == i + 1) return {};
      PathStep s;
      s.is_index = true;
      for (std::size_t k = i + 1; k < close; ++k) {
        if (path[k] < '0' || path[k] > '9' || s.index > 100000000) return {};
        s.index = s.index * 10 + static_cast<std::size_t>(path[k] - '0');
      }
      steps.push_back(s);
      i = close + 1;
      if (i < n && path[i] != '.' && path[i] != '[') return {};
      if (i < n && path[i] == '.' && ++i == n) return {};
      continue;
    }
    const std::size_t end = path.find_first_of(".[]", i);
    const std::size_t stop = end == std::string::npos ? n : end;
    if (stop == i || (end != std::string::npos && path[end] == ']')) return {};
    PathStep s;
    s.key = path.substr(i, stop - i);
    steps.push_back(s);
    i = stop;
    if (i < n && path[i] == '.' && ++i == n) return {};
  }
  return steps;
}

}  // namespace

void set_at_path(json& document, const std::string& path, json value, const std::string& file) {
  const std::vector<PathStep> steps = path_steps(path);
  if (steps.empty())
    throw InputError(file, path, "not a JSON path; expected keys joined by '.' with array indices in brackets, "
                                 "e.g. \"links[1].contours[0].a\"");
  json* at = &document;
  std::string where;  // the path walked so far ("" = the document)
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const PathStep& s = steps[k];
    const bool last = k + 1 == steps.size();
    const std::string here = where.empty() ? "the document" : where;
    if (s.is_index) {
      if (!at->is_array())
        throw InputError(file, path, here + " is " + kind_of(*at) + ", not an array; there is no [" + std::to_string(s.index) + "]");
      if (s.index >= at->size())
        throw InputError(file, path, "no element [" + std::to_string(s.index) + "]: " + here + " has " +
                                         std::to_string(at->size()) + " element(s)");
      where = index(where, s.index);
      at = &(*at)[s.index];
    } else {
      if (!at->is_object())
        throw InputError(file, path, here + " is " + kind_of(*at) + ", not an object; there is no key \"" + s.key + "\"");
      if (!last && !at->contains(s.key)) {
        std::vector<std::string> keys;
        for (auto it = at->begin(); it != at->end(); ++it) keys.push_back(it.key());
        throw InputError(file, path, "no key \"" + s.key + "\" in " + here + "; its keys are " + quoted_list(keys));
      }
      where = child(where, s.key);
      at = &(*at)[s.key];
    }
  }
  *at = std::move(value);
}

}  // namespace rollkin::io
