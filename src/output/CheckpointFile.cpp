#include "CheckpointFile.hpp"

#include <fcntl.h>
#include <sys/types.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace pf {
namespace {

const std::string kMagic = "PERIFORGE CHECKPOINT 1\n";
constexpr std::uint64_t kFnvOffset = 14695981039346656037ULL, kFnvPrime = 1099511628211ULL;
constexpr std::size_t kHeader = 16;         // payload length and checksum, after the magic line
constexpr std::size_t kBlock = 1 << 20;     // streamed copies and the checksum pass read 1 MB at a time
enum Kind : unsigned char { kNumbers = 1, kBytes = 2, kCount = 3 };  // kCount: encodeSections only

std::uint64_t fnv1a(std::uint64_t h, const char* p, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) h = (h ^ static_cast<unsigned char>(p[k])) * kFnvPrime;
  return h;
}

std::string errnoText() { return std::strerror(errno); }

void syncDirectoryOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  const int fd = ::open(dir.c_str(), O_RDONLY);
  if (fd < 0) return;  // the rename is done; only its durability across a power cut is not assured
  ::fsync(fd);
  ::close(fd);
}

// One section record (kind, name, size, data) appended to a string: the payload's layout in memory.
void appendRecord(std::string& out, unsigned char kind, const std::string& name, const void* data, std::uint64_t n) {
  const std::uint64_t nameLength = name.size();
  out.push_back(static_cast<char>(kind));
  out.append(reinterpret_cast<const char*>(&nameLength), sizeof nameLength);
  out += name;
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
  out.append(static_cast<const char*>(data), n);
}

// Reads a payload held in memory with bounds checks: a length past the end is a corrupt file, never a crash.
class PayloadReader {
 public:
  explicit PayloadReader(const std::string& text) : text_(text) {}
  const char* take(std::uint64_t n) {
    if (n > text_.size() - at_) throw std::runtime_error("corrupt sections (one runs past the end)");
    const char* p = text_.data() + at_;
    at_ += n;
    return p;
  }
  std::uint64_t u64() {
    std::uint64_t v;
    std::memcpy(&v, take(sizeof v), sizeof v);
    return v;
  }

 private:
  const std::string& text_;
  std::size_t at_ = 0;
};

}  // namespace

const std::vector<double>& CheckpointData::number(const std::string& name) const {
  auto it = numbers.find(name);
  if (it == numbers.end()) throw std::runtime_error("lacks section '" + name + "'");
  return it->second;
}

const std::string& CheckpointData::text(const std::string& name) const {
  auto it = bytes.find(name);
  if (it == bytes.end()) throw std::runtime_error("lacks section '" + name + "'");
  return it->second;
}

// ---- writing ----

CheckpointWriter::CheckpointWriter(const std::string& path, std::uint64_t numSections)
    : path_(path), tmp_(path + ".tmp"), sectionsLeft_(numSections), hash_(kFnvOffset) {
  file_ = std::fopen(tmp_.c_str(), "wb");
  if (!file_) throw std::runtime_error("cannot write checkpoint '" + tmp_ + "': " + errnoText());
  const char placeholder[kHeader] = {};
  if (std::fwrite(kMagic.data(), 1, kMagic.size(), file_) != kMagic.size() ||
      std::fwrite(placeholder, 1, kHeader, file_) != kHeader)
    throw std::runtime_error("'" + tmp_ + "': write failed: " + errnoText());
  putRaw(&numSections, sizeof numSections);
}

CheckpointWriter::~CheckpointWriter() {
  if (!file_) return;
  std::fclose(file_);
  std::remove(tmp_.c_str());
}

void CheckpointWriter::putRaw(const void* p, std::size_t n) {
  if (n > 0 && std::fwrite(p, 1, n, file_) != n) throw std::runtime_error("'" + tmp_ + "': write failed: " + errnoText());
  hash_ = fnv1a(hash_, static_cast<const char*>(p), n);
  length_ += n;
}

void CheckpointWriter::requireSectionDone() const {
  if (valuesLeft_ != 0)
    throw std::logic_error("checkpoint '" + tmp_ + "': a section lacks " + std::to_string(valuesLeft_) + " values");
}

void CheckpointWriter::section(unsigned char kind, const std::string& name, std::uint64_t bytes) {
  requireSectionDone();
  if (sectionsLeft_ == 0) throw std::logic_error("checkpoint '" + tmp_ + "': more sections than announced");
  --sectionsLeft_;
  const std::uint64_t nameLength = name.size();
  putRaw(&kind, 1);
  putRaw(&nameLength, sizeof nameLength);
  putRaw(name.data(), name.size());
  putRaw(&bytes, sizeof bytes);
}

void CheckpointWriter::beginNumbers(const std::string& name, std::uint64_t count) {
  section(kNumbers, name, count * sizeof(double));
  valuesLeft_ = count;
}

