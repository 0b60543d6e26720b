// The one exception type for bad input files (point files, SVG paths, scene JSON): it names the file,
// the location inside it (a line number, a JSON path, a character offset) and what is wrong and expected,
// e.g.   shapes/cam.txt:14: expected two numbers "x y", got "1.5 abc"
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace rollkin::io {

/// A byte shown as an escape: "\n", "\r", "\t" or "\xNN" (for control characters and stray bytes).
inline std::string escaped_byte(unsigned char c) {
  if (c == '\n') return "\\n";
  if (c == '\r') return "\\r";
  if (c == '\t') return "\\t";
  const char* hex = "0123456789abcdef";
  return std::string("\\x") + hex[c >> 4] + hex[c & 15];
}

/// `text` as quoted inside a message: control characters escaped (escaped_byte) so that a message stays one
/// readable line, and cut after about `max` characters (at a UTF-8 character boundary) with "..."
/// appended, e.g. a 10^6-character line of a point file is shown by its first 80 characters.
inline std::string excerpt(std::string_view text, std::size_t max = 80) {
  std::string out;
  std::size_t i = 0;
  for (; i < text.size() && out.size() < max; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f) out += escaped_byte(c);
    else out += static_cast<char>(c);
  }
  // Do not end inside a UTF-8 sequence: finish the character (continuation bytes are 10xxxxxx).
  while (i < text.size() && (static_cast<unsigned char>(text[i]) & 0xc0) == 0x80) out += text[i++];
  if (i < text.size()) out += "...";
  return out;
}

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string location, std::string message)
      : std::runtime_error(compose(file, location, message)),
        file_(std::move(file)),
        location_(std::move(location)),
        message_(std::move(message)) {}

  const std::string& file() const { return file_; }
  const std::string& location() const { return location_; }
  const std::string& message() const { return message_; }

 private:
  /// "file:location: message", leaving out the parts that are empty. The file and location are shown by
  /// excerpt() (a location may be a JSON path hundreds of levels deep); the message is capped at a few
  /// dozen lines' length, as a last guard for any value quoted in it without excerpt().
  static std::string compose(const std::string& file, const std::string& location, const std::string& message) {
    std::string out = excerpt(file, 400);
    if (!location.empty()) out += (out.empty() ? "" : ":") + excerpt(location, 200);
    return out.empty() ? capped(message) : out + ": " + capped(message);
  }

  /// The message cut after kMaxMessage bytes (at a UTF-8 character boundary) with "...".
  static std::string capped(const std::string& message) {
    if (message.size() <= kMaxMessage) return message;
    std::size_t end = kMaxMessage;
    while (end > 0 && (static_cast<unsigned char>(message[end]) & 0xc0) == 0x80) --end;
    return message.substr(0, end) + "...";
  }

  static constexpr std::size_t kMaxMessage = 4000;

  std::string file_, location_, message_;
};

}  // namespace rollkin::io
