// A run's results folder as one message between MPI ranks: a header (JSON) and the files' bytes,
// so that a rank with no shared file system can send back what it ran.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace sanet::study {

// `header` plus every file under `folder` (recursively), with an index of paths and sizes, and
// then `trailer`: bytes that travel with the folder but are not in it (the run's output).
std::string PackFolder(const nlohmann::json& header, const std::filesystem::path& folder, const std::string& trailer);

struct UnpackedMessage {
  nlohmann::json header;
  nlohmann::json index;  // [{path, size}]
  std::string files;     // their bytes, one after another
  std::string trailer;
};
UnpackedMessage ReadFolderMessage(const std::string& message);

// Writes the files as `folder`, whole: beside it first (folder.incoming), then in its place.
void WriteFolder(const UnpackedMessage& message, const std::filesystem::path& folder);

// A file's bytes ("" for a file that is not there).
std::string ReadWholeFile(const std::filesystem::path& path);

// Where WriteFolder puts a folder until it is complete.
std::filesystem::path IncomingFolder(const std::filesystem::path& folder);

}  // namespace sanet::study
