// A sweep kept in an unlinked temporary file (rollkin/output/sweep_file.hpp).
#include "rollkin/output/sweep_file.hpp"



#include <fcntl.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace rollkin::io {
namespace {

std::string temporary_directory() {
  const char* dir = std::getenv("TMPDIR");
  return dir && *dir ? dir : "/tmp";
}

std::string megabytes(double bytes) { return std::to_string(static_cast<long long>(bytes / 1e6 + 0.5)) + " MB"; }

[[noreturn]] void fail(const std::string& what, const std::string& dir) {
  throw std::runtime_error("the sweep's temporary file in " + dir + ": " + what + " (" + std::strerror(errno) +
                           "); set TMPDIR to a directory with room, or ask for fewer poses");
}

/// An unlinked file in `dir` (O_TMPFILE, else a named file removed at once).
int unlinked_file(const std::string& dir) {
#ifdef O_TMPFILE
  const int fd = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd >= 0) return fd;
#endif
  std::string name = dir + "/rollkin-sweep-XXXXXX";
  const int named = ::mkstemp(name.data());
  if (named < 0) fail("cannot be created", dir);
  ::unlink(name.c_str());
  return named;
}

}  // namespace

SweepFile::SweepFile(const SolveReport<double>& assembly, const std::vector<double>& inputs, int variables)
    : SweepSummary<double>(assembly, inputs.size(), assembly.ok() ? SolveStatus::NotReached : assembly.status),
      inputs_(&inputs),
      variables_(variables),
      row_bytes_(2 * static_cast<std::size_t>(variables) * sizeof(double) + sizeof(Record)),
      dir_(temporary_directory()) {
  const double needed = static_cast<double>(row_bytes_) * static_cast<double>(inputs.size());
  struct statvfs fs {};
  if (::statvfs(dir_.c_str(), &fs) == 0 && needed > static_cast<double>(fs.f_bavail) * static_cast<double>(fs.f_frsize)) {
    errno = ENOSPC;
    fail(std::to_string(inputs.size()) + " poses need " + megabytes(needed) + ", the file system has " +
             megabytes(static_cast<double>(fs.f_bavail) * static_cast<double>(fs.f_frsize)) + " free",
         dir_);
  }
  fd_ = unlinked_file(dir_);
  // Sized once: rows never written (not reached) read back as zeros, as sweep() leaves their columns.
  if (::ftruncate(fd_, static_cast<off_t>(needed)) != 0) {
    ::close(fd_);
    fail("cannot hold " + megabytes(needed), dir_);
  }
  buffer_.resize(kWindowRows * row_bytes_);
}

SweepFile::~SweepFile() {
  if (fd_ >= 0) ::close(fd_);
}

double* SweepFile::writable_row(std::size_t k) {
  const bool in_window = k >= window_ && k < window_ + kWindowRows;
  const bool extends = dirty_lo_ == dirty_hi_ || (k >= dirty_lo_ && k < dirty_hi_) || k == dirty_hi_ || k + 1 == dirty_lo_;
  if (!in_window || !extends) {
    flush();
    if (!in_window) window_ = k >= last_ ? k : (k + 1 >= kWindowRows ? k + 1 - kWindowRows : 0);
    dirty_lo_ = dirty_hi_ = k;
  }
  last_ = k;
  char* row = buffer_.data() + (k - window_) * row_bytes_;
  if (k < dirty_lo_ || k >= dirty_hi_) {  // a new row: no values until set_pose writes them
    std::memset(row, 0, row_bytes_);
    dirty_lo_ = std::min(dirty_lo_, k);
    dirty_hi_ = std::max(dirty_hi_, k + 1);
  }
  return reinterpret_cast<double*>(row);
}

void SweepFile::record_report(std::size_t k, const SolveReport<double>& rep) {
  SweepSummary<double>::set_report(k, rep);
  Record r{rep.residual, rep.condition, rep.iterations, rep.evaluations, rep.rank, 0};
  if (!SweepResult<double>::fits_record(rep, assembly)) {
    full_.push_back(rep);
    r.full = static_cast<std::int32_t>(full_.size());
  }
  std::memcpy(writable_row(k) + 2 * variables_, &r, sizeof r);
}

void SweepFile::set_report(std::size_t k, const SolveReport<double>& rep) { record_report(k, rep); }

void SweepFile::set_interpolated_pose(std::size_t, const VectorX<double>&, const SolveReport<double>&) {
  throw std::logic_error("SweepFile::set_interpolated_pose: a sink that keeps values is given solved poses only");
}

