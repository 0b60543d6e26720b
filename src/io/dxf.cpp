// DXF contour reader (io/dxf.hpp): libdxflib parses, a DL_CreationAdapter (dxf_collector.hpp) collects the
// entities of the ENTITIES section; then the selected entities are converted to exact Bezier segments
// (dxf_convert.cpp) and chained (dxf_chain.cpp). Here: the checks before libdxflib reads, the text helpers,
// the selection, the units and the entry points.
#include "dxf_collector.hpp"

#include "rollkin/io/csv.hpp"
#include "rollkin/io/input_file.hpp"
#include "rollkin/io/units.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <limits>
#include <optional>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <sstream>

namespace rollkin {
namespace dxf {

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}
std::string exact_number(double x) { return io::format_double(x); }
std::string point_text(const V& p) { return "(" + number(p.x()) + ", " + number(p.y()) + ")"; }

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

namespace {

/// Whether `t` is [sign] digits [. digits] [e|E [sign] digits] with at least one mantissa digit (a leading or
/// trailing point allowed: ".5", "5."), or, without point and exponent, an integer.
bool plain_decimal(const std::string& t, bool integer) {
  std::size_t i = 0, digits = 0;
  auto sign = [&] { if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i; };
  auto run = [&] {
    const std::size_t from = i;
    while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) ++i;
    return i - from;
  };
  sign();
  digits = run();
  if (!integer && i < t.size() && t[i] == '.') {
    ++i;
    digits += run();
  }
  if (digits == 0) return false;
  if (!integer && i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    sign();
    if (run() == 0) return false;
  }
  return i == t.size();
}

/// std::from_chars over a plain decimal, without the '+' it does not take.
template <class T> std::from_chars_result from_decimal(const std::string& t, T& out) {
  const char* first = t.data() + (t[0] == '+' ? 1 : 0);
  return std::from_chars(first, t.data() + t.size(), out);
}

}  // namespace

// libdxflib converts a real with std::istringstream >> double after replacing ',' by '.' (DL_Dxf::toReal) and
// an integer with strtol cast to int (DL_Dxf::toInt). Both read a plain decimal exactly as std::from_chars
// does (correctly rounded); anything else they read otherwise or partly (hexadecimal "0x1p8" as 0, "1.5abc"
// as 1.5, "1e" as 0) or truncate (99999999999 to 1215752191). So a value is accepted only as a plain decimal
// in range, and its text is converted once here: the value checked is the value libdxflib uses.
std::optional<double> read_real(const std::string& text, std::string& problem) {
  const std::string t = trim(text);
  double v = 0;
  if (!plain_decimal(t, false)) {
    problem = "is not a decimal number ([sign] digits [. digits] [E [sign] digits]; write a decimal point, not a comma): "
              "libdxflib would read it as " + exact_number(DL_Dxf().toReal(t));
    return std::nullopt;
  }
  const std::from_chars_result r = from_decimal(t, v);
  if (r.ec != std::errc() || r.ptr != t.data() + t.size() || !std::isfinite(v)) {
    problem = "is out of the range of a double (magnitude 2.2e-308 to 1.8e+308, or 0)";
    return std::nullopt;
  }
  return v;
}

std::optional<int> read_int(const std::string& text, std::string& problem) {
  const std::string t = trim(text);
  int v = 0;
  if (!plain_decimal(t, true)) {
    problem = "is not an integer ([sign] digits): libdxflib would read it as " + std::to_string(DL_Dxf().toInt(t));
    return std::nullopt;
  }
  const std::from_chars_result r = from_decimal(t, v);
  if (r.ec != std::errc() || r.ptr != t.data() + t.size()) {
    problem = "is out of the range of a DXF integer (" + std::to_string(std::numeric_limits<int>::min()) + " to " +
              std::to_string(std::numeric_limits<int>::max()) + "): libdxflib would read it as " +
              std::to_string(DL_Dxf().toInt(t));
    return std::nullopt;
  }
  return v;
}

