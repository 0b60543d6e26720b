// Parsing of a whole JSON document (a scene file) into nlohmann::ordered_json, with the checks a JSON
// parser does not make by itself. Every problem is an InputError naming the file, the line:column of the
// character where it was found and the JSON path of the value (with array indices), e.g.
//
//   scene.json:7:31: duplicate key "radius" at links[1].contours[0].radius; each key may appear only once
//   scene.json:3:22: number 1e400 at links[0].contours[0].radius is out of the range of a double ...
//   scene.json:1:273: nested deeper than 256 levels at description[0][0]...; ...
//
// The document is built by a SAX handler over nlohmann's parser (which is iterative: its own stack is a
// std::vector), so no step recurses over the nesting: depth is bounded while parsing, before the deep part
// is ever built, and the bounded document is destroyed by nlohmann's iterative destructor.
#pragma once

#include "rollkin/io/input_error.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>

namespace rollkin::io {

/// Nesting depth of arrays and objects allowed in a document (the top-level value is depth 1). A scene
/// needs about 6; the bound keeps every consumer of the document away from deep recursion.
constexpr std::size_t kMaxJsonDepth = 256;

/// Parses `text` (the content of `file`, named in messages). Rejects, as InputError: malformed JSON, a key
/// repeated in one object, numbers outside the range of a double, nesting deeper than `max_depth`. The messages
/// point to `format`, the document describing the file (a scene's, or docs/synthesis.md for a synthesis spec).
nlohmann::ordered_json parse_json_document(const std::string& text, const std::string& file,
                                           std::size_t max_depth = kMaxJsonDepth,
                                           const std::string& format = "docs/scene_format.md");

/// Replaces the value at `path` of `document` (a JSON path as the scene's messages write it, e.g.
/// "links[1].contours[0].a": keys joined by '.', array indices in brackets) by `value`. Every step but the
/// last must exist; the last may also be a new key of an object (whoever reads the document then checks it).
/// A malformed path, a missing key or index, or a step into a value that is not an object or array is an
/// InputError naming `file` and `path`, what is there and what was expected.
void set_at_path(nlohmann::ordered_json& document, const std::string& path, nlohmann::ordered_json value,
                 const std::string& file);

}  // namespace rollkin::io
