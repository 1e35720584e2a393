#pragma once
// Output files are written whole or not at all: content goes to a temporary file in the same
// folder, which is renamed over the target only when complete.
#include <string>

namespace modaltyre {

/// Writes `content` to `path` atomically; throws InputError if the folder is not writable.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace modaltyre
