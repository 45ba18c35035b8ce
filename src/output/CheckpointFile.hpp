#pragma once
// The checkpoint file's format: named sections of numbers (doubles) and of bytes (text, copies of output
// files) behind a magic line, the payload's length and its FNV-1a checksum (native byte order). What the
// sections mean is the restart's business (src/app/Checkpoint). Neither side holds a whole file: the
// writer streams sections in (a section's numbers may come chunk by chunk), and the reader indexes the
// sections and reads any part of one. Writing is atomic: <path>.tmp is written, synced and renamed over
// <path>, so a run killed while writing leaves the previous checkpoint whole. The reader accepts only a
// complete, unaltered file: std::runtime_error naming the path otherwise.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace pf {

class CheckpointReader;

struct CheckpointData {
  std::map<std::string, std::vector<double>> numbers;
  std::map<std::string, std::string> bytes;
  // Writing only: section name -> a file whose bytes are copied in as a bytes section (streamed, not held
  // in memory); reading returns them in `bytes`.
  std::map<std::string, std::string> fileCopies;
  // Reading: every numbers section's value count, those not read whole included; and, where the file was
  // opened (rank 0 of a restart), the file itself, to read the sections not read whole in parts.
  std::map<std::string, std::uint64_t> counts;
  std::shared_ptr<const CheckpointReader> source;

  // The named section; std::runtime_error "lacks section '<name>'" if there is none.
  const std::vector<double>& number(const std::string& name) const;
  const std::string& text(const std::string& name) const;
};

// Writes <path>.tmp section by section; commit() completes it and renames it over <path>. Destroyed
// without commit (an error on the way), it removes <path>.tmp.
class CheckpointWriter {
 public:
  CheckpointWriter(const std::string& path, std::uint64_t numSections);
  ~CheckpointWriter();
  CheckpointWriter(const CheckpointWriter&) = delete;
  CheckpointWriter& operator=(const CheckpointWriter&) = delete;

  void beginNumbers(const std::string& name, std::uint64_t count);  // count doubles follow through put
  void put(const double* values, std::size_t n);
  void add(const CheckpointData& data);  // each of its sections whole
  // std::runtime_error if the sections or a section's values are fewer or more than announced.
  void commit();

 private:
  void putRaw(const void* p, std::size_t n);
  void section(unsigned char kind, const std::string& name, std::uint64_t bytes);
  void copyFile(const std::string& name, const std::string& source);
  void requireSectionDone() const;
  std::string path_, tmp_;
  std::FILE* file_ = nullptr;
  std::uint64_t sectionsLeft_, length_ = 0, hash_;
  std::uint64_t valuesLeft_ = 0;  // of the numbers section begun last
};

// Opens a checkpoint, checks its magic line, length and checksum (one streamed pass), and indexes its
// sections; then reads them or parts of them without reading the rest.
class CheckpointReader {
 public:
  explicit CheckpointReader(const std::string& path);
  ~CheckpointReader();
  CheckpointReader(const CheckpointReader&) = delete;
  CheckpointReader& operator=(const CheckpointReader&) = delete;

  bool has(const std::string& name) const { return index_.count(name) > 0; }
  // A numbers section's value count; std::runtime_error "lacks section '<name>'" (or not numbers).
  std::uint64_t count(const std::string& name) const;
  // Values [first, first + n) of a numbers section; std::runtime_error past its end.
  void read(const std::string& name, std::uint64_t first, std::uint64_t n, double* out) const;
  // Every section whose name keep accepts, read whole.
  CheckpointData sections(const std::function<bool(const std::string&)>& keep) const;
  // A bytes section streamed into the file `to` (created or truncated).
  void copyTo(const std::string& name, const std::string& to) const;

 private:
  struct Entry {
    unsigned char kind;
    std::uint64_t offset, bytes;
  };
  const Entry& entry(const std::string& name) const;
  void readAt(std::uint64_t offset, void* out, std::uint64_t n) const;
  std::string path_;
  std::FILE* file_ = nullptr;
  std::map<std::string, Entry> index_;
};

void writeCheckpoint(const std::string& path, const CheckpointData& data);
CheckpointData readCheckpoint(const std::string& path);

// numbers, bytes and counts as one string and back (a broadcast of the small sections); decode throws
// std::runtime_error.
std::string encodeSections(const CheckpointData& data);
CheckpointData decodeSections(const std::string& text);

}  // namespace pf
