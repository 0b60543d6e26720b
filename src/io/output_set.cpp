#include "rollkin/io/output_set.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rollkin::io {
namespace {

namespace fs = std::filesystem;

std::string reason(int err) { return std::strerror(err); }

std::string named(const std::string& label, const std::string& path) {
  return (label.empty() ? "file" : label) + " '" + path + "'";
}

/// stat(2) following links; false if the file does not exist (or cannot be examined).
bool stat_of(const std::string& path, struct stat& st) { return ::stat(path.c_str(), &st) == 0; }

/// Absolute path with every existing component resolved (realpath of the longest existing prefix).
std::string canonical_name(const std::string& path) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? fs::absolute(path).lexically_normal().string() : p.string();
}

/// True if both names denote one file: same device and inode when both exist (hard links, symlinks,
/// other spellings), else the same resolved path.
bool same_file(const std::string& a, const std::string& b) {
  struct stat sa {}, sb {};
  if (stat_of(a, sa) && stat_of(b, sb)) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  return canonical_name(a) == canonical_name(b);
}

std::string directory_of(const std::string& path) {
  const fs::path dir = fs::path(path).parent_path();
  return dir.empty() ? "." : dir.string();
}

/// The mode a file created by open(path, O_CREAT, 0666) would get: 0666 minus the process's umask.
mode_t new_file_mode() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return static_cast<mode_t>(0666 & ~mask);
}

/// Writes all of `content` to fd; false (errno set) on failure.
bool write_all(int fd, const std::string& content) {
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

/// renameat2(RENAME_EXCHANGE): swaps the two names atomically. False (errno set) if it failed or the file
/// system does not support it.
bool exchange_names(const std::string& a, const std::string& b) {
#ifdef RENAME_EXCHANGE
  return ::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0;
#else
  (void)a;
  (void)b;
  errno = ENOSYS;
  return false;
#endif
}

}  // namespace

OutputSet::OutputSet(std::vector<std::string> inputs) {
  for (auto& path : inputs) inputs_.push_back(InputFile{std::move(path), {}});
}

OutputSet::OutputSet(std::vector<InputFile> inputs) : inputs_(std::move(inputs)) {}

OutputSet::~OutputSet() {
  for (const auto& t : temporaries_) ::unlink(t.c_str());
}

std::string OutputSet::resolve_target(const std::string& path) {
  std::string p = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::error_code ec;
    const fs::path link = fs::read_symlink(p, ec);
    if (ec) return p;
    p = link.is_absolute() ? link.string() : (fs::path(p).parent_path() / link).string();
  }
  throw OutputError("cannot write file '" + path + "': too many levels of symbolic links");
}

std::size_t OutputSet::add(const std::string& label, const std::string& path) {
  if (path.empty()) throw OutputError("cannot write " + named(label, path) + ": empty file name");
  const std::string target = resolve_target(path);
  const std::string shown = named(label, path) + (target == path ? "" : " (a link to '" + target + "')");
  for (const auto& in : inputs_)
    if (same_file(target, in.path))
      throw OutputError("refusing to write " + shown + ": it is " +
                        (in.what.empty() ? "the input file '" + in.path + "' read by this run" : in.what) +
                        "; inputs are never overwritten, choose another name");
  for (const auto& o : outputs_)
    if (same_file(target, o.target))
      throw OutputError(named(label, path) + " and " + named(o.label, o.path) +
                        " name the same file; give each output its own file");
  struct stat st {};
  if (stat_of(target, st)) {
    if (S_ISDIR(st.st_mode)) throw OutputError("cannot write " + shown + ": it is a directory; expected a file name");
    if (!S_ISREG(st.st_mode))
      throw OutputError("cannot write " + shown + ": it exists and is not a regular file (a device, pipe or socket)");
    if (::access(target.c_str(), W_OK) != 0)
      throw OutputError("cannot write " + shown + ": the existing file is not writable (" + reason(errno) + ")");
  }
  const std::string dir = directory_of(target);
  struct stat ds {};
  if (!stat_of(dir, ds)) throw OutputError("cannot write " + shown + ": directory '" + dir + "': " + reason(errno));
  if (!S_ISDIR(ds.st_mode)) throw OutputError("cannot write " + shown + ": '" + dir + "' is not a directory");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw OutputError("cannot write " + shown + ": directory '" + dir + "' is not writable (" + reason(errno) + ")");
  outputs_.push_back(Output{label, path, target, {}, {}, false});
  return outputs_.size() - 1;
}

