// Shared pre-read checks of input files (input_file.h).
#include "modaltyre/core/input_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "modaltyre/core/errors.h"

namespace modaltyre {

std::string file_size_text(std::uintmax_t bytes) {
  if (bytes < (1u << 20)) return std::to_string(bytes) + " bytes";
  return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MB";
}

void check_input_file(const std::string& path, const std::string& what, const std::string& kinds,
                      std::uintmax_t max_bytes) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (!fs::exists(st)) throw InputError({path, 0, ""}, "file not found");
  if (fs::is_directory(st)) throw InputError({path, 0, ""}, "is a directory, not " + what);
  // A named pipe or device would block the read (or never end): refuse it.
  if (!fs::is_regular_file(st)) {
    throw InputError({path, 0, ""}, "is not a regular file (a pipe or device?)");
  }
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw InputError({path, 0, ""}, "cannot read the file's size: " + ec.message());
  if (size > max_bytes) {
    throw InputError({path, 0, ""}, "is " + file_size_text(size) + "; refusing " + kinds +
                                        " over " + file_size_text(max_bytes) +
                                        " (is it the right file?)");
  }
}

std::string read_input_file(const std::string& path, const std::string& what,
                            const std::string& kinds, std::uintmax_t max_bytes) {
  check_input_file(path, what, kinds, max_bytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, ""}, "cannot open file for reading");
  std::ostringstream buf;
  buf << in.rdbuf();
  std::string text = buf.str();
  // The file may have grown between the check and the read.
  if (text.size() > max_bytes) {
    throw InputError({path, 0, ""}, "grew past " + file_size_text(max_bytes) + " while read");
  }
  return text;
}

}  // namespace modaltyre
