#include "study/folder_message.h"

#include <cstdint>
#include <fstream>
#include <stdexcept>

#include "core/json_text.h"

namespace sanet::study {
namespace {

namespace fs = std::filesystem;

// The header's length leads, as 8 decimal digits, so that the files need no escaping.
constexpr std::size_t kLengthDigits = 8;

}  // namespace

std::string PackFolder(const nlohmann::json& header, const fs::path& folder, const std::string& trailer) {
  nlohmann::json index = nlohmann::json::array();
  std::string files;
  if (fs::exists(folder))
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
      if (!entry.is_regular_file()) continue;
      const std::string content = ReadWholeFile(entry.path());
      index.push_back({{"path", fs::relative(entry.path(), folder).string()}, {"size", content.size()}});
      files += content;
    }
  const std::string head = JsonText(nlohmann::json{{"header", header}, {"index", index}, {"files_size", files.size()}});
  std::string length = std::to_string(head.size());
  length.insert(0, kLengthDigits - length.size(), '0');
  return length + head + files + trailer;
}

UnpackedMessage ReadFolderMessage(const std::string& message) {
  const std::size_t length = std::stoull(message.substr(0, kLengthDigits));
  const nlohmann::json head = nlohmann::json::parse(message.substr(kLengthDigits, length));
  const std::size_t files_size = head["files_size"].get<std::size_t>();
  if (kLengthDigits + length + files_size > message.size())
    throw std::runtime_error("a results message is shorter than its index");
  return {head["header"], head["index"], message.substr(kLengthDigits + length, files_size),
          message.substr(kLengthDigits + length + files_size)};
}

std::string ReadWholeFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

fs::path IncomingFolder(const fs::path& folder) { return folder.string() + ".incoming"; }

void WriteFolder(const UnpackedMessage& message, const fs::path& folder) {
  const fs::path incoming = IncomingFolder(folder);
  fs::remove_all(incoming);
  fs::create_directories(incoming);
  std::size_t at = 0;
  for (const auto& f : message.index) {
    const fs::path p = incoming / f["path"].get<std::string>();
    const std::size_t size = f["size"].get<std::size_t>();
    if (at + size > message.files.size()) throw std::runtime_error("a results message is shorter than its index");
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary).write(message.files.data() + at, static_cast<std::streamsize>(size));
    at += size;
  }
  fs::remove_all(folder);
  fs::rename(incoming, folder);
}

}  // namespace sanet::study