// DXF reference, "Group code value types": every numeric range (280-299: 8-bit integers and booleans;
// 420-429, 440-459: 32-bit integers; 460-469: reals).
bool real_code(unsigned c) {
  return (c >= 10 && c <= 59) || (c >= 110 && c <= 149) || (c >= 210 && c <= 239) || (c >= 460 && c <= 469) || (c >= 1010 && c <= 1059);
}
bool int_code(unsigned c) {
  return (c >= 60 && c <= 99) || (c >= 160 && c <= 179) || (c >= 270 && c <= 299) || (c >= 370 && c <= 389) ||
         (c >= 400 && c <= 409) || (c >= 420 && c <= 429) || (c >= 440 && c <= 459) || (c >= 1060 && c <= 1071);
}

}  // namespace dxf

using namespace dxf;

namespace {

constexpr std::size_t kMaxLine = 1000;  // libdxflib reads lines of at most 1023 characters

/// Checks what libdxflib relies on before it reads the text: not binary, lines short enough for its fixed
/// buffer, every group code line an integer 0..1071. Returns the number of group pairs.
std::size_t check_group_structure(const std::string& text, const std::string& file) {
  if (text.compare(0, 18, "AutoCAD Binary DXF") == 0)
    throw InputError(file, "", "binary DXF is not supported; save the drawing as ASCII DXF");
  std::size_t line = 0, pos = 0, pairs = 0;
  while (pos < text.size()) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) eol = text.size();
    ++line;
    const std::string content = text.substr(pos, eol - pos);
    if (content.size() > kMaxLine)
      throw InputError(file, "line " + std::to_string(line),
                       "line of " + std::to_string(content.size()) + " characters; DXF lines are at most " +
                           std::to_string(kMaxLine) + " characters here");
    if (line % 2 == 1) {
      std::string problem;
      const bool last_blank = eol >= text.size() - 1 && trim(content).empty();
      const std::optional<int> code = last_blank ? std::nullopt : read_int(content, problem);
      if (!last_blank && (!code || *code < 0 || *code > 1071))
        throw InputError(file, "line " + std::to_string(line),
                         "expected a group code (an integer 0..1071), got \"" + trim(content).substr(0, 40) + "\"");
      if (!last_blank) ++pairs;
    }
    pos = eol + 1;
  }
  return pairs;
}

// ---- units and selection -------------------------------------------------------------------------------------

void set_units(DxfContour& out, const Collector& collector, const std::string& file) {
  out.insunits = collector.has_insunits ? collector.insunits : 0;
  switch (out.insunits) {
    case 0: out.unit = ""; out.metres_per_unit = 0; break;
    case 1: out.unit = "in"; out.metres_per_unit = 0.0254; break;
    case 2: out.unit = "ft"; out.metres_per_unit = 0.3048; break;
    case 4: out.unit = "mm"; out.metres_per_unit = 0.001; break;
    case 5: out.unit = "cm"; out.metres_per_unit = 0.01; break;
    case 6: out.unit = "m"; out.metres_per_unit = 1; break;
    default:
      throw InputError(file, "$INSUNITS",
                       "drawing unit code " + std::to_string(out.insunits) +
                           " is not supported; use 0 (unitless), 1 (in), 2 (ft), 4 (mm), 5 (cm) or 6 (m)");
  }
}

/// A handle (group 5) names one entity of the drawing: two entities of the ENTITIES section with the same
/// handle (compared case-insensitively, as selection compares them) make the file invalid, whichever layer
/// either is on, since selecting by that handle would take both.
void check_unique_handles(const std::vector<RawEntity>& all, const std::string& file) {
  std::map<std::string, const RawEntity*> first;
  for (const RawEntity& e : all) {
    if (e.handle.empty()) continue;
    const auto [it, fresh] = first.emplace(upper(e.handle), &e);
    if (fresh) continue;
    const RawEntity& a = *it->second;
    auto where = [](const RawEntity& x) { return x.label() + " (line " + std::to_string(x.line) + ", layer \"" + x.layer + "\")"; };
    throw InputError(file, "line " + std::to_string(e.line),
                     where(a) + " and " + where(e) + " have the same handle " + e.handle +
                         "; a handle (group 5) names one entity: give one of them a new handle (a CAD program's audit or "
                         "save does)");
  }
}

