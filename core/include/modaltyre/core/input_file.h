#pragma once
// The checks every reader makes before it reads a byte of an input file (CSV, YAML, .tir, UFF):
// one wording of the refusals, one place to bound a file's size. Each is an InputError naming the
// path (line 0).
#include <cstddef>
#include <cstdint>
#include <optional>
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

/// Length of the well-formed UTF-8 sequence at text[i], 0 if there is none (RFC 3629: no
/// overlong forms, no surrogates, nothing above U+10FFFF).
std::size_t utf8_sequence(const std::string& text, std::size_t i);

/// Whether the whole of `text` is well-formed UTF-8.
bool valid_utf8(const std::string& text);

/// What keeps a text file from being read as UTF-8 text, at a 1-based line.
struct TextProblem {
  int line = 0;
  std::string message;
};

/// The first of: a NUL byte (a binary file), a byte sequence that is not UTF-8 (a Latin-1 or
/// Windows-1252 file), or carriage returns that end lines on their own (old Mac line ends: the
/// readers would see one long line); nullopt when the text is clean. A UTF-8 byte-order mark
/// at the start is not a problem. The YAML, .tir and UFF readers call it before parsing.
std::optional<TextProblem> text_problem(const std::string& text);

}  // namespace modaltyre
