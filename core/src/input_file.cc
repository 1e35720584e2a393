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

std::size_t utf8_sequence(const std::string& s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  if (c < 0x80) return 1;
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // allowed range of the second byte
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    if (c == 0xE0) lo = 0xA0;
    if (c == 0xED) hi = 0x9F;
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    if (c == 0xF0) lo = 0x90;
    if (c == 0xF4) hi = 0x8F;
  } else {
    return 0;
  }
  if (i + n > s.size() || b(i + 1) < lo || b(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k) {
    if (b(i + k) < 0x80 || b(i + k) > 0xBF) return 0;
  }
  return n;
}

bool valid_utf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t n = utf8_sequence(s, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

std::optional<TextProblem> text_problem(const std::string& text) {
  static const char* digits = "0123456789ABCDEF";
  int line = 1;
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      ++line;
      ++i;
      continue;
    }
    if (c == 0) return TextProblem{line, "contains a NUL byte: a binary file, not text"};
    if (c == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) {
      return TextProblem{line,
                         "a carriage return ends a line on its own (old Mac line ends?): save "
                         "the file with LF or CRLF line ends"};
    }
    const std::size_t n = utf8_sequence(text, i);
    if (n == 0) {
      return TextProblem{line, std::string("byte \\x") + digits[c >> 4] + digits[c & 0xF] +
                                   " is not UTF-8 (a Latin-1 or Windows-1252 file?): save the "
                                   "file as UTF-8"};
    }
    i += n;
  }
  return std::nullopt;
}

}  // namespace modaltyre
