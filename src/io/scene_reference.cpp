#include "rollkin/io/scene.hpp"

#include <cstdio>

namespace rollkin::io {

ReferenceSweep scene_reference(const Scene& scene, const Sweep& sweep, int digits) {
  const Mechanism<double>& m = scene.mechanism;
  const bool decimal = scene.angle_unit == AngleUnit::Degree || m.variables[sweep.variable].kind != ParamKind::Angle;
  if (!decimal) return reference_sweep(m, scene.guess, scene.held, sweep.driver, sweep_inputs(sweep), digits);
  std::vector<std::string> values;
  for (double v : sweep_values(sweep)) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", v);  // the file value's double, exactly as decimal
    values.emplace_back(text);
  }
  return reference_sweep_decimal(m, scene.guess, scene.held, sweep.driver, values, digits);
}

}  // namespace rollkin::io