void OutputSet::set(std::size_t index, std::string content) {
  outputs_.at(index).content = std::move(content);
  outputs_.at(index).has_content = true;
}

void OutputSet::set_writer(std::size_t index, std::function<void(OutputSink&)> write) {
  outputs_.at(index).writer = std::move(write);
  outputs_.at(index).has_content = true;
}

void OutputSet::omit(std::size_t index) { outputs_.at(index).omitted = true; }

void OutputSink::flush() {
  const bool ok = write_all(fd_, buffer_);
  if (!ok) throw OutputError("cannot write " + what_ + ": " + reason(errno));
  buffer_.clear();
}

void OutputSet::commit() {
  outputs_.erase(std::remove_if(outputs_.begin(), outputs_.end(), [](const Output& o) { return o.omitted; }), outputs_.end());
  for (const auto& o : outputs_)
    if (!o.has_content) throw OutputError("internal error: no content for " + named(o.label, o.path));
  // 1. Every temporary written and closed before any target is touched.
  const mode_t fresh = new_file_mode();
  std::vector<std::string> temps;
  for (const auto& o : outputs_) {
    const fs::path t = fs::path(directory_of(o.target)) / ("." + fs::path(o.target).filename().string() + ".XXXXXX");
    std::string name = t.string();
    const int fd = ::mkstemp(name.data());
    if (fd < 0) throw OutputError("cannot write " + named(o.label, o.path) + ": cannot create a temporary file in '" +
                                  directory_of(o.target) + "': " + reason(errno));
    temporaries_.push_back(name);
    temps.push_back(name);
    struct stat st {};
    const mode_t mode = stat_of(o.target, st) ? static_cast<mode_t>(st.st_mode & 07777) : fresh;
    const std::string what = named(o.label, o.path) + ": error while writing '" + name + "'";
    bool ok = ::fchmod(fd, mode) == 0;
    int err = errno;
    if (ok && o.writer) {
      try {  // the writer streams through the sink; the file is closed whatever happens
        OutputSink sink(fd, what);
        o.writer(sink);
        sink.flush();
      } catch (...) {
        ::close(fd);
        throw;
      }
    } else if (ok) {
      ok = write_all(fd, o.content);
      err = errno;
    }
    if (::close(fd) != 0 || !ok) throw OutputError("cannot write " + what + ": " + reason(ok ? errno : err));
  }
  // 2. Renames; a failure puts back what was already replaced.
  enum class How { Exchanged, Created, Replaced };  // Exchanged: the old content sits at the temporary's name
  struct Done {
    std::size_t index;
    How how;
  };
  std::vector<Done> done;
  for (std::size_t i = 0; i < outputs_.size(); ++i) {
    const std::string& target = outputs_[i].target;
    struct stat st {};
    const bool existed = stat_of(target, st);
    // Only a regular file is exchanged (add() checked it; it may have changed since): rename(2) over
    // anything else fails or is refused, and the failure below puts back what was replaced.
    const bool exchanged = existed && S_ISREG(st.st_mode) && exchange_names(temps[i], target);
    if (!exchanged && ::rename(temps[i].c_str(), target.c_str()) != 0) {
      const int err = errno;
      for (auto it = done.rbegin(); it != done.rend(); ++it) {
        const std::string& t = outputs_[it->index].target;
        if (it->how == How::Exchanged) exchange_names(temps[it->index], t);
        if (it->how == How::Created) ::unlink(t.c_str());
      }
      throw OutputError("cannot write " + named(outputs_[i].label, outputs_[i].path) + ": cannot rename '" + temps[i] +
                        "' to it: " + reason(err) + (done.empty() ? "" : "; the outputs already replaced were restored"));
    }
    done.push_back(Done{i, exchanged ? How::Exchanged : existed ? How::Replaced : How::Created});
  }
  // 3. Committed: the temporaries that hold replaced content are removed, the others no longer exist.
  for (const auto& d : done)
    if (d.how == How::Exchanged) ::unlink(temps[d.index].c_str());
  temporaries_.clear();
}

}  // namespace rollkin::io
