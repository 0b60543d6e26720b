// Python values <-> JSON for the Python module (declared and documented in convert.hpp).
#include "convert.hpp"

#include "rollkin/io/input_error.hpp"
#include "rollkin/io/json/document.hpp"

#include <cmath>
#include <utility>

namespace rollkin::python {
namespace {

/// Ctrl-C while a large array or list is converted (with the GIL held, before any worker starts): Python's
/// signal handlers run every 65536 elements, and their exception (KeyboardInterrupt) propagates.
void check_signals_every_block(std::size_t i) {
  if (i % 65536 == 65535 && PyErr_CheckSignals() != 0) throw py::error_already_set();
}

// ---- Python values <-> JSON ------------------------------------------------------------------------------

/// A float NumPy array of 1 or 2 dimensions as JSON numbers (nested lists), read straight from its buffer:
/// a large contour array goes into the document without a Python list in between. Non-finite values are an
/// InputError at the element's JSON path.
json float_array_json(py::handle v, const std::string& path, const std::string& file) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(v);
  if (!a || a.ndim() < 1 || a.ndim() > 2)
    throw io::InputError(file, path, "a float array of " + std::to_string(a ? a.ndim() : 0) +
                                     " dimensions; expected a vector or an (n, k) array");
  const py::ssize_t rows = a.shape(0), cols = a.ndim() == 2 ? a.shape(1) : 1;
  const double* data = a.data();
  auto number = [&](py::ssize_t i, py::ssize_t j) -> json {
    const double d = data[i * cols + j];
    if (std::isfinite(d)) return d;
    const std::string at = a.ndim() == 2 ? rollkin::io::index(rollkin::io::index(path, static_cast<std::size_t>(i)), static_cast<std::size_t>(j))
                                            : rollkin::io::index(path, static_cast<std::size_t>(i));
    throw io::InputError(file, at, "the number " + std::string(py::str(py::float_(d))) + " is not finite; expected a finite number");
  };
  json out = json::array();
  out.get_ref<json::array_t&>().reserve(static_cast<std::size_t>(rows));
  for (py::ssize_t i = 0; i < rows; ++i) {
    check_signals_every_block(static_cast<std::size_t>(i));
    if (a.ndim() == 1) {
      out.push_back(number(i, 0));
      continue;
    }
    json row = json::array();
    for (py::ssize_t j = 0; j < cols; ++j) row.push_back(number(i, j));
    out.push_back(std::move(row));
  }
  return out;
}

}  // namespace

std::string json_text(py::handle v, const std::string& path, const std::string& file) {
  Py_ssize_t size = 0;
  const char* utf8 = PyUnicode_AsUTF8AndSize(v.ptr(), &size);
  if (utf8) return std::string(utf8, static_cast<std::size_t>(size));
  PyErr_Clear();
  throw io::InputError(file, path, "the string " + std::string(py::repr(v)) +
                                   " holds a lone surrogate, which no JSON text can; expected valid Unicode");
}

json to_json(py::handle v, const std::string& path, const std::string& file, std::size_t depth) {
  if (depth > rollkin::io::kMaxJsonDepth)
    throw io::InputError(file, path, "nested deeper than " + std::to_string(rollkin::io::kMaxJsonDepth) + " levels");
  if (v.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>();
  if (py::isinstance<py::int_>(v)) {
    int overflow = 0;
    const long long i = PyLong_AsLongLongAndOverflow(v.ptr(), &overflow);
    if (!overflow) return i;
    return to_json(py::float_(py::reinterpret_borrow<py::object>(v)), path, file, depth);
  }
  if (py::isinstance<py::float_>(v)) {
    const double d = v.cast<double>();
    if (!std::isfinite(d)) throw io::InputError(file, path, "the number " + std::string(py::str(v)) + " is not finite; expected a finite number");
    return d;
  }
  if (py::isinstance<py::str>(v)) return json_text(v, path, file);
  if (py::isinstance<py::dict>(v)) {
    json out = json::object();
    for (auto item : py::reinterpret_borrow<py::dict>(v)) {
      if (!py::isinstance<py::str>(item.first))
        throw io::InputError(file, path, "a key " + std::string(py::repr(item.first)) + " that is not a string; JSON keys are strings");
      const std::string key = json_text(item.first, path, file);
      out[key] = to_json(item.second, rollkin::io::child(path, key), file, depth + 1);
    }
    return out;
  }
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    json out = json::array();
    std::size_t i = 0;
    for (auto item : v) {
      check_signals_every_block(i);
      out.push_back(to_json(item, rollkin::io::index(path, i++), file, depth + 1));
    }
    return out;
  }
  if (py::isinstance<py::array>(v) && py::array::ensure(v).dtype().kind() == 'f') return float_array_json(v, path, file);
  if (py::hasattr(v, "tolist") && py::hasattr(v, "dtype")) return to_json(v.attr("tolist")(), path, file, depth);
  throw io::InputError(file, path, "a Python " + std::string(py::str(v.get_type().attr("__name__"))) +
                                   " cannot be a scene value; expected a dict, list, str, number, bool or None");
}

py::object to_python(const json& j) {
  switch (j.type()) {
    case json::value_t::null: return py::none();
    case json::value_t::boolean: return py::bool_(j.get<bool>());
    case json::value_t::number_integer: return py::int_(j.get<long long>());
    case json::value_t::number_unsigned: return py::int_(j.get<unsigned long long>());
    case json::value_t::number_float: return py::float_(j.get<double>());
    case json::value_t::string: return py::str(j.get<std::string>());
    case json::value_t::array: {
      py::list out;
      for (const json& e : j) out.append(to_python(e));
      return std::move(out);
    }
    case json::value_t::object: {
      py::dict out;
      for (auto it = j.begin(); it != j.end(); ++it) out[py::str(it.key())] = to_python(it.value());
      return std::move(out);
    }
    default: return py::none();
  }
}

std::string path_argument(const py::handle& path, const char* argument) {
  const py::module_ os = py::module_::import("os");
  const std::string name = argument;
  if (!py::isinstance<py::str>(path) && !py::isinstance<py::bytes>(path) && !py::hasattr(path, "__fspath__"))
    throw py::type_error(name + ": expected a path (str, bytes or os.PathLike), got " +
                         std::string(py::str(path.get_type().attr("__name__"))));
  const py::object given = os.attr("fspath")(path);
  py::object encoded;
  try {
    encoded = os.attr("fsencode")(given);
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_UnicodeError)) throw;
    throw py::value_error(name + ": the path " + std::string(py::repr(given)) +
                          " cannot be a file name: the file system's encoding cannot encode it (" + e.what() + ")");
  }
  const std::string bytes = encoded.cast<std::string>();
  const std::string shown = py::repr(os.attr("fsdecode")(given));
  if (bytes.empty()) throw py::value_error(name + ": the path is empty; expected a file name");
  if (bytes.find('\0') != std::string::npos)
    throw py::value_error(name + ": the path " + shown + " contains a NUL character, which no file name can hold");
  return bytes;
}

py::str text_of(const std::string& text) {
  PyObject* s = PyUnicode_DecodeFSDefaultAndSize(text.data(), static_cast<Py_ssize_t>(text.size()));
  if (!s) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(s);
}

}  // namespace rollkin::python
