// Where a byte offset falls in a text file, for the messages of the readers of text formats (JSON, SVG).
#pragma once

#include <cstddef>
#include <string_view>
#include <utility>

namespace rollkin::io {

/// 1-based line and column of the character at byte `offset` of `text` (offsets past the end give the position
/// after the last character).
inline std::pair<std::size_t, std::size_t> line_column_at(std::string_view text, std::size_t offset) {
  std::size_t line = 1, column = 1;
  const std::size_t end = offset < text.size() ? offset : text.size();
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

}  // namespace rollkin::io
