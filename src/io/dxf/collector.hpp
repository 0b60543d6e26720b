// The DXF reader's libdxflib adapter (internal to src/io/dxf/drawing.cpp): collects the entities of the ENTITIES
// section with their type, handle and layer (from processCodeValuePair, which libdxflib calls for every group
// before interpreting it), checks group values and the counts libdxflib sizes its arrays with, and keeps the
// geometry libdxflib reports.
#pragma once

#include "detail.hpp"

#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace rollkin::io::dxf {

class Collector : public DL_CreationAdapter {
 public:
  Collector(std::string file, std::size_t pairs) : file_(std::move(file)), pairs_(pairs) {}

  std::vector<RawEntity> entities;
  bool has_insunits = false;
  int insunits = 0;

  void processCodeValuePair(unsigned int code, const std::string& value) override {
    ++pair_;
    const std::size_t line = 2 * pair_ - 1;
    if (code == 0) {
      entity_type_ = trim(value);
      return entity_start(entity_type_, line);
    }
    // (In ENTITIES and BLOCKS count_value checks them too, naming the entity by its handle.)
    if (!recording() && sizes_an_array(entity_type_, code)) bounded_count(code, value, line);
    if (code == 2 && expect_section_name_) {
      section_ = trim(value);
      expect_section_name_ = false;
      return;
    }
    if (section_ == "HEADER") {
      if (code == 9) header_variable_ = trim(value);
      if (header_variable_ == "$INSUNITS" && code == 70) {
        insunits = number_or_fail<int>(code, value, line, "$INSUNITS");
        has_insunits = true;
      }
      return;
    }
    if (!recording() || current_ < 0) return;
    RawEntity& e = entities[static_cast<std::size_t>(current_)];
    // A malformed number is the entity's defect (reported when it is used); a count libdxflib sizes an array
    // with is checked now (count_value), whatever the entity.
    if (!sizes_an_array(e.type, code)) {
      if (real_code(code)) note_number<double>(e, code, value, line);
      if (int_code(code)) note_number<int>(e, code, value, line);
    }
    if (in_sequence_) return;  // VERTEX, ATTRIB, SEQEND of a POLYLINE or INSERT: libdxflib reports them
    // libdxflib stores an LWPOLYLINE's vertices and bulges in an array sized by group 90 and indexed from the
    // last group 10: a vertex before the count, or a bulge before the first vertex, would be written outside it.
    if (e.type == "LWPOLYLINE" && (code == 10 || code == 42) && (e.g90 < 0 || (code == 42 && e.n10 == 0)))
      throw InputError(file_, "line " + std::to_string(line), e.label() + ": group " + std::to_string(code) +
                                                                  (code == 10 ? " (vertex) before the vertex count (group 90)"
                                                                              : " (bulge) before the first vertex (group 10)"));
    switch (code) {
      case 2:
        if (e.type == "BLOCK") block_ = e.name = trim(value);  // the entities up to ENDBLK are this block's
        break;
      case 5: e.handle = trim(value); break;
      case 8: e.layer = trim(value); break;
      case 10: ++e.n10; break;
      case 11: ++e.n11; break;
      case 40: ++e.n40; break;
      case 41: ++e.n41; break;
      default: break;
    }
    // Groups 72, 73, 74, 76 and 90 are counts only where libdxflib sizes an array with them (a VIEWPORT's or
    // MULTILEADER's group 90 is a set of flags, -1073741824 for instance).
    if (sizes_an_array(e.type, code)) {
      const long n = count_value(e, code, value, line);
      if (code == 72) e.g72 = n;
      if (code == 73) e.g73 = n;
      if (code == 74) e.g74 = n;
      if (code == 90) e.g90 = n;
    }
  }

  /// The text ended at `line` (1-based; the code line of a group without a value when `code` >= 0) before
  /// group 0 EOF. An entity of the ENTITIES section still open there is cut short: libdxflib would drop it.
  void text_ended(std::size_t line, int code) const {
    std::string inside;
    if (recording() && current_ >= 0) {
      const RawEntity& e = entities[static_cast<std::size_t>(current_)];
      inside = " inside entity " + e.label() + (e.handle.empty() ? "" : " (line " + std::to_string(e.line) + ")");
    }
    if (code >= 0)
      throw InputError(file_, "line " + std::to_string(line),
                       "the file ends" + inside + " after group code " + std::to_string(code) +
                           " without its value: the DXF is cut short; export it again");
    if (!inside.empty())
      throw InputError(file_, "line " + std::to_string(line),
                       "the file ends" + inside + ": the DXF is cut short (an entity ends at the next group 0, the "
                       "file with 0 ENDSEC and 0 EOF); export it again");
  }

