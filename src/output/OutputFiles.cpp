#include "OutputFiles.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace pf {
namespace {

bool isDirectory(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

// Linux: the state letter after the command's closing parenthesis in /proc/<pid>/stat.
bool isZombie(long pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
  const std::size_t close = text.rfind(')');
  return close != std::string::npos && close + 2 < text.size() && text[close + 2] == 'Z';
}

// The lock's PID as written ("<pid>\n"): 0 when the file is empty or holds anything else.
long lockPid(const std::string& lock) {
  std::ifstream in(lock);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  char* end = nullptr;
  const long pid = std::strtol(text.c_str(), &end, 10);
  return end != text.c_str() && std::string(end) == "\n" && pid > 0 ? pid : 0;
}

// Linux: whether /proc/<pid>/comm names this program (periforge, or a build variant periforge-...); true
// when it cannot be read (another OS, a restricted /proc): a lock is then taken as held.
bool runsThisProgram(long pid) {
  std::ifstream comm("/proc/" + std::to_string(pid) + "/comm");
  std::string name;
  if (!std::getline(comm, name)) return true;
  return name.rfind("periforge", 0) == 0;
}

}  // namespace

OutputFiles::OutputFiles(const std::string& base, const std::vector<std::string>& suffixes, const std::string& where)
    : base_(base), where_(where), suffixes_(suffixes) {
  checkTargets();
  takeLock();
  // Until the run ends this says who writes; it survives a kill -9 (with the dead PID in the lock).
  writeStatus("running (pid " + std::to_string(::getpid()) + ")");
}

OutputFiles::~OutputFiles() { releaseLock(); }

// A final name that is a directory could never be replaced: refuse now, not after the whole run.
void OutputFiles::checkTargets() const {
  for (const std::string& s : suffixes_)
    for (const std::string& path : {base_ + s, part(s)})
      if (isDirectory(path)) throw std::runtime_error(where_ + ": '" + path + "' is a directory");
}

// O_EXCL makes the creation atomic: of two runs starting together exactly one gets the lock. A lock whose
// PID is no longer running (a killed run) is taken over, once.
void OutputFiles::takeLock() {
  const std::string lock = base_ + ".lock";
  for (int attempt = 0; attempt < 2; ++attempt) {
    const int fd = ::open(lock.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd >= 0) {
      const std::string pid = std::to_string(::getpid()) + "\n";
      const bool ok = ::write(fd, pid.data(), pid.size()) == static_cast<ssize_t>(pid.size());
      const int err = errno;
      ::close(fd);
      if (!ok) {
        std::remove(lock.c_str());
        throw std::runtime_error(where_ + ": cannot write '" + lock + "': " + std::strerror(err));
      }
      locked_ = true;
      return;
    }
    if (errno != EEXIST)
      throw std::runtime_error(where_ + ": cannot create '" + lock + "': " + std::strerror(errno));
    long pid = 0;
    if (lockHeldByLiveProcess(&pid))
      throw std::runtime_error(where_ + ": '" + base_ + "' is being written by " +
                               (pid == ::getpid() ? std::string("another output list of this run")
                                                  : "another run (pid " + std::to_string(pid) + ")") +
                               "; lock file '" + lock + "'");
    std::remove(lock.c_str());  // stale: its run is gone
  }
  throw std::runtime_error(where_ + ": cannot take the lock file '" + base_ + ".lock'");
}

// A lock is held while its PID runs this program. kill(pid, 0) probes without signalling: 0 or EPERM means
// the process exists, unless it is a zombie (a killed rank nobody has reaped yet, common in containers) or a
// later process that got the PID of a dead run (/proc/<pid>/comm names another program). A lock just created
// by a run starting at the same moment is empty until its owner writes the PID, a few microseconds later:
// it is read again for up to 2 s before an empty or unreadable lock counts as stale (a run killed between
// the two calls, or a file someone else wrote).
bool OutputFiles::lockHeldByLiveProcess(long* pid) const {
  const std::string lock = base_ + ".lock";
  *pid = lockPid(lock);
  for (int wait = 0; *pid == 0 && wait < 40; ++wait) {
    ::usleep(50000);
    *pid = lockPid(lock);
  }
  if (*pid == 0 || (::kill(static_cast<pid_t>(*pid), 0) != 0 && errno != EPERM)) return false;
  return !isZombie(*pid) && runsThisProgram(*pid);
}

void OutputFiles::writeStatus(const std::string& line) const {
  std::ofstream out(base_ + ".status", std::ios::trunc);
  out << line << "\n";
}

void OutputFiles::commit() {
  for (const std::string& s : suffixes_)
    if (std::rename(part(s).c_str(), (base_ + s).c_str()) != 0)
      throw std::runtime_error(where_ + ": cannot rename '" + part(s) + "' to '" + base_ + s +
                               "': " + std::strerror(errno));
  std::remove((base_ + ".status").c_str());
  releaseLock();
}

void OutputFiles::abandon(const std::string& statusLine) noexcept {
  try {
    if (locked_) writeStatus(statusLine);
  } catch (...) {  // a full disk: the lock is still released
  }
  releaseLock();
}

void OutputFiles::releaseLock() noexcept {
  if (locked_) std::remove((base_ + ".lock").c_str());
  locked_ = false;
}

}  // namespace pf
