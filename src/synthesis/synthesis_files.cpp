// The files of `rollkin synthesize cam` and `rollkin synthesize gears` (include/rollkin/synthesis/synthesis_files.hpp).
#include "rollkin/synthesis/synthesis_files.hpp"

#include "rollkin/io/dxf/writer.hpp"
#include "rollkin/io/point_file.hpp"

#include <algorithm>
#include <sstream>

namespace rollkin::synthesis {
namespace {

std::string profile_text(const CamSpec& spec, const std::vector<Vec2<double>>& points) {
  return io::point_file_text("cam profile written by rollkin synthesize cam from " + spec.file +
                                 "\nclosed, counter-clockwise, in the cam's frame (the cam turns about the origin); units: " +
                                 (spec.length_label.empty() ? std::string("as the spec") : spec.length_label),
                             points);
}

/// A follower given as any contour, at the law's start in the world: 400 points of its domain placed in the
/// follower's frame (translating: the world's axes at the follower's origin; oscillating: the arm's at the pivot).
std::vector<Vec2<double>> follower_contour_points(const CamSpec& spec, const CamProfile& profile) {
  std::vector<Vec2<double>> out;
  if (spec.contact != FollowerContact::Contour) return out;
  const Contour<double>& c = spec.follower_shape->mechanism.contours[0];
  const SE2<double> place(spec.motion == FollowerMotion::Oscillating ? spec.start_angle : 0.0, profile.follower_origin);
  const int n = 400;
  for (int i = 0; i <= n; ++i) out.push_back(place.act(c.jet(c.domain().lo + (c.domain().hi - c.domain().lo) * i / n, 0).p));
  return out;
}

/// The cam (filled profile) and the follower at the law's start, y up, the cam centre marked.
std::string drawing_svg(const CamSpec& spec, const CamProfile& profile) {
  double lo_x = 0, hi_x = 0, lo_y = 0, hi_y = 0;
  auto grow = [&](const Vec2<double>& p, double r) {
    lo_x = std::min(lo_x, p.x() - r);
    hi_x = std::max(hi_x, p.x() + r);
    lo_y = std::min(lo_y, p.y() - r);
    hi_y = std::max(hi_y, p.y() + r);
  };
  for (const auto& p : profile.points) grow(p, 0);
  const Vec2<double> f = profile.follower_origin;
  const std::vector<Vec2<double>> shape = follower_contour_points(spec, profile);
  if (spec.contact == FollowerContact::Roller) grow(f, spec.roller_radius);
  else if (spec.contact == FollowerContact::Flat) grow(f, profile.face_half_length);
  for (const auto& p : shape) grow(p, 0);
  if (spec.motion == FollowerMotion::Oscillating) grow(spec.pivot, 0);
  const double margin = 0.05 * std::max(hi_x - lo_x, hi_y - lo_y);
  std::ostringstream s;
  s.precision(10);
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << lo_x - margin << " " << -hi_y - margin << " "
    << hi_x - lo_x + 2 * margin << " " << hi_y - lo_y + 2 * margin << "\">\n<g transform=\"scale(1,-1)\" fill=\"none\" "
    << "stroke=\"black\" stroke-width=\"" << margin / 10 << "\">\n<path id=\"cam\" fill=\"#dde\" d=\"M";
  for (const auto& p : profile.points) s << " " << p.x() << " " << p.y();
  s << " Z\"/>\n";
  if (spec.contact == FollowerContact::Contour) {
    s << "<path id=\"follower\" d=\"M";
    for (const auto& p : shape) s << " " << p.x() << " " << p.y();
    s << "\"/>\n";
  } else if (spec.contact == FollowerContact::Roller)
    s << "<circle id=\"roller\" cx=\"" << f.x() << "\" cy=\"" << f.y() << "\" r=\"" << spec.roller_radius << "\"/>\n";
  else
    s << "<line id=\"face\" x1=\"" << f.x() - profile.face_half_length << "\" y1=\"" << f.y() << "\" x2=\""
      << f.x() + profile.face_half_length << "\" y2=\"" << f.y() << "\"/>\n";
  if (spec.motion == FollowerMotion::Oscillating && spec.contact != FollowerContact::Contour)
    s << "<line id=\"arm\" x1=\"" << spec.pivot.x() << "\" y1=\"" << spec.pivot.y() << "\" x2=\"" << f.x() << "\" y2=\""
      << f.y() << "\"/>\n";
  s << "<circle id=\"cam_centre\" cx=\"0\" cy=\"0\" r=\"" << margin / 5 << "\"/>\n</g>\n</svg>\n";
  return s.str();
}

}  // namespace

CamFiles cam_files(const CamSpec& spec, const CamProfile& profile, const std::string& profile_file) {
  CamFiles f;
  f.profile = profile_text(spec, profile.points);
  f.dxf = io::dxf_text({io::spline_of(SampledProfile<double>(profile.points, SplineOptions<double>{true}), "CAM")}, spec.length_label);
  f.svg = drawing_svg(spec, profile);
  f.scene = cam_scene(spec, profile, profile_file).dump(2) + "\n";
  return f;
}

GearFiles gear_files(const GearSpec& spec, const GearDesign& design, const std::string& file1, const std::string& file2) {
  const std::string what = "pitch curve written by rollkin synthesize gears from " + spec.file + ", closed, counter-clockwise, ";
  GearFiles f;
  f.gear1 = io::point_file_text(what + "gear 1 (pivot at the origin)", design.pair.gear1);
  f.gear2 = io::point_file_text(what + "gear 2 (pivot at the origin of its frame)", design.pair.gear2);
  SplineOptions<double> closed;
  closed.closed = true;
  f.dxf = io::dxf_text({io::spline_of(SampledProfile<double>(design.pair.gear1, closed), "GEAR1"),
                        io::spline_of(SampledProfile<double>(design.pair.gear2, closed), "GEAR2")},
                       spec.length_label);
  f.scene = gear_scene(spec, design, file1, file2).dump(2) + "\n";
  return f;
}

}  // namespace rollkin::synthesis
