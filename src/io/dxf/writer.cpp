#include "rollkin/io/dxf/writer.hpp"

#include "rollkin/io/temporary_file.hpp"

#include <dxflib/dl_dxf.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace rollkin::io {
namespace {

/// libdxflib writes to a file by name only: an unnamed scratch file in $TMPDIR, opened by libdxflib through
/// /proc/self/fd/N (io::TemporaryFile), so that nothing is left whatever ends the run.
class ScratchFile {
 public:
  ScratchFile() : file_(std::filesystem::temp_directory_path().string(), "rollkin-dxf-") {}
  std::string path() const { return file_.path(); }
  std::string contents() const {
    std::ifstream in(file_.path(), std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

 private:
  TemporaryFile file_;
};

/// libdxflib's writer with every real written as the shortest decimal that reads back to the same double
/// (std::to_chars). DL_WriterA::dxfReal prints "%.16f": 16 digits after the point, so a contour of size 1e-12
/// kept 4 significant digits and one of size 1e-17 was written as zeros (a degenerate SPLINE the reader
/// refuses), found by the writers' contract test (tests/test_io_writers_contract.cpp). A magnitude below
/// 2.2e-308 (subnormal) is written as 0: the reader's range (io/dxf.hpp), and below any drawing's round-off.
class ExactWriter : public DL_WriterA {
 public:
  using DL_WriterA::DL_WriterA;
  void dxfReal(int gc, double value) const override {
    if (std::fpclassify(value) == FP_SUBNORMAL) value = 0;
    char text[32];
    const std::to_chars_result r = std::to_chars(text, text + sizeof text, value);
    dxfString(gc, std::string(text, r.ptr));
  }
};

/// $INSUNITS code of a scene's length unit label (DXF reference: 1 in, 2 ft, 4 mm, 5 cm, 6 m; 0 unitless).
int insunits_code(const std::string& unit) {
  if (unit == "in") return 1;
  if (unit == "ft") return 2;
  if (unit == "mm") return 4;
  if (unit == "cm") return 5;
  if (unit == "m") return 6;
  return 0;
}

void write_tables(DL_Dxf& dxf, DL_WriterA& dw, const std::vector<std::string>& layers) {
  dw.sectionTables();
  dxf.writeVPort(dw);
  dw.tableLinetypes(1);
  dxf.writeLinetype(dw, DL_LinetypeData("CONTINUOUS", "Solid line", 0, 0, 0.0));
  dw.tableEnd();
  dw.tableLayers(static_cast<int>(layers.size()) + 1);
  dxf.writeLayer(dw, DL_LayerData("0", 0), DL_Attributes("", 7, 0, "CONTINUOUS", 1.0));
  for (std::size_t k = 0; k < layers.size(); ++k)
    dxf.writeLayer(dw, DL_LayerData(layers[k], 0), DL_Attributes("", static_cast<int>(1 + k % 6), 0, "CONTINUOUS", 1.0));
  dw.tableEnd();
  dw.tableStyle(1);
  dxf.writeStyle(dw, DL_StyleData("Standard", 0, 0.0, 1.0, 0.0, 0, 2.5, "txt", ""));
  dw.tableEnd();
  dxf.writeView(dw);
  dxf.writeUcs(dw);
  dw.tableAppid(1);
  dxf.writeAppid(dw, "ACAD");
  dw.tableEnd();
  dxf.writeDimStyle(dw, 1, 1, 1, 1, 1);
  dxf.writeBlockRecord(dw);
  dw.tableEnd();
  dw.sectionEnd();
}

void write_blocks(DL_Dxf& dxf, DL_WriterA& dw) {
  dw.sectionBlocks();
  for (const char* name : {"*Model_Space", "*Paper_Space"}) {
    dxf.writeBlock(dw, DL_BlockData(name, 0, 0.0, 0.0, 0.0));
    dxf.writeEndBlock(dw, name);
  }
  dw.sectionEnd();
}

void write_spline(DL_Dxf& dxf, DL_WriterA& dw, const DxfSpline& s) {
  const int planar = 8, closed = 1;
  dxf.writeSpline(dw,
                  DL_SplineData(s.degree, static_cast<int>(s.knots.size()), static_cast<int>(s.control.size()), 0,
                                planar | (s.closed ? closed : 0)),
                  DL_Attributes(s.layer, 256, 0, "BYLAYER", 1.0));
  for (double k : s.knots) dxf.writeKnot(dw, DL_KnotData(k));
  for (const Vec2<double>& c : s.control) dxf.writeControlPoint(dw, DL_ControlPointData(c.x(), c.y(), 0.0, 1.0));
}

}  // namespace

DxfSpline spline_of(const SampledProfile<double>& p, const std::string& layer) {
  DxfSpline s;
  s.layer = layer;
  s.closed = p.domain().closed;
  const std::vector<double>& u = p.knots();
  s.knots.assign(4, u.front());
  for (std::size_t k = 1; k + 1 < u.size(); ++k) s.knots.insert(s.knots.end(), 3, u[k]);
  s.knots.insert(s.knots.end(), 4, u.back());
  for (std::size_t k = 0; k + 1 < u.size(); ++k) {
    const double h = u[k + 1] - u[k];
    // At a knot the spline's value and slope are continuous (C2 spline); the closed spline's last knot wraps
    // to its first, so the curve closes exactly.
    const Jet<double> a = p.jet(u[k], 1), b = p.jet(u[k + 1], 1);
    if (k == 0) s.control.push_back(a.p);
    s.control.push_back(a.p + h * a.d1 / 3.0);
    s.control.push_back(b.p - h * b.d1 / 3.0);
    s.control.push_back(b.p);
  }
  return s;
}

DxfSpline polyline_spline(const std::vector<Vec2<double>>& points, const std::string& layer) {
  DxfSpline s;
  s.layer = layer;
  s.degree = 1;
  s.control = points;
  s.knots.push_back(0.0);
  for (std::size_t k = 0; k < points.size(); ++k) s.knots.push_back(static_cast<double>(k));
  s.knots.push_back(static_cast<double>(points.size() - 1));
  return s;
}

std::string dxf_text(const std::vector<DxfSpline>& splines, const std::string& length_unit) {
  std::vector<std::string> layers;
  for (const DxfSpline& s : splines)
    if (std::find(layers.begin(), layers.end(), s.layer) == layers.end()) layers.push_back(s.layer);
  ScratchFile scratch;
  {
    DL_Dxf dxf;
    // DL_Dxf::out sets the document's version; its writer is replaced by the exact one on the same file.
    if (!std::unique_ptr<DL_WriterA>(dxf.out(scratch.path().c_str(), DL_Codes::AC1015)))
      throw std::runtime_error("the DXF writer cannot open its scratch file " + scratch.path());
    std::unique_ptr<DL_WriterA> dw = std::make_unique<ExactWriter>(scratch.path().c_str(), DL_Codes::AC1015);
    if (dw->openFailed()) throw std::runtime_error("the DXF writer cannot open its scratch file " + scratch.path());
    dxf.writeHeader(*dw);
    dw->dxfString(9, "$INSUNITS");
    dw->dxfInt(70, insunits_code(length_unit));
    dw->sectionEnd();
    write_tables(dxf, *dw, layers);
    write_blocks(dxf, *dw);
    dw->sectionEntities();
    for (const DxfSpline& s : splines) write_spline(dxf, *dw, s);
    dw->sectionEnd();
    dxf.writeObjects(*dw);
    dxf.writeObjectsEnd(*dw);
    dw->dxfEOF();
    dw->close();
  }
  return scratch.contents();
}

}  // namespace rollkin::io
