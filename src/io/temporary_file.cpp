#include "rollkin/io/temporary_file.hpp"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <random>
#include <stdexcept>

#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rollkin::io {
namespace {

// ---- the registry of temporary names a signal must remove (async-signal-safe reads) -------------------------

constexpr int kSlots = 64;
constexpr std::size_t kNameBytes = 4096;
enum SlotState : int { kFree = 0, kFilling = 1, kLive = 2 };
std::atomic<int> g_slot_state[kSlots];
char g_slot_name[kSlots][kNameBytes];

/// Registers `name`; returns its slot, or -1 when the table is full or the name too long (the destructor still
/// removes it; only a signal would leave it).
int register_name(const std::string& name) {
  if (name.size() >= kNameBytes) return -1;
  for (int s = 0; s < kSlots; ++s) {
    int expected = kFree;
    if (!g_slot_state[s].compare_exchange_strong(expected, kFilling)) continue;
    std::memcpy(g_slot_name[s], name.c_str(), name.size() + 1);
    g_slot_state[s].store(kLive);
    return s;
  }
  return -1;
}

void unregister(int slot) {
  if (slot >= 0) g_slot_state[slot].store(kFree);
}

/// In a signal handler: unlink(2) every registered name.
void remove_registered_names() {
  for (int s = 0; s < kSlots; ++s)
    if (g_slot_state[s].load() == kLive) ::unlink(g_slot_name[s]);
}

// ---- termination signals ---------------------------------------------------------------------------------

constexpr int kTerminationSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
std::atomic<int> g_deferring{0};           // TerminationDeferred scopes alive, in any thread
volatile sig_atomic_t g_held_signal = 0;   // a signal that arrived inside one
static_assert(std::atomic<int>::is_always_lock_free, "the handler reads atomics: they must be lock-free");

void end_by(int sig) {
  remove_registered_names();
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  sigset_t unblock;
  sigemptyset(&unblock);
  sigaddset(&unblock, sig);
  ::pthread_sigmask(SIG_UNBLOCK, &unblock, nullptr);
  ::raise(sig);
}

extern "C" void on_termination_signal(int sig) {
  const int saved = errno;
  if (g_deferring.load() > 0) {
    g_held_signal = sig;  // raised again when the last TerminationDeferred ends
    errno = saved;
    return;
  }
  end_by(sig);
  errno = saved;
}

sigset_t termination_set() {
  sigset_t set;
  sigemptyset(&set);
  for (const int s : kTerminationSignals) sigaddset(&set, s);
  return set;
}

std::string proc_fd_path(int fd) { return "/proc/self/fd/" + std::to_string(fd); }

/// `directory`/`stem` followed by six random letters and digits.
std::string fresh_name(const std::string& directory, const std::string& stem) {
  static thread_local std::mt19937_64 random{std::random_device{}() ^ static_cast<unsigned long>(::getpid())};
  static const char kLetters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  std::string name = (directory.empty() ? "." : directory) + "/" + stem;
  for (int i = 0; i < 6; ++i) name += kLetters[random() % (sizeof kLetters - 1)];
  return name;
}

}  // namespace

TemporaryFile::TemporaryFile(const std::string& directory, const std::string& stem)
    : directory_(directory.empty() ? "." : directory), stem_(stem) {
#ifdef O_TMPFILE
  fd_ = ::open(directory_.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  // Named later through /proc/self/fd/N (linkat AT_SYMLINK_FOLLOW, as open(2) describes): without /proc the
  // file could never be named, so it is not used.
  if (fd_ >= 0 && ::access(proc_fd_path(fd_).c_str(), F_OK) != 0) {
    ::close(fd_);
    fd_ = -1;
  }
  tmpfile_ = fd_ >= 0;
#endif
  if (fd_ >= 0) return;
  // No O_TMPFILE here: a named file, registered as it is made (no signal in between).
  std::string name = directory_ + "/" + stem_ + "XXXXXX";
  int slot = -1;
  {
    TerminationDeferred hold;
    fd_ = ::mkstemp(name.data());
    if (fd_ >= 0) slot = register_name(name);
  }
  if (fd_ < 0)
    throw std::runtime_error("cannot create a temporary file in '" + directory_ + "': " + std::strerror(errno));
  ::fcntl(fd_, F_SETFD, FD_CLOEXEC);
  name_ = name;
  slot_ = slot;
}

TemporaryFile::~TemporaryFile() {
  if (fd_ >= 0) ::close(fd_);
  if (name_.empty()) return;
  TerminationDeferred hold;  // the name leaves the registry as it leaves the directory
  ::unlink(name_.c_str());
  unregister(slot_);
}

std::string TemporaryFile::path() const { return name_.empty() ? proc_fd_path(fd_) : name_; }

bool TemporaryFile::close() {
  if (fd_ < 0 || tmpfile_) return true;  // an unnamed file keeps its descriptor until it is named
  const int fd = fd_;
  fd_ = -1;
  return ::close(fd) == 0;
}

std::string TemporaryFile::give_name() {
  if (!name_.empty()) return name_;
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string name = fresh_name(directory_, stem_);
    if (::linkat(AT_FDCWD, proc_fd_path(fd_).c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) == 0) {
      name_ = name;
      slot_ = register_name(name);  // after the link: a name that was taken is never registered
      ::close(fd_);
      fd_ = -1;
      tmpfile_ = false;
      return name_;
    }
    const int err = errno;
    if (err != EEXIST)
      throw std::runtime_error("cannot name the temporary file in '" + directory_ + "': " + std::strerror(err));
  }
  throw std::runtime_error("cannot name the temporary file in '" + directory_ + "': 100 names taken");
}

void TemporaryFile::release_name() {
  unregister(slot_);
  slot_ = -1;
  name_.clear();
}

TerminationDeferred::TerminationDeferred() {
  g_deferring.fetch_add(1);
  const sigset_t set = termination_set();
  ::pthread_sigmask(SIG_BLOCK, &set, &previous_);
}

TerminationDeferred::~TerminationDeferred() {
  if (g_deferring.fetch_sub(1) == 1 && g_held_signal != 0) {
    const int sig = g_held_signal;
    g_held_signal = 0;
    end_by(sig);
  }
  ::pthread_sigmask(SIG_SETMASK, &previous_, nullptr);  // a signal blocked meanwhile is delivered now
}

void install_signal_cleanup() {
  struct sigaction sa {};
  sa.sa_handler = on_termination_signal;
  sigemptyset(&sa.sa_mask);
  for (const int s : kTerminationSignals) sigaddset(&sa.sa_mask, s);
  for (const int s : kTerminationSignals) ::sigaction(s, &sa, nullptr);
}

}  // namespace rollkin::io
