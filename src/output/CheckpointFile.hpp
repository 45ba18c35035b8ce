#pragma once
// The checkpoint file's format: named sections of numbers (doubles) and of bytes (text, copies of output
// files) behind a magic line, the payload's length and its FNV-1a checksum (native byte order). What the
// sections mean is the restart's business (src/app/Checkpoint). writeCheckpoint is atomic: <path>.tmp is
// written, synced and renamed over <path>, so a run killed while writing leaves the previous checkpoint
// whole. readCheckpoint accepts only a complete, unaltered file: std::runtime_error naming the path otherwise.
#include <map>
#include <string>
#include <vector>

namespace pf {

struct CheckpointData {
  std::map<std::string, std::vector<double>> numbers;
  std::map<std::string, std::string> bytes;
  // writeCheckpoint only: section name -> a file whose bytes are copied in as a bytes section (streamed,
  // not held in memory); readCheckpoint returns them in `bytes`.
  std::map<std::string, std::string> fileCopies;

  // The named section; std::runtime_error "lacks section '<name>'" if there is none.
  const std::vector<double>& number(const std::string& name) const;
  const std::string& text(const std::string& name) const;
};

void writeCheckpoint(const std::string& path, const CheckpointData& data);
CheckpointData readCheckpoint(const std::string& path);

}  // namespace pf
