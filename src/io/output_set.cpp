#include "rollkin/io/output_set.hpp"

#include "rollkin/io/input_error.hpp"
#include "rollkin/io/input_file.hpp"
#include "rollkin/io/temporary_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <new>
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

OutputSet::~OutputSet() = default;

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

void OutputSet::commit(const std::function<void()>& check) {
  outputs_.erase(std::remove_if(outputs_.begin(), outputs_.end(), [](const Output& o) { return o.omitted; }), outputs_.end());
  for (const auto& o : outputs_)
    if (!o.has_content) throw OutputError("internal error: no content for " + named(o.label, o.path));
  // 1. Every temporary written (unnamed, in its target's directory) before any target is touched.
  const mode_t fresh = new_file_mode();
  temporaries_.clear();
  for (const auto& o : outputs_) {
    const std::string dir = directory_of(o.target);
    try {
      temporaries_.push_back(std::make_unique<TemporaryFile>(dir, "." + fs::path(o.target).filename().string() + "."));
    } catch (const std::runtime_error& e) {
      throw OutputError("cannot write " + named(o.label, o.path) + ": " + e.what());
    }
    const int fd = temporaries_.back()->fd();
    struct stat st {};
    const mode_t mode = stat_of(o.target, st) ? static_cast<mode_t>(st.st_mode & 07777) : fresh;
    const std::string what = named(o.label, o.path) + ": error while writing its temporary file in '" + dir + "'";
    bool ok = ::fchmod(fd, mode) == 0;
    int err = errno;
    if (ok && o.writer) {  // the writer streams through the sink; a throw leaves the temporaries to their destructors
      OutputSink sink(fd, what);
      o.writer(sink);
      sink.flush();
    } else if (ok) {
      ok = write_all(fd, o.content);
      err = errno;
    }
    if (!ok) throw OutputError("cannot write " + what + ": " + reason(err));
  }
  // 2. Whatever else can fail runs now, reading the outputs from their temporaries.
  if (check) run_check(check);
  // 3. Named and renamed with the termination signals held: committed all, or (rolled back) none.
  TerminationDeferred hold;
  std::vector<std::string> temps;
  for (std::size_t i = 0; i < outputs_.size(); ++i) {
    TemporaryFile& t = *temporaries_[i];
    try {
      temps.push_back(t.give_name());
    } catch (const std::runtime_error& e) {
      throw OutputError("cannot write " + named(outputs_[i].label, outputs_[i].path) + ": " + e.what());
    }
    if (!t.close()) throw OutputError("cannot write " + named(outputs_[i].label, outputs_[i].path) + ": " + reason(errno));
  }
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
    if (!exchanged) temporaries_[i]->release_name();  // the name is the target's now
    done.push_back(Done{i, exchanged ? How::Exchanged : existed ? How::Replaced : How::Created});
  }
  // 4. Committed: the temporaries that hold replaced content are removed (their destructors unlink them).
  temporaries_.clear();
}

void OutputSet::run_check(const std::function<void()>& check) {
  std::vector<std::pair<std::string, std::string>> staged;
  for (std::size_t i = 0; i < outputs_.size(); ++i) staged.emplace_back(outputs_[i].target, temporaries_[i]->path());
  const StagedOutputs view(staged);
  const std::string defect = "; nothing was written. This is a defect of rollkin: please report it with the input that produced it";
  try {
    check();
  } catch (const InputError& e) {
    throw InternalError(std::string("a file this run wrote is refused by rollkin's own reader: ") + e.what() + defect);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const OutputError&) {
    throw;
  } catch (const InternalError&) {
    throw;
  } catch (const std::exception& e) {
    throw InternalError(std::string("reading back the files this run wrote failed: ") + e.what() + defect);
  }
}

}  // namespace rollkin::io
