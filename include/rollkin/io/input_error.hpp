// The one exception type for bad input files (point files, SVG paths, scene JSON): it names the file,
// the location inside it (a line number, a JSON path, a character offset) and what is wrong and expected,
// e.g.   shapes/cam.txt:14: expected two numbers "x y", got "1.5 abc"
#pragma once

#include <stdexcept>
#include <string>

namespace rollkin {

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
  /// "file:location: message", leaving out the parts that are empty.
  static std::string compose(const std::string& file, const std::string& location, const std::string& message) {
    std::string out = file;
    if (!location.empty()) out += (out.empty() ? "" : ":") + location;
    return out.empty() ? message : out + ": " + message;
  }

  std::string file_, location_, message_;
};

}  // namespace rollkin
