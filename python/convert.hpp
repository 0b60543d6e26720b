// Python values <-> the JSON of a scene document, and NumPy arrays of text, for the Python module `rollkin`
// (python/convert.cpp): a dict given to rollkin.scene() or an override becomes the JSON the scene reader
// reads, with its messages in the same form (JSON path of a bad value).
#pragma once
#include "io/json/access.hpp"  // child(), index(), kind_of() of the scene reader's messages (src/io)

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <string>

namespace py = pybind11;

namespace rollkin::python {

using io::json;

/// A Python value as JSON (dict, list/tuple, str, int, float, bool, None; NumPy arrays and scalars through
/// their tolist()). What JSON cannot hold (NaN, infinities, other types, nesting deeper than the scene reader
/// allows) is an InputError naming `file` and the value's JSON path.
json to_json(py::handle v, const std::string& path, const std::string& file, std::size_t depth = 1);

/// A Python str as the UTF-8 text of a JSON string; one holding a lone surrogate (which no UTF-8 text can hold)
/// is an InputError naming `file` and `path`.
std::string json_text(py::handle v, const std::string& path, const std::string& file);

/// A JSON value as Python objects (dict, list, str, int, float, bool, None).
py::object to_python(const json& j);

/// Every path argument of the module (load_scene's path, scene()'s base_dir and name, write()'s and
/// centrodes()'s files) as the bytes the file system takes: str, bytes or os.PathLike (os.fspath), a str
/// encoded and bytes taken as they are, as os.fsencode does (so a bytes name decodes with os.fsdecode).
/// `argument` names it in the errors: TypeError for another type, ValueError for an empty path, a NUL
/// character (which would end the name early) or a str the file system's encoding cannot encode.
std::string path_argument(const py::handle& path, const char* argument);

/// Text from C++ (a file name as the file system gave it, a message naming one) as a Python str, bytes that
/// are not UTF-8 kept as os.fsdecode keeps them (surrogate escapes).
py::str text_of(const std::string& text);

/// Texts as a NumPy array of str (dtype <U width of the longest), its UCS-4 buffer filled here: no Python
/// string per row.
template <class Texts> py::array str_array(const Texts& texts) {
  std::size_t width = 1;
  for (const std::string& t : texts) width = std::max(width, t.size());
  py::array out = py::module_::import("numpy").attr("empty")(std::size(texts), py::arg("dtype") = "<U" + std::to_string(width));
  auto* chars = static_cast<char32_t*>(out.mutable_data());
  std::fill(chars, chars + std::size(texts) * width, U'\0');
  std::size_t row = 0;
  for (const std::string& t : texts) {
    for (std::size_t i = 0; i < t.size(); ++i) chars[row * width + i] = static_cast<unsigned char>(t[i]);
    ++row;
  }
  return out;
}

}  // namespace rollkin::python
