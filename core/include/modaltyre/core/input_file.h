#pragma once
// The checks every reader makes before it reads a byte of an input file (CSV, YAML, .tir, UFF):
// one wording of the refusals, one place to bound a file's size. Each is an InputError naming the
// path (line 0).
#include <cstdint>
#include <string>

namespace modaltyre {

/// "123 bytes" below 1 MB, else whole MB rounded up ("65 MB").
std::string file_size_text(std::uintmax_t bytes);

/// Refuses a missing path ("file not found"), a directory ("is a directory, not <what>"), a pipe
/// or device (a read would block or never end) and a file over max_bytes ("is 65 MB; refusing
/// <kinds> over 64 MB (is it the right file?)"). `what` is e.g. "a CSV file", `kinds` "CSV files".
void check_input_file(const std::string& path, const std::string& what, const std::string& kinds,
                      std::uintmax_t max_bytes);

/// check_input_file, then the whole file as bytes.
std::string read_input_file(const std::string& path, const std::string& what,
                            const std::string& kinds, std::uintmax_t max_bytes);

}  // namespace modaltyre
