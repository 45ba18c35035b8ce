#include "HistoryWriter.hpp"

#include <set>
#include <stdexcept>

namespace pf {

HistoryWriter::HistoryWriter(const std::string& path, const std::vector<std::string>& columns, bool append)
    : path_(path), columns_(columns) {
  if (columns_.empty()) throw std::runtime_error("HistoryWriter(" + path + "): no columns");
  std::set<std::string> seen;
  for (const auto& c : columns_) {
    if (c.empty() || c.find_first_of(",\"\n\r") != std::string::npos)
      throw std::runtime_error("HistoryWriter(" + path + "): invalid column name '" + c + "'");
    if (!seen.insert(c).second)
      throw std::runtime_error("HistoryWriter(" + path + "): duplicate column name '" + c + "'");
  }
  file_ = std::fopen(path.c_str(), append ? "a" : "w");
  if (!file_) throw std::runtime_error("HistoryWriter: cannot open '" + path + "' for writing");
  if (append) return;
  std::string header;
  for (std::size_t i = 0; i < columns_.size(); ++i) header += (i ? "," : "") + columns_[i];
  header += "\n";
  if (std::fputs(header.c_str(), file_) < 0 || std::fflush(file_) != 0)
    throw std::runtime_error("HistoryWriter: write to '" + path + "' failed");
}

HistoryWriter::~HistoryWriter() {
  if (file_) std::fclose(file_);
}

void HistoryWriter::writeRow(const std::vector<double>& values) {
  if (values.size() != columns_.size())
    throw std::runtime_error("HistoryWriter(" + path_ + "): row has " + std::to_string(values.size()) +
                             " values, header has " + std::to_string(columns_.size()) + " columns");
  bool ok = true;
  for (std::size_t i = 0; i < values.size(); ++i)
    ok = ok && std::fprintf(file_, i ? ",%.17g" : "%.17g", values[i]) > 0;
  ok = ok && std::fputc('\n', file_) != EOF && std::fflush(file_) == 0;
  if (!ok) throw std::runtime_error("HistoryWriter: write to '" + path_ + "' failed");
}

}  // namespace pf
