// Measuring helpers of the benchmark: wall-clock medians, the process's memory counters, the machine.
#pragma once

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

namespace rollkin::bench {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

inline double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/// A field of /proc/self/status in kB ("VmHWM", "VmRSS"), or -1.
inline long proc_status_kb(const std::string& field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, field.size() + 1, field + ":") == 0) return std::stol(line.substr(field.size() + 1));
  return -1;
}

/// Resets the peak RSS (VmHWM) to the current RSS (Linux >= 4.0: "5" to /proc/self/clear_refs).
/// Returns false where that is not allowed; the deltas are then against the earlier peak.
inline bool reset_peak_rss() {
  std::ofstream out("/proc/self/clear_refs");
  if (!out) return false;
  out << "5" << std::endl;
  return static_cast<bool>(out);
}

/// Peak and retained resident memory of one operation, in bytes.
struct MemoryDelta {
  double peak = 0;      // VmHWM after - VmRSS before (peak reached while the operation ran)
  double retained = 0;  // VmRSS after - VmRSS before
};

template <class F> MemoryDelta measure_memory(F&& f) {
  reset_peak_rss();
  const long rss0 = proc_status_kb("VmRSS");
  f();
  MemoryDelta d;
  d.peak = 1024.0 * static_cast<double>(proc_status_kb("VmHWM") - rss0);
  d.retained = 1024.0 * static_cast<double>(proc_status_kb("VmRSS") - rss0);
  return d;
}

inline std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(colon + 2);
    }
  return "unknown";
}

/// The first three fields of /proc/loadavg (other work on a shared machine skews the timings).
inline std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

inline long cpu_count() { return sysconf(_SC_NPROCESSORS_ONLN); }

inline std::string compiler() {
  std::ostringstream os;
#if defined(__clang__)
  os << "clang " << __clang_major__ << "." << __clang_minor__ << "." << __clang_patchlevel__;
#elif defined(__GNUC__)
  os << "g++ " << __GNUC__ << "." << __GNUC_MINOR__ << "." << __GNUC_PATCHLEVEL__;
#else
  os << "unknown compiler";
#endif
#ifdef NDEBUG
  os << ", NDEBUG";
#else
  os << ", assertions on (not a Release build)";
#endif
#ifdef __OPTIMIZE__
  os << ", optimised";
#else
  os << ", NOT optimised";
#endif
  return os.str();
}

}  // namespace rollkin::bench
