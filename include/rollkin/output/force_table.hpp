// The --forces columns of a solved sweep (docs/forces.md), computed once per sweep by output::sweep_forces
// (output/sweep_forces.hpp) and read by the result table (output/sweep_table.hpp) row by row.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rollkin::io {

struct ForceTable {
  std::vector<std::string> names;   // the columns, in output order
  std::vector<double> values;       // row-major: rows x names.size(); empty_cell() where not defined
  std::vector<std::string> status;  // per row: "separation", "slip", or "" (the sweep's own status)

  std::size_t columns() const { return names.size(); }
  const double* row(std::size_t r) const { return values.data() + r * names.size(); }
};

}  // namespace rollkin::io
