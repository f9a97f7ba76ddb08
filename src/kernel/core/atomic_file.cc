#include "core/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace sanet {

// The temporary file is opened for each write and closed after it, so that a run with a file per
// node (packets/NODE.csv) holds no descriptor per node: 10,000 nodes would pass any ulimit.
AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), temp_path_(path_ + ".tmp") {
  std::FILE* file = std::fopen(temp_path_.c_str(), "wb");
  if (!file) throw std::runtime_error("cannot write " + temp_path_ + ": " + std::strerror(errno));
  std::fclose(file);
}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temp_path_.c_str());
}

void AtomicFile::Write(std::string_view text) {
  std::FILE* file = std::fopen(temp_path_.c_str(), "ab");
  if (!file) throw std::runtime_error("cannot write " + temp_path_ + ": " + std::strerror(errno));
  const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
  const int error = errno;
  if (std::fclose(file) != 0 || !written)
    throw std::runtime_error("cannot write " + temp_path_ + ": " + std::strerror(written ? errno : error));
}

void AtomicFile::Commit() {
  committed_ = true;
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    const int error = errno;
    std::remove(temp_path_.c_str());
    throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(error));
  }
}

void WriteFileAtomically(const std::string& path, std::string_view content) {
  AtomicFile file(path);
  file.Write(content);
  file.Commit();
}

}  // namespace sanet