  void addLine(const DL_LineData& d) override {
    if (RawEntity* e = target()) e->v = {d.x1, d.y1, d.z1, d.x2, d.y2, d.z2, 0, 0, 0};
  }
  void addArc(const DL_ArcData& d) override {
    if (RawEntity* e = target()) e->v = {d.cx, d.cy, d.cz, d.radius, d.angle1, d.angle2, 0, 0, 0};
  }
  void addCircle(const DL_CircleData& d) override {
    if (RawEntity* e = target()) e->v = {d.cx, d.cy, d.cz, d.radius, 0, 0, 0, 0, 0};
  }
  void addEllipse(const DL_EllipseData& d) override {
    if (RawEntity* e = target()) e->v = {d.cx, d.cy, d.cz, d.mx, d.my, d.mz, d.ratio, d.angle1, d.angle2};
  }
  void addPolyline(const DL_PolylineData& d) override {
    if (RawEntity* e = target()) e->flags = d.flags;
  }
  void addVertex(const DL_VertexData& d) override {
    if (RawEntity* e = target(false)) e->vertices.push_back({d.x, d.y, d.z, d.bulge});
  }
  void addInsert(const DL_InsertData& d) override {
    if (RawEntity* e = target()) {
      e->name = d.name;
      e->v = {d.ipx, d.ipy, d.sx, d.sy, d.angle, static_cast<double>(d.cols), static_cast<double>(d.rows), d.colSp, d.rowSp};
    }
  }
  void addBlock(const DL_BlockData& d) override {
    if (RawEntity* e = target()) {
      e->name = d.name;
      e->v[0] = d.bpx, e->v[1] = d.bpy;
    }
  }
  void addSpline(const DL_SplineData& d) override {
    if (RawEntity* e = target()) {
      e->degree = static_cast<int>(d.degree);
      e->flags = d.flags;
    }
  }
  void addControlPoint(const DL_ControlPointData& d) override {
    if (RawEntity* e = target()) e->control.push_back({d.x, d.y, d.z, d.w});
  }
  void addKnot(const DL_KnotData& d) override {
    if (RawEntity* e = target()) e->knots.push_back(d.k);
  }

 private:
  /// The entity a callback belongs to: the one whose end (the next group 0) libdxflib is processing, when it
  /// lies in the ENTITIES section; records that its geometry arrived and, from the entity's own callback
  /// (`own`), the extrusion libdxflib set for it. A POLYLINE's VERTEX callbacks come with the VERTEX's
  /// extrusion, (0, 0, 1) by default: the POLYLINE's own (group 210 of the POLYLINE) must not be replaced by
  /// it (ezdxf_random.py's mirrored POLYLINEs were read unmirrored).
  RawEntity* target(bool own = true) {
    if (target_ < 0) return nullptr;
    RawEntity& e = entities[static_cast<std::size_t>(target_)];
    e.delivered = true;
    if (own) {
      const double* dir = getExtrusion()->getDirection();
      e.extrusion = {dir[0], dir[1], dir[2]};
    }
    return &e;
  }

  /// Entities are recorded in the ENTITIES section and in block definitions (which INSERTs place).
  bool recording() const { return section_ == "ENTITIES" || section_ == "BLOCKS"; }

  /// Records a malformed number as the entity's defect (the first one).
  template <class T> void note_number(RawEntity& e, unsigned code, const std::string& value, std::size_t line) const {
    std::string problem;
    std::optional<T> v;
    if constexpr (std::is_same_v<T, double>) v = read_real(value, problem);
    else v = read_int(value, problem);
    if (!v && e.defect.empty()) {
      e.defect = "group " + std::to_string(code) + " value \"" + excerpt(trim(value), 40) + "\" " + problem;
      e.defect_where = "line " + std::to_string(line + 1);
    }
  }

  /// Groups from which libdxflib sizes an array (new double[k * count]) for the entity it is reading, in any
  /// section: ENTITIES, BLOCKS or one it does not know (fuzz_dxf: a SPLINE in a misspelt section with
  /// 1056964608 fit points overflowed the size).
  static bool sizes_an_array(const std::string& type, unsigned code) {
    return (type == "LWPOLYLINE" && code == 90) || (type == "SPLINE" && (code == 72 || code == 73 || code == 74)) ||
           (type == "LEADER" && code == 76);
  }

