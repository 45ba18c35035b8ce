#pragma once
// CSV time-history output (one row per output step). Rows are flushed as they are written so
// a run that is killed or diverges still leaves a valid, plottable prefix.

#include <cstdio>
#include <string>
#include <vector>

namespace pf {

class HistoryWriter {
 public:
  // Truncates/creates path and writes the header "col1,col2,...".
  // Throws std::runtime_error naming the file if it cannot be opened, or if a column name is
  // empty, duplicated, or contains a comma/quote/newline (the file is plain, unquoted CSV).
  // append: continue a file that already holds this header and some rows (a restart); nothing is written
  // on opening.
  HistoryWriter(const std::string& path, const std::vector<std::string>& columns, bool append = false);
  ~HistoryWriter();

  HistoryWriter(const HistoryWriter&) = delete;
  HistoryWriter& operator=(const HistoryWriter&) = delete;

  // values.size() must equal the number of columns. Written with %.17g (round-trips doubles).
  void writeRow(const std::vector<double>& values);

  const std::vector<std::string>& columns() const { return columns_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::vector<std::string> columns_;
  std::FILE* file_ = nullptr;
};

}  // namespace pf
