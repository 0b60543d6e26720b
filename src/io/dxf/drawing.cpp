// DXF contour reader (io/dxf/reader.hpp), the drawing: the checks before libdxflib reads the text, the text helpers,
// libdxflib's run with the collector (dxf/collector.hpp: the entities of the ENTITIES and BLOCKS sections),
// the drawing-wide checks ($INSUNITS, unique handles) and the placement of blocks by INSERTs (Placer). The
// selection of one contour from the drawing is dxf/selection.cpp; the conversion of entities to exact Bezier
// segments dxf/convert.cpp, the chains dxf/chain.cpp.
#include "collector.hpp"

#include "rollkin/io/format.hpp"
#include "rollkin/io/input_file.hpp"
#include "rollkin/io/temporary_file.hpp"
#include "rollkin/io/units.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <limits>
#include <optional>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <sstream>

namespace rollkin::io {
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
/// buffer, every group code line an integer 0..1071, up to group 0 EOF (what follows it is not DXF: CAD
/// programs ignore it, and so does this reader). Returns the number of group pairs; `end` gets the offset just
/// after the EOF group (the text's size without one).
std::size_t check_group_structure(const std::string& text, const std::string& file, std::size_t& end) {
  if (text.compare(0, 18, "AutoCAD Binary DXF") == 0)
    throw InputError(file, "", "binary DXF is not supported; save the drawing as ASCII DXF");
  std::size_t line = 0, pos = 0, pairs = 0;
  bool code_zero = false;
  end = text.size();
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
      code_zero = code && *code == 0;
    } else if (code_zero && trim(content) == "EOF") {
      end = std::min(eol + 1, text.size());
      return pairs;
    }
    pos = eol + 1;
  }
  return pairs;
}

