#include "CheckpointFile.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <stdexcept>

namespace pf {
namespace {

const std::string kMagic = "PERIFORGE CHECKPOINT 1\n";
constexpr std::uint64_t kFnvOffset = 14695981039346656037ULL, kFnvPrime = 1099511628211ULL;
enum Kind : unsigned char { kNumbers = 1, kBytes = 2 };

std::uint64_t fnv1a(std::uint64_t h, const char* p, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) h = (h ^ static_cast<unsigned char>(p[k])) * kFnvPrime;
  return h;
}

// The payload as it streams out: counts its bytes and hashes them.
class PayloadWriter {
 public:
  PayloadWriter(std::FILE* f, const std::string& path) : f_(f), path_(path) {}
  void put(const void* p, std::size_t n) {
    if (n > 0 && std::fwrite(p, 1, n, f_) != n) throw std::runtime_error("'" + path_ + "': write failed: " + std::strerror(errno));
    hash_ = fnv1a(hash_, static_cast<const char*>(p), n);
    length_ += n;
  }
  void putU64(std::uint64_t v) { put(&v, sizeof v); }
  void section(Kind kind, const std::string& name, std::uint64_t bytes) {
    put(&kind, 1);
    putU64(name.size());
    put(name.data(), name.size());
    putU64(bytes);
  }
  void copyFile(const std::string& name, const std::string& source) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(source.c_str(), "rb"), &std::fclose);
    if (!in) throw std::runtime_error("'" + path_ + "': cannot read '" + source + "': " + std::strerror(errno));
    std::fseek(in.get(), 0, SEEK_END);
    const long size = std::ftell(in.get());
    std::fseek(in.get(), 0, SEEK_SET);
    section(kBytes, name, static_cast<std::uint64_t>(size));
    std::vector<char> buf(1 << 20);
    for (long left = size; left > 0;) {
      const std::size_t n = std::fread(buf.data(), 1, std::min<std::size_t>(buf.size(), static_cast<std::size_t>(left)), in.get());
      if (n == 0) throw std::runtime_error("'" + path_ + "': '" + source + "' ended early");
      put(buf.data(), n);
      left -= static_cast<long>(n);
    }
  }
  std::uint64_t length() const { return length_; }
  std::uint64_t hash() const { return hash_; }

 private:
  std::FILE* f_;
  std::string path_;
  std::uint64_t length_ = 0, hash_ = kFnvOffset;
};

void writePayload(PayloadWriter& out, const CheckpointData& data) {
  out.putU64(data.numbers.size() + data.bytes.size() + data.fileCopies.size());
  for (const auto& [name, values] : data.numbers) {
    out.section(kNumbers, name, values.size() * sizeof(double));
    out.put(values.data(), values.size() * sizeof(double));
  }
  for (const auto& [name, text] : data.bytes) {
    out.section(kBytes, name, text.size());
    out.put(text.data(), text.size());
  }
  for (const auto& [name, source] : data.fileCopies) out.copyFile(name, source);
}

// Reads the payload's pieces with bounds checks: a length past the end is a corrupt file, never a crash.
class PayloadReader {
 public:
  PayloadReader(const std::string& text, std::size_t at, const std::string& path) : text_(text), at_(at), path_(path) {}
  const char* take(std::uint64_t n) {
    if (n > text_.size() - at_) throw std::runtime_error("'" + path_ + "': corrupt checkpoint (a section runs past the end)");
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
  std::size_t at_;
  std::string path_;
};

void syncDirectoryOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  const int fd = ::open(dir.c_str(), O_RDONLY);
  if (fd < 0) return;  // the rename is done; only its durability across a power cut is not assured
  ::fsync(fd);
  ::close(fd);
}

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

void writeCheckpoint(const std::string& path, const CheckpointData& data) {
  const std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw std::runtime_error("cannot write checkpoint '" + tmp + "': " + std::strerror(errno));
  try {
    const std::uint64_t placeholder[2] = {0, 0};
    if (std::fwrite(kMagic.data(), 1, kMagic.size(), f) != kMagic.size() || std::fwrite(placeholder, 8, 2, f) != 2)
      throw std::runtime_error("'" + tmp + "': write failed: " + std::strerror(errno));
    PayloadWriter out(f, tmp);
    writePayload(out, data);
    const std::uint64_t header[2] = {out.length(), out.hash()};
    if (std::fseek(f, static_cast<long>(kMagic.size()), SEEK_SET) != 0 || std::fwrite(header, 8, 2, f) != 2 ||
        std::fflush(f) != 0 || ::fsync(::fileno(f)) != 0)
      throw std::runtime_error("'" + tmp + "': write failed: " + std::strerror(errno));
  } catch (...) {
    std::fclose(f);
    std::remove(tmp.c_str());
    throw;
  }
  if (std::fclose(f) != 0 || std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write checkpoint '" + path + "': " + std::strerror(err));
  }
  syncDirectoryOf(path);
}

CheckpointData readCheckpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("'" + path + "': cannot open checkpoint: " + std::strerror(errno));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.compare(0, kMagic.size(), kMagic) != 0)
    throw std::runtime_error("'" + path + "': not a Periforge checkpoint (or of another version)");
  const std::size_t start = kMagic.size() + 16;
  std::uint64_t header[2] = {0, 0};
  if (text.size() >= start) std::memcpy(header, text.data() + kMagic.size(), 16);
  if (text.size() < start || text.size() - start != header[0])
    throw std::runtime_error("'" + path + "': truncated or padded checkpoint (" + std::to_string(text.size()) +
                             " bytes, its header announces " + std::to_string(start + header[0]) + ")");
  if (fnv1a(kFnvOffset, text.data() + start, text.size() - start) != header[1])
    throw std::runtime_error("'" + path + "': corrupt checkpoint (checksum mismatch)");
  PayloadReader r(text, start, path);
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
    } else {
      throw std::runtime_error("'" + path + "': corrupt checkpoint (section '" + name + "')");
    }
  }
  return data;
}

}  // namespace pf