const char* kSupported = "LINE, ARC, CIRCLE, ELLIPSE, LWPOLYLINE, POLYLINE, SPLINE";

bool supported(const std::string& type) {
  for (const char* t : {"LINE", "ARC", "CIRCLE", "ELLIPSE", "LWPOLYLINE", "POLYLINE", "SPLINE"})
    if (type == t) return true;
  return false;
}

std::vector<const RawEntity*> select(const std::vector<RawEntity>& all, const DxfSelection& sel, const std::string& file) {
  if (sel.layer.empty() == sel.handle.empty())
    throw InputError(file, "", "select the contour by a layer name or by an entity handle (exactly one of the two)");
  std::vector<const RawEntity*> chosen;
  for (const RawEntity& e : all)
    if (sel.layer.empty() ? upper(e.handle) == upper(sel.handle) : upper(e.layer) == upper(sel.layer)) chosen.push_back(&e);
  if (chosen.empty()) {
    std::vector<std::string> layers;
    for (const RawEntity& e : all)
      if (std::find(layers.begin(), layers.end(), e.layer) == layers.end()) layers.push_back(e.layer);
    std::string known;
    for (std::size_t i = 0; i < layers.size() && i < 20; ++i) known += (i ? ", \"" : "\"") + layers[i] + "\"";
    throw InputError(file, "",
                     sel.layer.empty() ? "no entity with handle " + sel.handle + " in the ENTITIES section"
                                       : "no entity on layer \"" + sel.layer + "\" in the ENTITIES section (layers with entities: " +
                                             (known.empty() ? "none" : known) + ")");
  }
  std::string unsupported;
  for (const RawEntity* e : chosen)
    if (!supported(e->type) || !e->delivered)
      unsupported += (unsupported.empty() ? "" : ", ") + e->label() + " (line " + std::to_string(e->line) + ")";
  if (!unsupported.empty())
    throw InputError(file, sel.layer.empty() ? "handle " + sel.handle : "layer \"" + sel.layer + "\"",
                     "unsupported entities: " + unsupported + "; a contour is made of " + kSupported +
                         " (explode blocks, and move text, hatches and dimensions to another layer)");
  return chosen;
}

std::string describe(const DxfContour& out, const DxfSelection& sel, const std::string& file) {
  std::ostringstream os;
  os << "DXF " << (file.empty() ? std::string("<text>") : file) << " "
     << (sel.layer.empty() ? "handle " + sel.handle : "layer \"" + sel.layer + "\"") << ": " << out.entities.size()
     << (out.entities.size() == 1 ? " entity (" : " entities (");
  for (std::size_t i = 0; i < out.entities.size() && i < 4; ++i) os << (i ? ", " : "") << out.entities[i];
  if (out.entities.size() > 4) os << ", ...";
  os << "), " << out.segments.size() << " segments, " << (out.closed ? "closed" : "open") << ", " << out.corners.size()
     << (out.corners.size() == 1 ? " corner, " : " corners, ")
     << (out.unit.empty() ? std::string("unitless") : "unit " + out.unit + " (" + number(out.metres_per_unit) + " m)");
  return os.str();
}

}  // namespace

