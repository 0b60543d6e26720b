// High-precision references (see include/rollkin/reference.hpp): the choice of precision and the CSV. The
// solver in MPFR is compiled once per precision in src/reference_mp30.cpp, reference_mp50.cpp and
// reference_mp100.cpp (src/reference_mp.hxx).
#include "rollkin/reference.hpp"

#include "rollkin/io/atomic_file.hpp"
#include "rollkin/io/input_file.hpp"
#include "rollkin/io/units.hpp"

#include <sstream>
#include <stdexcept>

namespace rollkin {

namespace detail {
/// reference_sweep() at D = 30, 50 or 100 digits, compiled in src/reference_mp<D>.cpp.
template <unsigned D>
ReferenceSweep reference_run(const Mechanism<double>& mech, const VectorX<double>& guess, const std::vector<int>& held,
                             int driver, const std::vector<std::string>* decimal_inputs,
                             const std::vector<double>* inputs, const ReferenceOptions& options);
}  // namespace detail

namespace {

ReferenceSweep dispatch(const Mechanism<double>& mech, const VectorX<double>& guess, const std::vector<int>& held,
                        int driver, const std::vector<std::string>* dec, const std::vector<double>* in, int digits,
                        const ReferenceOptions& options) {
  if (driver < 0 || driver >= static_cast<int>(mech.drivers.size()))
    throw std::invalid_argument("reference_sweep: driver " + std::to_string(driver) + " out of range");
  if (guess.size() != mech.variable_count())
    throw std::invalid_argument("reference_sweep: the guess has " + std::to_string(guess.size()) + " entries, the mechanism " +
                                std::to_string(mech.variable_count()) + " variables");
  switch (digits) {
    case 30: return detail::reference_run<30>(mech, guess, held, driver, dec, in, options);
    case 50: return detail::reference_run<50>(mech, guess, held, driver, dec, in, options);
    case 100: return detail::reference_run<100>(mech, guess, held, driver, dec, in, options);
    default: throw std::invalid_argument("reference_sweep: digits must be 30, 50 or 100, not " + std::to_string(digits));
  }
}

}  // namespace

ReferenceSweep reference_sweep(const Mechanism<double>& mech, const VectorX<double>& guess, const std::vector<int>& held,
                               int driver, const std::vector<double>& inputs, int digits, const ReferenceOptions& options) {
  return dispatch(mech, guess, held, driver, nullptr, &inputs, digits, options);
}

ReferenceSweep reference_sweep_decimal(const Mechanism<double>& mech, const VectorX<double>& guess,
                                       const std::vector<int>& held, int driver, const std::vector<std::string>& inputs,
                                       int digits, const ReferenceOptions& options) {
  return dispatch(mech, guess, held, driver, &inputs, nullptr, digits, options);
}

// ---- CSV -----------------------------------------------------------------------------------------------

std::string reference_csv_text(const ReferenceSweep& ref, const Mechanism<double>& mech) {
  if (mech.drivers.empty()) throw std::invalid_argument("reference_csv_text: the mechanism has no driver");
  const int input = mech.drivers[0];
  if (static_cast<int>(ref.variables.size()) != mech.variable_count())
    throw std::invalid_argument("reference_csv_text: the sweep does not belong to this mechanism");
  std::ostringstream os;
  os << ref.variables[input];
  for (int i = 0; i < mech.variable_count(); ++i)
    if (i != input) os << ',' << ref.variables[i];
  os << ",residual,status\n";
  for (const auto& p : ref.poses) {
    os << p.input;
    const bool ok = p.status == SolveStatus::Converged || p.status == SolveStatus::Singular;
    for (int i = 0; i < mech.variable_count(); ++i)
      if (i != input) os << ',' << (ok ? p.q[i] : std::string("nan"));
    os << ',' << (ok ? p.residual : std::string("nan")) << ',' << to_string(p.status) << '\n';
  }
  return os.str();
}

void write_reference_csv(const ReferenceSweep& ref, const Mechanism<double>& mech, const std::string& path) {
  io::write_file_atomic(path, reference_csv_text(ref, mech));
}

int ReferenceTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return static_cast<int>(i);
  return -1;
}

ReferenceTable read_reference_csv(const std::string& path) {
  std::istringstream in(io::read_input_file(path, "the reference file"));
  auto split = [](const std::string& line) {
    std::vector<std::string> f;
    std::string cur;
    std::istringstream ls(line);
    while (std::getline(ls, cur, ',')) f.push_back(cur);
    if (!line.empty() && line.back() == ',') f.emplace_back();
    return f;
  };
  ReferenceTable t;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    if (t.columns.empty()) {
      t.columns = split(line);
      continue;
    }
    auto row = split(line);
    if (row.size() != t.columns.size())
      throw std::runtime_error(path + ":" + std::to_string(number) + ": " + std::to_string(row.size()) + " fields, expected " +
                               std::to_string(t.columns.size()));
    t.rows.push_back(std::move(row));
  }
  if (t.columns.empty()) throw std::runtime_error("reference file '" + path + "' is empty");
  return t;
}

}  // namespace rollkin
