// High-precision references (see include/rollkin/reference.hpp). The only translation unit of the library
// that compiles the solver in MPFR: 30, 50 and 100 digits.
#include "rollkin/reference.hpp"

#include "rollkin/io/atomic_file.hpp"
#include "rollkin/io/input_file.hpp"
#include "rollkin/io/units.hpp"
#include "rollkin/scalar_mpfr.hpp"
#include "rollkin/solve/continuation.hpp"

#include <sstream>
#include <stdexcept>

namespace rollkin {

namespace {

template <class S> std::string decimal(const S& x, int digits) {
  using std::isfinite;
  if (!(x == x)) return "nan";
  return x.str(digits, std::ios_base::fmtflags(0));
}

template <class S> S display_scale(const Mechanism<S>& m, int var) {
  return m.variables[var].kind == ParamKind::Angle ? rad_to_deg(S(1)) : S(1);
}

template <class S> std::string limit_text(const SolveReport<S>& r, int digits) {
  return std::string(to_string(r.status)) + " at " + decimal(r.limit_input, digits) + ": " + r.detail;
}

}  // namespace

template <class S>
ReferenceSweep reference_sweep_mp(const Mechanism<S>& m, const VectorX<S>& guess, const std::vector<int>& held,
                                  int driver, const std::vector<S>& inputs, const ReferenceOptions& options) {
  const int digits = std::numeric_limits<S>::digits10;
  ReferenceSweep out;
  out.digits = digits;
  for (const auto& v : m.variables) {
    out.variables.push_back(v.name);
    out.kinds.push_back(v.kind);
  }
  SolveData<S> sd(m);
  sd.settings.consistency_tolerance = S(options.consistency_tolerance);
  VectorX<S> q = guess;
  const SolveReport<S> assembly = assemble(m, q, sd, held);
  out.assembly_status = assembly.status;
  out.assembly_detail = assembly.detail;
  out.assembly_residual = decimal(assembly.residual, 3);
  out.rank = assembly.rank;
  out.equations = assembly.equations;
  out.unknowns = assembly.unknowns;
  for (Eigen::Index i = 0; i < q.size(); ++i) out.assembly_q_raw.push_back(decimal(q(i), digits));

  const SweepResult<S> r = sweep(m, sd, q, assembly, driver, inputs);
  const int var = m.drivers.at(driver);
  for (const auto& lim : r.limits) out.limits.push_back(limit_text(lim, digits));
  for (const auto& pose : r.poses) {
    ReferencePose p;
    p.status = pose.report.status;
    p.iterations = pose.report.iterations;
    p.input = decimal(S(pose.input * display_scale(m, var)), digits);
    if (pose.report.has_pose()) {
      p.residual = decimal(pose.report.residual, 3);
      for (Eigen::Index i = 0; i < pose.q.size(); ++i) {
        p.q_raw.push_back(decimal(pose.q(i), digits));
        p.q.push_back(decimal(S(pose.q(i) * display_scale(m, static_cast<int>(i))), digits));
      }
    }
    out.poses.push_back(std::move(p));
  }
  return out;
}

namespace {

template <unsigned D>
ReferenceSweep run_cast(const Mechanism<double>& mech, const VectorX<double>& guess, const std::vector<int>& held,
                        int driver, const std::vector<std::string>* decimal_inputs,
                        const std::vector<double>* inputs, const ReferenceOptions& options) {
  using S = mpfr_scalar<D>;
  const Mechanism<S> m = mech.template cast<S>();
  const VectorX<S> g = guess.template cast<S>();
  std::vector<S> in;
  const int var = m.drivers.at(driver);
  if (decimal_inputs) {
    const S to_solver = m.variables[var].kind == ParamKind::Angle ? io::radians_per<S>(io::AngleUnit::Degree) : S(1);
    for (const auto& s : *decimal_inputs) in.push_back(S(s) * to_solver);
  } else {
    for (double x : *inputs) in.push_back(S(x));
  }
  return reference_sweep_mp<S>(m, g, held, driver, in, options);
}

ReferenceSweep dispatch(const Mechanism<double>& mech, const VectorX<double>& guess, const std::vector<int>& held,
                        int driver, const std::vector<std::string>* dec, const std::vector<double>* in, int digits,
                        const ReferenceOptions& options) {
  if (driver < 0 || driver >= static_cast<int>(mech.drivers.size()))
    throw std::invalid_argument("reference_sweep: driver " + std::to_string(driver) + " out of range");
  if (guess.size() != mech.variable_count())
    throw std::invalid_argument("reference_sweep: the guess has " + std::to_string(guess.size()) + " entries, the mechanism " +
                                std::to_string(mech.variable_count()) + " variables");
  switch (digits) {
    case 30: return run_cast<30>(mech, guess, held, driver, dec, in, options);
    case 50: return run_cast<50>(mech, guess, held, driver, dec, in, options);
    case 100: return run_cast<100>(mech, guess, held, driver, dec, in, options);
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

template ReferenceSweep reference_sweep_mp<mpfr_scalar<30>>(const Mechanism<mpfr_scalar<30>>&, const VectorX<mpfr_scalar<30>>&,
                                                            const std::vector<int>&, int, const std::vector<mpfr_scalar<30>>&,
                                                            const ReferenceOptions&);
template ReferenceSweep reference_sweep_mp<mpfr_scalar<50>>(const Mechanism<mpfr_scalar<50>>&, const VectorX<mpfr_scalar<50>>&,
                                                            const std::vector<int>&, int, const std::vector<mpfr_scalar<50>>&,
                                                            const ReferenceOptions&);
template ReferenceSweep reference_sweep_mp<mpfr_scalar<100>>(const Mechanism<mpfr_scalar<100>>&,
                                                             const VectorX<mpfr_scalar<100>>&, const std::vector<int>&, int,
                                                             const std::vector<mpfr_scalar<100>>&, const ReferenceOptions&);

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
