// The files of `rollkin synthesize` and the synthesis pictures of Python (rollkin/output/synthesis_files.hpp).
#include "rollkin/output/synthesis_files.hpp"

#include "rollkin/io/dxf/writer.hpp"
#include "rollkin/io/point_file.hpp"
#include "rollkin/io/svg/markup.hpp"
#include "rollkin/output/drawing.hpp"
#include "rollkin/output/svg_drawing.hpp"

namespace rollkin::output {
namespace {

/// The canvas and strokes of a synthesis picture: the size of one panel of `rollkin solve --draw`, each body in
/// the colour --draw gives its link in the written scene (link 1, then link 2; the ground black).
constexpr int kWidth = 450, kHeight = 360;
constexpr double kMargin = 24;

io::Stroke body_stroke(std::size_t link) {
  io::Stroke s;
  s.color = io::palette_color(link);
  s.width = 1.6;
  return s;
}

io::Fill body_fill(std::size_t link) { return io::Fill{io::palette_color(link), 0.15}; }

/// A ground pivot as --draw marks it: a square, labelled.
void add_pivot(io::SvgDrawing& d, const Vec2<double>& at, const std::string& name) {
  d.add_point(at, "#000000", 5, io::Marker::Square);
  d.add_text(at, name, 12, "#000000", 6, 14);
}

/// A closed spline through `points` (the one a `samples` contour fits) as a DXF SPLINE on `layer`.
io::DxfSpline closed_spline(const std::vector<Vec2<double>>& points, const std::string& layer) {
  SplineOptions<double> closed;
  closed.closed = true;
  return io::spline_of(SampledProfile<double>(points, closed), layer);
}

/// A follower given as any contour, at the law's start in the world: 400 points of its domain placed in the
/// follower's frame (translating: the world's axes at the follower's origin; oscillating: the arm's at the pivot).
std::vector<Vec2<double>> follower_contour_points(const synthesis::CamSpec& spec, const synthesis::CamProfile& profile) {
  std::vector<Vec2<double>> out;
  if (spec.contact != synthesis::FollowerContact::Contour) return out;
  const Contour<double>& c = spec.follower_shape->mechanism.contours[0];
  const SE2<double> place(spec.motion == synthesis::FollowerMotion::Oscillating ? spec.start_angle : 0.0, profile.follower_origin);
  const int n = 400;
  for (int i = 0; i <= n; ++i) out.push_back(place.act(c.jet(c.domain().lo + (c.domain().hi - c.domain().lo) * i / n, 0).p));
  return out;
}

}  // namespace

std::string cam_svg(const synthesis::CamSpec& spec, const synthesis::CamProfile& profile) {
  io::SvgDrawing d(kWidth, kHeight, kMargin);
  d.set_title(base_name(spec.file) + ": at the law's start");
  d.add_polyline(profile.points, body_stroke(1), true, body_fill(1), "cam");
  const Vec2<double> f = profile.follower_origin;
  switch (spec.contact) {
    case synthesis::FollowerContact::Contour:
      d.add_polyline(follower_contour_points(spec, profile), body_stroke(2), false, {}, "follower");
      break;
    case synthesis::FollowerContact::Roller: d.add_circle(f, spec.roller_radius, body_stroke(2), {}, "roller"); break;
    case synthesis::FollowerContact::Flat: {
      const Vec2<double> half(profile.face_half_length, 0);
      d.add_polyline({Vec2<double>(f - half), Vec2<double>(f + half)}, body_stroke(2), false, {}, "face");
      break;
    }
  }
  if (spec.motion == synthesis::FollowerMotion::Oscillating) {
    if (spec.contact != synthesis::FollowerContact::Contour) {
      io::Stroke arm = body_stroke(2);
      arm.width = 2.4;  // as --draw draws a link's body
      d.add_polyline({spec.pivot, f}, arm, false, {}, "arm");
    }
    add_pivot(d, spec.pivot, "follower");  // the revolute of cam_scene
  }
  d.add_point(profile.contact, "#d62728", 3.5, io::Marker::Dot);
  add_pivot(d, Vec2<double>::Zero(), "cam");  // the revolute of cam_scene
  return d.to_svg();
}

CamFiles cam_files(const synthesis::CamSpec& spec, const synthesis::CamProfile& profile, const std::string& profile_file) {
  CamFiles f;
  f.profile = io::PointFileText()
                  .comment("cam profile written by rollkin synthesize cam from " + spec.file)
                  .comment("closed, counter-clockwise, in the cam's frame (the cam turns about the origin); units: " +
                           (spec.length_label.empty() ? std::string("as the spec") : spec.length_label))
                  .points(profile.points)
                  .text();
  f.dxf = io::dxf_text({closed_spline(profile.points, "CAM")}, spec.length_label);
  f.svg = cam_svg(spec, profile);
  f.scene = synthesis::cam_scene(spec, profile, profile_file).dump(2) + "\n";
  return f;
}

std::string gear_svg(const synthesis::GearSpec& spec, const synthesis::GearDesign& design) {
  io::SvgDrawing d(kWidth, kHeight, kMargin);
  d.set_title(base_name(spec.file) + ": pitch curves at gear1.phi = 0");
  // The assembly pose of gear_scene: gear 2's pivot at (E, 0), the gear turned by -f(0).
  const Vec2<double> pivot2(spec.centre_distance, 0);
  const SE2<double> place2(-synthesis::transmission(spec).f(0), pivot2);
  std::vector<Vec2<double>> gear2;
  for (const Vec2<double>& p : design.pair.gear2) gear2.push_back(place2.act(p));
  d.add_polyline(design.pair.gear1, body_stroke(1), true, body_fill(1), "gear1");
  d.add_polyline(gear2, body_stroke(2), true, body_fill(2), "gear2");
  d.add_point(design.pair.gear1.front(), "#d62728", 3.5, io::Marker::Dot);  // the contact: gear 1's first sample
  add_pivot(d, Vec2<double>::Zero(), "gear1");
  add_pivot(d, pivot2, "gear2");
  return d.to_svg();
}

GearFiles gear_files(const synthesis::GearSpec& spec, const synthesis::GearDesign& design, const std::string& file1,
                     const std::string& file2) {
  const std::string what = "pitch curve written by rollkin synthesize gears from " + spec.file + ", closed, counter-clockwise, ";
  GearFiles f;
  f.gear1 = io::point_file_text(what + "gear 1 (pivot at the origin)", design.pair.gear1);
  f.gear2 = io::point_file_text(what + "gear 2 (pivot at the origin of its frame)", design.pair.gear2);
  f.dxf = io::dxf_text({closed_spline(design.pair.gear1, "GEAR1"), closed_spline(design.pair.gear2, "GEAR2")}, spec.length_label);
  f.svg = gear_svg(spec, design);
  f.scene = synthesis::gear_scene(spec, design, file1, file2).dump(2) + "\n";
  return f;
}

std::string envelope_dxf(const std::vector<Vec2<double>>& points, bool closed, const std::string& length_unit) {
  SplineOptions<double> options;
  options.closed = closed;
  return io::dxf_text({io::spline_of(SampledProfile<double>(points, options), "ENVELOPE")}, length_unit);
}

}  // namespace rollkin::output