namespace {

/// A private temporary copy of a text, removed when it goes out of scope.
class TempFile {
 public:
  explicit TempFile(const std::string& text) {
    std::string pattern = (std::filesystem::temp_directory_path() / "rollkin-dxf-XXXXXX").string();
    const int fd = mkstemp(pattern.data());
    if (fd < 0) throw std::runtime_error("cannot create a temporary file for the DXF text in " + pattern);
    path_ = pattern;
    std::size_t done = 0;
    while (done < text.size()) {
      const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    ::close(fd);
    if (done != text.size()) {
      std::remove(path_.c_str());
      throw std::runtime_error("cannot write the temporary copy " + path_ + " of the DXF text");
    }
  }
  ~TempFile() { std::remove(path_.c_str()); }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// Runs the collector's checks over the group pairs of `text` as libdxflib will deliver them (a code line and
/// a value line per group, up to group 0 "EOF"), before libdxflib reads it. The checks must not fire while
/// libdxflib reads: an exception thrown through DL_Dxf::in leaves its FILE open (fuzz_dxf ran out of file
/// descriptors after some 10^5 rejected inputs), so every input error is found here first.
void check_groups_before_reading(const std::string& text, Collector& dry) {
  std::size_t pos = 0, line = 0;
  auto next_line = [&](std::string& content) {
    if (pos >= text.size()) return false;
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) eol = text.size();
    content = text.substr(pos, eol - pos);
    pos = eol + 1;
    ++line;
    return true;
  };
  std::string code_line, value, problem;
  while (next_line(code_line)) {
    const std::optional<int> code = read_int(code_line, problem);
    if (!code) break;  // only a trailing blank line (check_group_structure)
    if (!next_line(value)) dry.text_ended(line, *code);
    dry.processCodeValuePair(static_cast<unsigned>(*code), value);
    if (*code == 0 && trim(value) == "EOF") return;
  }
  dry.text_ended(line, -1);
}

/// `text` is the content of the file at `disk_path`, which libdxflib reads (its FILE* reader is the one that
/// calls processCodeValuePair; its istream reader, in libdxflib 3.26, does not).
DxfContour contour_from(const std::string& text, const std::string& disk_path, const DxfSelection& selection,
                        const std::string& file) {
  const std::size_t pairs = check_group_structure(text, file);
  {
    Collector dry(file, pairs);
    check_groups_before_reading(text, dry);
  }
  Collector collector(file, pairs);
  {
    DL_Dxf reader;
    if (!reader.in(disk_path, &collector)) throw InputError(file, "", "libdxflib could not open the DXF file");
  }
  DxfContour out;
  set_units(out, collector, file);
  check_unique_handles(collector.entities, file);
  const std::vector<const RawEntity*> chosen = select(collector.entities, selection, file);

  std::vector<Piece> pieces;
  for (const RawEntity* e : chosen) pieces.push_back(convert_entity(*e, file));
  double size = 0;
  Chain chain = chain_pieces(file, pieces, size);
  out.segments = std::move(chain.segments);
  out.closed = chain.closed;
  for (std::size_t i = 0; i < chain.owner.size(); ++i)
    if (i == 0 || chain.owner[i] != chain.owner[i - 1]) out.entities.push_back(pieces[chain.owner[i]].label);

  const std::size_t n = out.segments.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t before = chain.owner[(i + n - 1) % n], after = chain.owner[i];
    out.joint_entities.push_back(before == after ? pieces[after].label : pieces[before].label + " / " + pieces[after].label);
  }
  const BezierPathOptions<double> options;
  for (const PathCorner<double>& k : path_corners(out.segments, out.closed, options.joint_tolerance * size, options.corner_tolerance))
    out.corners.push_back({out.joint_entities[k.piece], k.piece, k.point, rad_to_deg(k.turn)});
  out.description = describe(out, selection, file);
  return out;
}

}  // namespace

DxfContour parse_dxf_contour(const std::string& dxf, const DxfSelection& selection, const std::string& file) {
  const TempFile copy(dxf);
  return contour_from(dxf, copy.path(), selection, file);
}

DxfContour read_dxf_contour(const std::string& path, const DxfSelection& selection) {
  return contour_from(io::read_input_file(path, "the DXF file"), path, selection, path);
}

}  // namespace rollkin