/// A private temporary copy of a text for libdxflib, which reads a file by name: an unnamed file in $TMPDIR
/// opened through /proc/self/fd/N (io::TemporaryFile), so that nothing is left whatever ends the run.
class TempFile {
 public:
  explicit TempFile(const std::string& text) : file_(std::filesystem::temp_directory_path().string(), "rollkin-dxf-") {
    std::size_t done = 0;
    while (done < text.size()) {
      const ssize_t n = ::write(file_.fd(), text.data() + done, text.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    if (done != text.size() || !file_.close())
      throw std::runtime_error("cannot write the temporary copy of the DXF text in " + std::filesystem::temp_directory_path().string());
  }
  std::string path() const { return file_.path(); }

 private:
  TemporaryFile file_;
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

// ---- blocks ------------------------------------------------------------------------------------------------

/// cos and sin of an angle in degrees, exact at multiples of 90 degrees.
std::pair<double, double> cos_sin_degrees(double degrees) {
  const double turns = degrees / 90;
  if (turns == std::floor(turns) && std::abs(turns) < 1e15) {
    switch (((static_cast<long long>(turns) % 4) + 4) % 4) {
      case 0: return {1, 0};
      case 1: return {0, 1};
      case 2: return {-1, 0};
      default: return {0, -1};
    }
  }
  return {std::cos(deg_to_rad(degrees)), std::sin(deg_to_rad(degrees))};
}

}  // namespace

namespace dxf {

// ---- units and handles ---------------------------------------------------------------------------------------

void set_units(DxfContour& out, const Drawing& drawing, const std::string& file) {
  out.insunits = drawing.has_insunits ? drawing.insunits : 0;
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

/// A handle (group 5) names one entity of the drawing. Rule (docs/reliability.md, "CAD readers (issue 37)"): a
/// selection by a handle that several entities of the ENTITIES section share (compared case-insensitively, as
/// selection compares them) is refused naming that handle and its entities; entities sharing a handle never
/// make the rest of the drawing unreadable.
void check_one_entity(const std::string& handle, const std::vector<const RawEntity*>& with_it, const std::string& file) {
  if (with_it.size() < 2) return;
  auto where = [](const RawEntity& x) { return x.label() + " (line " + std::to_string(x.line) + ", layer \"" + x.layer + "\")"; };
  std::string names;
  for (std::size_t i = 0; i < with_it.size() && i < 6; ++i)
    names += (i ? (i + 1 == with_it.size() ? " and " : ", ") : "") + where(*with_it[i]);
  if (with_it.size() > 6) names += ", ... (" + std::to_string(with_it.size()) + " entities)";
  throw InputError(file, "handle " + handle,
                   "the handle " + handle + " is ambiguous: " + names + " have it; a handle (group 5) names one entity: "
                   "give one of them a new handle (a CAD program's audit or save does), or select the contour by "
                   "its layer or a point \"near\" it");
}

bool supported(const std::string& type) {
  for (const char* t : {"LINE", "ARC", "CIRCLE", "ELLIPSE", "LWPOLYLINE", "POLYLINE", "SPLINE"})
    if (type == t) return true;
  return false;
}

void check_drawing(const Drawing& drawing, const std::string& file) {
  DxfContour units;
  set_units(units, drawing, file);
}

bool never_a_curve(const std::string& type) {
  for (const char* t : {"TEXT", "MTEXT", "ATTDEF", "ATTRIB", "DIMENSION", "ARC_DIMENSION", "LARGE_RADIAL_DIMENSION", "HATCH",
                        "MPOLYGON", "POINT", "VIEWPORT", "MULTILEADER", "MLEADER", "LEADER", "TOLERANCE", "IMAGE", "WIPEOUT",
                        "OLEFRAME", "OLE2FRAME", "ACAD_TABLE", "TABLE", "RAY", "XLINE", "SHAPE", "UNDERLAY", "PDFUNDERLAY",
                        "DWFUNDERLAY", "DGNUNDERLAY", "LIGHT", "SUN", "SECTION", "GEOPOSITIONMARKER"})
    if (type == t) return true;
  return false;
}

std::vector<const RawEntity*> Drawing::top_level() const {
  std::vector<const RawEntity*> out;
  for (const RawEntity& e : entities)
    if (e.block.empty() && e.type != "BLOCK" && e.type != "ENDBLK") out.push_back(&e);
  return out;
}

Drawing read_drawing(const std::string& text, const std::string& disk_path, const std::string& file) {
  std::size_t end = 0;
  const std::size_t pairs = check_group_structure(text, file, end);
  {
    Collector dry(file, pairs);
    check_groups_before_reading(text, dry);
  }
  Collector collector(file, pairs);
  {
    // libdxflib reads to the end of the file, EOF or not: it is given the text up to group 0 EOF.
    std::optional<TempFile> copy;
    const std::string opened = disk_path.empty() ? disk_path : opened_path(disk_path);  // a staged output's temporary
    if (opened.empty() || end < text.size()) copy.emplace(text.substr(0, end));
    DL_Dxf reader;
    if (!reader.in(copy ? copy->path() : opened, &collector)) throw InputError(file, "", "libdxflib could not open the DXF file");
  }
  Drawing d;
  d.entities = std::move(collector.entities);
  d.has_insunits = collector.has_insunits;
  d.insunits = collector.insunits;
  return d;
}

Placer::Placer(const Drawing& drawing, std::string file) : file_(std::move(file)) {
  Block* current = nullptr;
  for (const RawEntity& e : drawing.entities) {
    if (e.type == "BLOCK") {
      Block& b = blocks_[upper(e.name)];
      b = Block{e.name, V(e.v[0], e.v[1]), {}};
      current = &b;
    } else if (e.type == "ENDBLK") {
      current = nullptr;
    } else if (!e.block.empty() && current) {
      current->entities.push_back(&e);
    }
  }
}

void Placer::fail(const RawEntity& e, const std::string& what) const {
  throw InputError(file_, "line " + std::to_string(e.line), e.label() + " " + what);
}

void Placer::place(const RawEntity& top, std::vector<Piece>& out) {
  std::vector<std::string> stack;
  place_in(top, Affine{}, "", stack, top, out);
}

void Placer::place_in(const RawEntity& e, const Affine& m, const std::string& suffix, std::vector<std::string>& stack,
                      const RawEntity& top, std::vector<Piece>& out) {
  if (never_a_curve(e.type)) return;
  if (e.type == "INSERT") return place_insert(e, m, suffix, stack, top, out);
  if (++placed_ > kDxfMaxPlacedEntities)  // one piece each (the INSERTs placing it are counted by their copies)
    fail(top, "places more than " + std::to_string(kDxfMaxPlacedEntities) + " entities (nested blocks and MINSERT arrays); "
              "a contour is one chain: explode the blocks it is not in");
  if (!supported(e.type) || !e.delivered)
    throw InputError(file_, "line " + std::to_string(e.line),
                     e.label() + suffix + " is not supported; a contour is made of " + std::string(kSupported));
  Piece p;
  try {
    p = convert_entity(e, file_);
  } catch (const InputError& ex) {
    if (suffix.empty()) throw;
    throw InputError(file_, "line " + std::to_string(e.line), std::string(ex.what()) + " (placed" + suffix + ")");
  }
  p.label += suffix;
  p.layer = top.layer;
  p.handle = top.handle;
  if (!m.identity())
    for (Segment& s : p.segments)
      for (V& q : s.points) q = m(q);
  for (const Segment& s : p.segments)
    for (const V& q : s.points)
      if (!std::isfinite(q.x()) || !std::isfinite(q.y()))
        throw InputError(file_, "line " + std::to_string(e.line),
                         p.label + " reaches beyond the range of double precision (" + exact_number(q.x()) + ", " +
                             exact_number(q.y()) + "); check its coordinates and the scales of the INSERTs placing it");
  out.push_back(std::move(p));
}

// An INSERT places its block (ezdxf's Insert.matrix44 and multi_insert, the DXF reference's INSERT): block
// coordinates q -> OCS(ip + offset + R(angle) diag(sx, sy) (q - base)), offset = R(angle) (column c x column
// spacing, row r x row spacing) for the MINSERT's columns and rows (spacing not scaled; a spacing of 0 places
// one copy in that direction), OCS the arbitrary axis algorithm of its extrusion (+Z: identity, -Z: x -> -x).
void Placer::place_insert(const RawEntity& e, const Affine& m, const std::string& suffix, std::vector<std::string>& stack,
                          const RawEntity& top, std::vector<Piece>& out) {
  if (!e.defect.empty()) throw InputError(file_, e.defect_where, e.label() + suffix + ": " + e.defect);
  auto fail = [&](const RawEntity& x, const std::string& what) {
    throw InputError(file_, "line " + std::to_string(x.line), x.label() + suffix + " " + what);
  };
  const auto& n = e.extrusion;
  if (!(n[2] != 0 && std::hypot(n[0], n[1]) <= 1e-12 * std::abs(n[2])))
    fail(e, "has extrusion direction (" + exact_number(n[0]) + ", " + exact_number(n[1]) + ", " + exact_number(n[2]) +
                "): only blocks placed in the XY plane are read, extrusion (0, 0, 1) or (0, 0, -1)");
  const auto it = blocks_.find(upper(e.name));
  if (it == blocks_.end()) fail(e, "inserts block \"" + e.name + "\", which the BLOCKS section does not define");
  const Block& block = it->second;
  if (std::find(stack.begin(), stack.end(), upper(e.name)) != stack.end()) {
    std::string path;
    for (const std::string& b : stack) path += b + " -> ";
    fail(e, "inserts block \"" + e.name + "\" into itself (" + path + upper(e.name) + "); a block cannot contain itself");
  }
  if (static_cast<int>(stack.size()) >= kDxfMaxInsertDepth)
    fail(e, "is nested " + std::to_string(stack.size() + 1) + " INSERTs deep; at most " + std::to_string(kDxfMaxInsertDepth) + " are read");
  const double ipx = e.v[0], ipy = e.v[1], sx = e.v[2], sy = e.v[3], angle = e.v[4], cols = e.v[5], rows = e.v[6];
  const double col_spacing = e.v[7], row_spacing = e.v[8];
  for (double x : {ipx, ipy, sx, sy, angle, col_spacing, row_spacing})
    if (!std::isfinite(x)) fail(e, "has a value that is not finite");
  if (sx == 0 || sy == 0) fail(e, "has scale (" + exact_number(sx) + ", " + exact_number(sy) + "): a zero scale flattens the block");
  if (cols < 1 || rows < 1) fail(e, "has " + number(cols) + " columns and " + number(rows) + " rows; each must be at least 1");
  const auto [c, s] = cos_sin_degrees(angle);
  const double mirror = n[2] < 0 ? -1 : 1;
  // The bound counts what is placed (docs/reliability.md, "CAD readers (issue 37)"): each entity of each copy
  // once (place_in), a copy of a block without curve entities once (it is visited, places nothing). At least
  // copies x max(1, the block's curve entities) are to come: above the bound, refused before any is placed.
  const double copies_d = (col_spacing == 0 ? 1 : std::floor(cols)) * (row_spacing == 0 ? 1 : std::floor(rows));
  const std::size_t curves = static_cast<std::size_t>(std::count_if(
      block.entities.begin(), block.entities.end(), [](const RawEntity* x) { return !never_a_curve(x->type); }));
  const double to_come = copies_d * static_cast<double>(std::max<std::size_t>(curves, 1));
  if (static_cast<double>(placed_) + to_come > static_cast<double>(kDxfMaxPlacedEntities))
    fail(e, "places more than " + std::to_string(kDxfMaxPlacedEntities) + " entities and copies (nested blocks and "
              "MINSERT arrays; here " + number(col_spacing == 0 ? 1 : std::floor(cols)) + " x " +
              number(row_spacing == 0 ? 1 : std::floor(rows)) + " copies of block \"" + block.name + "\" with " +
              std::to_string(curves) + " curve entit" + (curves == 1 ? "y" : "ies") + "); a contour is one chain: "
              "explode the blocks it is not in");
  const long columns = col_spacing == 0 ? 1 : static_cast<long>(cols), lines = row_spacing == 0 ? 1 : static_cast<long>(rows);
  if (curves == 0) placed_ += static_cast<std::size_t>(copies_d);  // copies that place nothing
  stack.push_back(upper(e.name));
  for (long r = 0; r < lines; ++r)
    for (long k = 0; k < columns; ++k) {
      const double ox = k * col_spacing, oy = r * row_spacing;
      const V at(ipx + c * ox - s * oy, ipy + s * ox + c * oy);  // OCS
      Affine place;  // q -> at + R S (q - base), then the OCS
      place.a = c * sx, place.b = -s * sy, place.c = s * sx, place.d = c * sy;
      place.t = at - V(place.a * block.base.x() + place.b * block.base.y(), place.c * block.base.x() + place.d * block.base.y());
      place.a *= mirror, place.b *= mirror, place.t.x() *= mirror;
      const std::string here = " in " + e.label() +
                               (columns * lines > 1 ? " (column " + std::to_string(k) + ", row " + std::to_string(r) + ")" : "") + suffix;
      const Affine total = m.after(place);
      for (const RawEntity* child : block.entities) place_in(*child, total, here, stack, top, out);
    }
  stack.pop_back();
}

}  // namespace dxf

}  // namespace rollkin::io