void SweepFile::share_report(std::size_t k, std::size_t like) {
  if (like != shared_row_) {  // the row the continuation just reported (the first beyond a limit)
    shared_row_ = like;
    shared_full_ = record_of(like).full;
  }
  SweepSummary<double>::share_report(k, like);
  const SolveReport<double> rep = shared_full_ > 0 ? full_[static_cast<std::size_t>(shared_full_ - 1)] : SolveReport<double>{};
  Record r{rep.residual, rep.condition, rep.iterations, rep.evaluations, rep.rank, shared_full_};
  std::memcpy(writable_row(k) + 2 * variables_, &r, sizeof r);
}

SweepFile::Record SweepFile::record_of(std::size_t k) const {
  Record r{};
  const std::size_t at = 2 * static_cast<std::size_t>(variables_) * sizeof(double);
  if (k >= dirty_lo_ && k < dirty_hi_) std::memcpy(&r, buffer_.data() + (k - window_) * row_bytes_ + at, sizeof r);
  else read_bytes(reinterpret_cast<char*>(&r), sizeof r, k * row_bytes_ + at);
  return r;
}

void SweepFile::read_bytes(char* to, std::size_t bytes, std::size_t at) const {
  std::size_t done = 0;
  while (done < bytes) {
    const ssize_t got = ::pread(fd_, to + done, bytes - done, static_cast<off_t>(at + done));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) fail("reading failed", dir_);
    done += static_cast<std::size_t>(got);
  }
}

void SweepFile::flush() {
  const char* from = buffer_.data() + (dirty_lo_ - window_) * row_bytes_;
  std::size_t bytes = (dirty_hi_ - dirty_lo_) * row_bytes_;
  off_t at = static_cast<off_t>(dirty_lo_ * row_bytes_);
  while (bytes > 0) {
    const ssize_t written = ::pwrite(fd_, from, bytes, at);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) fail("writing failed", dir_);
    from += written;
    at += written;
    bytes -= static_cast<std::size_t>(written);
  }
  dirty_lo_ = dirty_hi_;
}

void SweepFile::finish() {
  flush();
  sort_singular();
}

void SweepFile::read(std::size_t first, std::size_t count, SweepResult<double>& block) const {
  count = std::min(count, size() - std::min(first, size()));
  std::vector<char> bytes(count * row_bytes_);
  read_bytes(bytes.data(), bytes.size(), first * row_bytes_);
  block.assembly = assembly;
  block.limits = limits;
  block.inputs_.assign(inputs_->begin() + static_cast<std::ptrdiff_t>(first),
                       inputs_->begin() + static_cast<std::ptrdiff_t>(first + count));
  block.q_.resize(variables_, static_cast<Eigen::Index>(count));
  block.qdot_.resize(variables_, static_cast<Eigen::Index>(count));
  block.records_.resize(count);
  block.full_.clear();
  std::int32_t last_full = 0;
  for (std::size_t j = 0; j < count; ++j) {
    const char* row = bytes.data() + j * row_bytes_;
    const auto col = static_cast<Eigen::Index>(j);
    std::memcpy(block.q_.col(col).data(), row, variables_ * sizeof(double));
    std::memcpy(block.qdot_.col(col).data(), row + variables_ * sizeof(double), variables_ * sizeof(double));
    Record r;
    std::memcpy(&r, row + 2 * variables_ * sizeof(double), sizeof r);
    auto& out = block.records_[j];
    out.status = status[first + j];
    out.residual = r.residual;
    out.condition = r.condition;
    out.iterations = r.iterations;
    out.evaluations = r.evaluations;
    out.rank = r.rank;
    out.full = -1;
    if (r.full > 0) {  // rows sharing a report (not reached beyond a limit) share it in the block too
      if (r.full != last_full) block.full_.push_back(full_[static_cast<std::size_t>(r.full - 1)]);
      last_full = r.full;
      out.full = static_cast<std::int32_t>(block.full_.size() - 1);
    }
  }
}

void sweep_to_file(const Mechanism<double>& m, SolveData<double>& sd, const VectorX<double>& q0,
                   const SolveReport<double>& assembly, int driver, const std::vector<double>& inputs,
                   const ContinuationSettings<double>& cfg, SweepFile& out) {
  sweep_into(m, sd, q0, assembly, driver, inputs, cfg, out);
  out.finish();
}

}  // namespace rollkin::io
