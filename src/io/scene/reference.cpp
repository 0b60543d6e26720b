#include "rollkin/io/csv.hpp"
#include "rollkin/io/scene/reader.hpp"

namespace rollkin::io {

ReferenceSweep scene_reference(const Scene& scene, const Sweep& sweep, int digits) {
  const Mechanism<double>& m = scene.mechanism;
  const bool decimal = scene.angle_unit == AngleUnit::Degree || m.variables[sweep.variable].kind != ParamKind::Angle;
  if (!decimal) return reference_sweep(m, scene.guess, scene.held, sweep.driver, sweep_inputs(sweep), digits);
  // The grid's values as the decimals they stand for: each is the double nearest to the decimal from + k step
  // (solve/sweep_grid.hpp), whose shortest text is that decimal ("-49.999", not -49.999000000000002).
  std::vector<std::string> values;
  for (double v : sweep_values(sweep)) values.push_back(format_double(v));
  return reference_sweep_decimal(m, scene.guess, scene.held, sweep.driver, values, digits);
}

}  // namespace rollkin::io