void CheckpointWriter::put(const double* values, std::size_t n) {
  if (n > valuesLeft_) throw std::logic_error("checkpoint '" + tmp_ + "': more values than the section announced");
  putRaw(values, n * sizeof(double));
  valuesLeft_ -= n;
}

void CheckpointWriter::copyFile(const std::string& name, const std::string& source) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(source.c_str(), "rb"), &std::fclose);
  if (!in) throw std::runtime_error("'" + tmp_ + "': cannot read '" + source + "': " + errnoText());
  std::fseek(in.get(), 0, SEEK_END);
  const long size = std::ftell(in.get());
  std::fseek(in.get(), 0, SEEK_SET);
  section(kBytes, name, static_cast<std::uint64_t>(size));
  std::vector<char> buf(kBlock);
  for (long left = size; left > 0;) {
    const std::size_t n = std::fread(buf.data(), 1, std::min<std::size_t>(buf.size(), static_cast<std::size_t>(left)), in.get());
    if (n == 0) throw std::runtime_error("'" + tmp_ + "': '" + source + "' ended early");
    putRaw(buf.data(), n);
    left -= static_cast<long>(n);
  }
}

void CheckpointWriter::add(const CheckpointData& data) {
  for (const auto& [name, values] : data.numbers) {
    beginNumbers(name, values.size());
    put(values.data(), values.size());
  }
  for (const auto& [name, text] : data.bytes) {
    section(kBytes, name, text.size());
    putRaw(text.data(), text.size());
  }
  for (const auto& [name, source] : data.fileCopies) copyFile(name, source);
}

void CheckpointWriter::commit() {
  requireSectionDone();
  if (sectionsLeft_ != 0) throw std::logic_error("checkpoint '" + tmp_ + "': fewer sections than announced");
  const std::uint64_t header[2] = {length_, hash_};
  if (std::fseek(file_, static_cast<long>(kMagic.size()), SEEK_SET) != 0 || std::fwrite(header, 8, 2, file_) != 2 ||
      std::fflush(file_) != 0 || ::fsync(::fileno(file_)) != 0)
    throw std::runtime_error("'" + tmp_ + "': write failed: " + errnoText());
  const int closed = std::fclose(file_);
  file_ = nullptr;
  if (closed != 0 || std::rename(tmp_.c_str(), path_.c_str()) != 0) {
    const int err = errno;
    std::remove(tmp_.c_str());
    throw std::runtime_error("cannot write checkpoint '" + path_ + "': " + std::strerror(err));
  }
  syncDirectoryOf(path_);
}

// ---- reading ----

CheckpointReader::CheckpointReader(const std::string& path) : path_(path) {
  file_ = std::fopen(path.c_str(), "rb");
  if (!file_) throw std::runtime_error("'" + path + "': cannot open checkpoint: " + errnoText());
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> closer(file_, &std::fclose);  // until the checks pass
  std::string magic(kMagic.size(), '\0');
  if (std::fread(&magic[0], 1, magic.size(), file_) != magic.size() || magic != kMagic)
    throw std::runtime_error("'" + path + "': not a Periforge checkpoint (or of another version)");
  ::fseeko(file_, 0, SEEK_END);
  const std::uint64_t size = static_cast<std::uint64_t>(::ftello(file_)), start = kMagic.size() + kHeader;
  std::uint64_t header[2] = {0, 0};
  if (size >= start) readAt(kMagic.size(), header, kHeader);
  if (size < start || size - start != header[0])
    throw std::runtime_error("'" + path + "': truncated or padded checkpoint (" + std::to_string(size) +
                             " bytes, its header announces " + std::to_string(start + header[0]) + ")");
  std::vector<char> buf(kBlock);
  std::uint64_t hash = kFnvOffset;
  for (std::uint64_t at = start; at < size; at += buf.size()) {
    const std::uint64_t n = std::min<std::uint64_t>(buf.size(), size - at);
    readAt(at, buf.data(), n);
    hash = fnv1a(hash, buf.data(), n);
  }
  if (hash != header[1]) throw std::runtime_error("'" + path + "': corrupt checkpoint (checksum mismatch)");
  // The checksum holds, so the records are as written; the bounds checks guard against a forged file.
  const std::string pastEnd = "'" + path + "': corrupt checkpoint (a section runs past the end)";
  std::uint64_t at = start, n = 0;
  auto need = [&](std::uint64_t bytes) {
    if (bytes > size - at) throw std::runtime_error(pastEnd);
  };
  need(8);
  readAt(at, &n, 8);
  at += 8;
  for (std::uint64_t s = 0; s < n; ++s) {
    unsigned char kind = 0;
    std::uint64_t nameLength = 0, bytes = 0;
    need(9);
    readAt(at, &kind, 1);
    readAt(at + 1, &nameLength, 8);
    at += 9;
    need(nameLength);
    std::string name(nameLength, '\0');
    readAt(at, &name[0], nameLength);
    at += nameLength;
    need(8);
    readAt(at, &bytes, 8);
    at += 8;
    need(bytes);
    if (!(kind == kBytes || (kind == kNumbers && bytes % sizeof(double) == 0)))
      throw std::runtime_error("'" + path + "': corrupt checkpoint (section '" + name + "')");
    index_[name] = Entry{kind, at, bytes};
    at += bytes;
  }
  closer.release();
}

