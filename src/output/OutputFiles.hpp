#pragma once
// The files of one output name, handled so that a result on disk is never replaced by a partial one
// (rank 0 only). The constructor takes <name>.lock (O_EXCL, holding the PID; a dead owner's lock is
// taken over) or refuses a second run on the name; writers write part(suffix) = <name><suffix>.part;
// commit() renames the parts to their final names and removes <name>.status; abandon(line) keeps the
// parts and writes line to <name>.status. Both release the lock. Errors are std::runtime_error naming where.
#include <string>
#include <vector>

namespace pf {

class OutputFiles {
 public:
  // base: the Output Filename; suffixes: ".csv", ".e"; where: "deck: list/Output Filename" for messages.
  OutputFiles(const std::string& base, const std::vector<std::string>& suffixes, const std::string& where);
  ~OutputFiles();  // releases the lock if neither commit() nor abandon() did
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  std::string part(const std::string& suffix) const { return base_ + suffix + ".part"; }
  void commit();
  void abandon(const std::string& statusLine) noexcept;

 private:
  void takeLock();
  bool lockHeldByLiveProcess(long* pid) const;
  void checkTargets() const;
  void writeStatus(const std::string& line) const;
  void releaseLock() noexcept;

  std::string base_, where_;
  std::vector<std::string> suffixes_;
  bool locked_ = false;
};

}  // namespace pf
