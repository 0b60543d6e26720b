// Temporary files that nothing leaves behind: not an error, not SIGINT or SIGTERM (docs/reliability.md,
// "Outputs, signals and messages (issue 37)").
//
//   io::TemporaryFile t(dir, ".run.csv.");   // an unnamed file in dir (O_TMPFILE): no name to leave behind
//   write(t.fd(), ...);                      // or open t.path() (/proc/self/fd/N) by name, as libdxflib does
//   { io::TerminationDeferred hold;          // SIGINT, SIGTERM, SIGHUP, SIGQUIT wait until the scope ends
//     const std::string name = t.give_name(); rename(name, target); t.release_name(); }
//
// The one rule: a temporary has no name while anything that can take long runs. It is made by open(2) with
// O_TMPFILE in its directory and given a name (linkat(2) through /proc/self/fd/N) only inside a
// TerminationDeferred scope, the few system calls before it is renamed over its target. A file system without
// O_TMPFILE (or a process without /proc) gets a named file from mkstemp(3) instead: its name is registered, and
// the handlers of install_signal_cleanup() remove every registered name before the process ends by the signal
// (async-signal-safe: unlink(2), sigaction(2), raise(3) on a fixed table). The destructor removes the name in
// every other case. SIGKILL cannot be caught: it leaves at most the names of one commit's few system calls.
#pragma once

#include <string>

#include <signal.h>

namespace rollkin::io {

class TemporaryFile {
 public:
  /// An unnamed temporary in `directory`; where that is impossible, the named file `directory`/`stem`XXXXXX.
  /// Throws std::runtime_error naming the directory and the reason when neither can be created.
  TemporaryFile(const std::string& directory, const std::string& stem);
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  int fd() const { return fd_; }
  /// A path that opens this file: /proc/self/fd/N while it is unnamed, its name otherwise.
  std::string path() const;
  /// Closes the descriptor (the file stays, unnamed or under its name). Returns false (errno set) on failure.
  bool close();
  /// Gives the file a fresh name `directory`/`stem`XXXXXX (registered for removal by a signal) and returns it;
  /// a named temporary returns the name it has. Call inside a TerminationDeferred scope. Throws
  /// std::runtime_error on failure.
  std::string give_name();
  /// The name was renamed over its target: it is no longer this temporary's (nothing is removed).
  void release_name();
  /// True while the file has no name (O_TMPFILE).
  bool unnamed() const { return name_.empty(); }

 private:
  std::string directory_, stem_, name_;  // name_: "" while unnamed
  int fd_ = -1;
  int slot_ = -1;  // the registry slot holding name_ (install_signal_cleanup), -1 for none
  bool tmpfile_ = false;  // made by O_TMPFILE (its descriptor must stay open until it is named)
};

/// While alive, SIGINT, SIGTERM, SIGHUP and SIGQUIT wait: blocked in this thread, and held by the handlers of
/// install_signal_cleanup() if another thread receives one; when the last scope ends a held signal is raised
/// again (and ends the process, its temporaries removed). For the few system calls that name temporaries and
/// rename them over their targets, so that a run's outputs are all committed or none.
class TerminationDeferred {
 public:
  TerminationDeferred();
  ~TerminationDeferred();
  TerminationDeferred(const TerminationDeferred&) = delete;
  TerminationDeferred& operator=(const TerminationDeferred&) = delete;

 private:
  sigset_t previous_;
};

/// Installs handlers for SIGINT, SIGTERM, SIGHUP and SIGQUIT (for a program such as build/rollkin, not a
/// library that lives in another's process): each removes every registered temporary name, restores the
/// signal's default action and raises it again, so that the process ends as it would have (status 128 + n
/// in a shell). A signal that arrives inside a TerminationDeferred scope is held until the scope ends.
void install_signal_cleanup();

}  // namespace rollkin::io