CheckpointReader::~CheckpointReader() {
  if (file_) std::fclose(file_);
}

void CheckpointReader::readAt(std::uint64_t offset, void* out, std::uint64_t n) const {
  if (::fseeko(file_, static_cast<off_t>(offset), SEEK_SET) != 0 || std::fread(out, 1, n, file_) != n)
    throw std::runtime_error("'" + path_ + "': read failed: " + errnoText());
}

const CheckpointReader::Entry& CheckpointReader::entry(const std::string& name) const {
  auto it = index_.find(name);
  if (it == index_.end()) throw std::runtime_error("lacks section '" + name + "'");
  return it->second;
}

std::uint64_t CheckpointReader::count(const std::string& name) const {
  const Entry& e = entry(name);
  if (e.kind != kNumbers) throw std::runtime_error("section '" + name + "' is not numbers");
  return e.bytes / sizeof(double);
}

void CheckpointReader::read(const std::string& name, std::uint64_t first, std::uint64_t n, double* out) const {
  const std::uint64_t have = count(name);
  if (first > have || n > have - first)
    throw std::runtime_error("section '" + name + "' has " + std::to_string(have) + " values, not " +
                             std::to_string(first + n));
  readAt(entry(name).offset + first * sizeof(double), out, n * sizeof(double));
}

CheckpointData CheckpointReader::sections(const std::function<bool(const std::string&)>& keep) const {
  CheckpointData data;
  for (const auto& [name, e] : index_) {
    if (e.kind == kNumbers) data.counts[name] = e.bytes / sizeof(double);
    if (!keep(name)) continue;
    if (e.kind == kNumbers) {
      std::vector<double>& v = data.numbers[name];
      v.resize(e.bytes / sizeof(double));
      readAt(e.offset, v.data(), e.bytes);
    } else {
      std::string& t = data.bytes[name];
      t.resize(e.bytes);
      if (e.bytes > 0) readAt(e.offset, &t[0], e.bytes);
    }
  }
  return data;
}

void CheckpointReader::copyTo(const std::string& name, const std::string& to) const {
  const Entry& e = entry(name);
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> out(std::fopen(to.c_str(), "wb"), &std::fclose);
  if (!out) throw std::runtime_error("cannot write '" + to + "': " + errnoText());
  std::vector<char> buf(kBlock);
  for (std::uint64_t at = 0; at < e.bytes; at += buf.size()) {
    const std::uint64_t n = std::min<std::uint64_t>(buf.size(), e.bytes - at);
    readAt(e.offset + at, buf.data(), n);
    if (std::fwrite(buf.data(), 1, n, out.get()) != n) throw std::runtime_error("cannot write '" + to + "': " + errnoText());
  }
  if (std::fflush(out.get()) != 0) throw std::runtime_error("cannot write '" + to + "': " + errnoText());
}

void writeCheckpoint(const std::string& path, const CheckpointData& data) {
  CheckpointWriter out(path, data.numbers.size() + data.bytes.size() + data.fileCopies.size());
  out.add(data);
  out.commit();
}

CheckpointData readCheckpoint(const std::string& path) {
  return CheckpointReader(path).sections([](const std::string&) { return true; });
}

std::string encodeSections(const CheckpointData& data) {
  std::string out;
  const std::uint64_t n = data.numbers.size() + data.bytes.size() + data.counts.size();
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
  for (const auto& [name, count] : data.counts) appendRecord(out, kCount, name, &count, sizeof count);
  for (const auto& [name, values] : data.numbers) appendRecord(out, kNumbers, name, values.data(), values.size() * sizeof(double));
  for (const auto& [name, text] : data.bytes) appendRecord(out, kBytes, name, text.data(), text.size());
  return out;
}

CheckpointData decodeSections(const std::string& text) {
  PayloadReader r(text);
  CheckpointData data;
  for (std::uint64_t s = 0, n = r.u64(); s < n; ++s) {
    const unsigned char kind = static_cast<unsigned char>(*r.take(1));
    const std::uint64_t nameLength = r.u64();
    const std::string name(r.take(nameLength), nameLength);
    const std::uint64_t size = r.u64();
    const char* p = r.take(size);
    if (kind == kNumbers && size % sizeof(double) == 0) {
      std::vector<double>& v = data.numbers[name];
      v.resize(size / sizeof(double));
      std::memcpy(v.data(), p, size);
    } else if (kind == kBytes) {
      data.bytes[name].assign(p, size);
    } else if (kind == kCount && size == sizeof(std::uint64_t)) {
      std::memcpy(&data.counts[name], p, size);
    } else {
      throw std::runtime_error("corrupt sections ('" + name + "')");
    }
  }
  return data;
}

}  // namespace pf