  /// Such a count must be an integer between 0 and the number of groups in the file.
  void bounded_count(unsigned code, const std::string& value, std::size_t line) const {
    std::string problem;
    const std::optional<int> n = read_int(value, problem);
    if (!n || *n < 0 || static_cast<std::size_t>(*n) > pairs_)
      throw InputError(file_, "line " + std::to_string(line + 1),
                       entity_type_ + ": group " + std::to_string(code) + " count \"" + trim(value).substr(0, 40) +
                           "\" is impossible (not an integer from 0 to the file's " + std::to_string(pairs_) + " groups)");
  }

  long count_value(const RawEntity& e, unsigned code, const std::string& value, std::size_t line) {
    const long n = number_or_fail<int>(code, value, line, e.label());
    if (n < 0 || static_cast<std::size_t>(n) > pairs_)
      throw InputError(file_, "line " + std::to_string(line + 1),
                       e.label() + ": group " + std::to_string(code) + " count " + std::to_string(n) +
                           " is impossible (negative or more than the file's " + std::to_string(pairs_) + " groups)");
    return n;
  }

  /// A group's value as a number (read_real, read_int): the one reading of it, libdxflib's too; an InputError
  /// naming `who`, the group, the value's line and the value otherwise.
  template <class T> T number_or_fail(unsigned code, const std::string& value, std::size_t line, const std::string& who) const {
    std::string problem;
    std::optional<T> v;
    if constexpr (std::is_same_v<T, double>) v = read_real(value, problem);
    else v = read_int(value, problem);
    if (!v)
      throw InputError(file_, "line " + std::to_string(line + 1),
                       who + ": group " + std::to_string(code) + " value \"" + excerpt(trim(value), 40) + "\" " + problem);
    return *v;
  }

  void entity_start(const std::string& type, std::size_t line) {
    target_ = -1;
    if (recording() && current_ >= 0) {
      RawEntity& e = entities[static_cast<std::size_t>(current_)];
      const bool owner = e.type == "POLYLINE" || e.type == "INSERT";
      if (owner && (type == "VERTEX" || type == "ATTRIB" || type == "SEQEND")) {
        target_ = current_;  // libdxflib completes the POLYLINE or the previous VERTEX now
        in_sequence_ = true;
        return;
      }
      check_counts(e);
      target_ = current_;
      current_ = -1;
      in_sequence_ = false;
    }
    if (type == "SECTION") {
      expect_section_name_ = true;
      section_.clear();
    } else if (type == "ENDSEC") {
      section_.clear();
    } else if (recording()) {
      RawEntity e;
      e.type = type;
      e.line = line;
      if (type == "ENDBLK") block_.clear();
      e.block = block_;
      entities.push_back(e);
      current_ = static_cast<long>(entities.size()) - 1;
    }
  }

  /// The counts libdxflib sizes its arrays with must match the groups that follow (it keeps a missing count
  /// from the previous entity and drops or zero-fills the difference): otherwise the entity's defect.
  void check_counts(RawEntity& e) const {
    auto fail = [&](const std::string& what) {
      if (!e.defect.empty()) return;
      e.defect = what;
      e.defect_where = "line " + std::to_string(e.line);
    };
    auto declared = [](long g) { return g < 0 ? std::string("no count") : "a count of " + std::to_string(g); };
    if (e.type == "LWPOLYLINE" && e.g90 != e.n10)
      fail("group 90 gives " + declared(e.g90) + " vertices but " + std::to_string(e.n10) + " vertices (group 10) follow");
    if (e.type == "SPLINE") {
      if (e.g72 != e.n40) fail("group 72 gives " + declared(e.g72) + " knots but " + std::to_string(e.n40) + " knots (group 40) follow");
      if (e.g73 != e.n10 && !(e.g73 < 0 && e.n10 == 0))
        fail("group 73 gives " + declared(e.g73) + " control points but " + std::to_string(e.n10) + " (group 10) follow");
      if (e.n41 != 0 && e.n41 != e.n10)
        fail(std::to_string(e.n41) + " weights (group 41) for " + std::to_string(e.n10) + " control points; give one per point or none");
      if (e.g74 >= 0 && e.g74 != e.n11)
        fail("group 74 gives " + declared(e.g74) + " fit points but " + std::to_string(e.n11) + " (group 11) follow");
    }
  }

  std::string file_;
  std::size_t pairs_, pair_ = 0;
  std::string section_, header_variable_, entity_type_, block_;  // entity_type_: of the last group 0, any section
  bool expect_section_name_ = false, in_sequence_ = false;
  long current_ = -1, target_ = -1;
};

}  // namespace rollkin::io::dxf
