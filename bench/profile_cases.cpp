// rollkin_bench, the cases (bench/main.cpp, docs/benchmark.md): the profile representations of each scene,
// their sample counts and targets.
#include "profile_bench.hpp"

namespace rollkin::bench::profiles {
namespace {

ArcLengthMethod quadrature(Quadrature kind, int order, int panels) {
  ArcLengthMethod m;
  m.closed_form = false;
  m.rule.kind = kind;
  m.rule.order = order;
  m.rule.panels = panels;
  return m;
}

}  // namespace

std::string count_tag(long n) {
  if (n >= 1000 && n % 1000 == 0) {
    int e = 0;
    long m = n;
    while (m % 10 == 0) m /= 10, ++e;
    if (m == 1) return "1e" + std::to_string(e);
  }
  return std::to_string(n);
}

std::vector<Case> make_cases(bool quick) {
  std::vector<Case> cs;
  const double a = 0.5;
  // Reference example, analytic parabola.
  auto analytic_paper = [&](std::string name, std::string group, std::string tag, ArcLengthMethod arc, std::string target) {
    Case c;
    c.name = std::move(name);
    c.group = std::move(group);
    c.tag = std::move(tag);
    c.scene = "paper";
    c.target = std::move(target);
    c.profiles = [arc, a](const Samples&) {
      return std::vector<Shape>{Parabola<double>(a, -2, 2, arc), Circle<double>(1), Circle<double>(4)};
    };
    c.mechanism = [](const std::vector<Shape>& s) { return paper_scene(s[0], s[1], s[2]); };
    cs.push_back(c);
  };
  analytic_paper("paper: parabola closed form", "analytic (closed form)", "closed", {}, "analytic");
  for (auto [order, panels] : {std::pair{4, 1}, {8, 1}, {8, 4}, {16, 1}})
    analytic_paper("paper: parabola Gauss-Legendre " + std::to_string(order) + "x" + std::to_string(panels),
                   "analytic, Gauss-Legendre", "GL" + std::to_string(order) + "x" + std::to_string(panels),
                   quadrature(Quadrature::GaussLegendre, order, panels), "");
  for (int panels : {4, 16, 64, 256})
    analytic_paper("paper: parabola Simpson x" + std::to_string(panels), "analytic, Simpson (paper)",
                   "S" + std::to_string(panels), quadrature(Quadrature::NewtonCotes, 2, panels), "");
  {
    Case c;
    c.name = "paper: Bezier parabola";
    c.group = "Bezier (exact rational)";
    c.tag = "Bz";
    c.scene = "paper";
    c.profiles = [a](const Samples&) {
      return std::vector<Shape>{BezierPath<double>::parabola(a, -2, 2), Circle<double>(1), Circle<double>(4)};
    };
    c.mechanism = [](const std::vector<Shape>& s) { return paper_scene(s[0], s[1], s[2]); };
    cs.push_back(c);
    c.name = "paper: Bezier parabola + circles";
    c.tag = "Bz+circles";
    c.profiles = [a](const Samples&) {
      return std::vector<Shape>{BezierPath<double>::parabola(a, -2, 2), BezierPath<double>::circle(Vec2d(0, 0), 1),
                                BezierPath<double>::circle(Vec2d(0, 0), 4)};
    };
    cs.push_back(c);
  }
  for (long n : {50L, 100L, 1000L, 10000L, 100000L, 1000000L}) {
    Case c;
    c.name = "paper: sampled parabola " + count_tag(n);
    c.group = "sampled parabola (spline)";
    c.tag = "P" + count_tag(n);
    c.scene = "paper";
    c.points = n;
    c.target = n == 1000 ? "sampled1e3" : (n == 100000 ? "sampled1e5" : "");
    c.sweep = !(quick && n >= 100000);
    c.samples = [n, a] { return Samples{parabola_samples(a, -2, 2, static_cast<std::size_t>(n))}; };
    c.profiles = [](const Samples& s) {
      return std::vector<Shape>{SampledProfile<double>(s[0]), Circle<double>(1), Circle<double>(4)};
    };
    c.mechanism = [](const std::vector<Shape>& s) { return paper_scene(s[0], s[1], s[2]); };
    cs.push_back(c);
  }

  // Twin elliptical gears (a = 2, e = 0.5), rolling pair over a full turn.
  const double ga = 2, ge = 0.5, gb = ga * std::sqrt(1 - ge * ge);
  for (bool rolling : {true, false}) {
    const std::string scene = rolling ? "gears" : "cam";
    const double start = rolling ? 0 : deg_to_rad(30.0);
    const std::string kind = rolling ? "elliptical gears" : "elliptical cam pair";
    Case c;
    c.name = kind + ": analytic";
    c.group = rolling ? "ellipse gears, analytic" : "ellipse cam, analytic";
    c.tag = rolling ? "EG analytic" : "EC analytic";
    c.scene = scene;
    c.profiles = [ga, gb](const Samples&) { return std::vector<Shape>{Ellipse<double>(ga, gb), Ellipse<double>(ga, gb)}; };
    c.mechanism = [=](const std::vector<Shape>& s) { return gear_scene(s[0], s[1], ga, ge, rolling, start); };
    cs.push_back(c);
    std::vector<long> counts = {100, 1000, 10000};
    if (!quick) counts.push_back(100000);
    for (long n : counts) {
      Case d = c;
      d.name = kind + ": sampled " + count_tag(n);
      d.group = rolling ? "ellipse gears, sampled" : "ellipse cam, sampled";
      d.tag = (rolling ? "EG" : "EC") + count_tag(n);
      d.points = n;
      d.samples = [=] { return Samples{ellipse_samples(ga, gb, static_cast<std::size_t>(n))}; };
      d.profiles = [](const Samples& s) {
        SplineOptions<double> o;
        o.closed = true;
        const SampledProfile<double> p(s[0], o);
        return std::vector<Shape>{p, p};  // both gears share the pitch curve (two copies, as a scene would)
      };
      cs.push_back(d);
    }
  }

  // Non-circular gear pair synthesised from f(p) = p + 0.3 sin p (sampled pitch curves only).
  for (bool rolling : {true, false}) {
    std::vector<long> counts = {1000, 10000};
    if (!quick) counts.push_back(100000);
    for (long n : counts) {
      Case c;
      const std::string kind = rolling ? "non-circular gears" : "non-circular cam pair";
      c.name = kind + ": sampled " + count_tag(n);
      c.group = rolling ? "non-circular gears, sampled" : "non-circular cam, sampled";
      c.tag = (rolling ? "NG" : "NC") + count_tag(n);
      c.scene = rolling ? "noncircular" : "noncircular_cam";
      c.points = n;
      c.samples = [n] {
        const GearPair<double> g = NonCircularGears{}.pitch_curves(static_cast<std::size_t>(n));
        return Samples{g.gear1, g.gear2};
      };
      c.profiles = [](const Samples& s) {
        SplineOptions<double> o;
        o.closed = true;
        return std::vector<Shape>{SampledProfile<double>(s[0], o), SampledProfile<double>(s[1], o)};
      };
      const double start = rolling ? 0 : deg_to_rad(30.0);
      c.mechanism = [rolling, start](const std::vector<Shape>& s) { return NonCircularGears{}.scene(s[0], s[1], rolling, start); };
      cs.push_back(c);
    }
  }
  return cs;
}

}  // namespace rollkin::bench::profiles
