// Files written whole: the content goes to "<path>.tmp" and is renamed over <path> on Commit(),
// so a reader never sees half a file and a crash never leaves a truncated result.
#pragma once

#include <string>
#include <string_view>

namespace sanet {

class AtomicFile {
 public:
  explicit AtomicFile(std::string path);  // throws std::runtime_error if it cannot be created
  ~AtomicFile();                          // without Commit(): removes the temporary file
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void Write(std::string_view text);
  void Commit();  // rename into place; throws on failure
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::string temp_path_;
  bool committed_ = false;
};

// Writes `content` to `path` whole.
void WriteFileAtomically(const std::string& path, std::string_view content);

}  // namespace sanet
