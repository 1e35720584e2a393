#pragma once
// Shared helpers of the libFuzzer targets (tests/fuzz/README.md).
//
// Contract of every target: the readers may reject an input only with InputError or
// ComputationError. guarded() swallows exactly those two; any other exception escapes
// LLVMFuzzerTestOneInput, std::terminate aborts, and libFuzzer reports the input as a crash
// (as it does for sanitizer reports, timeouts and out-of-memory).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "modaltyre/core/errors.h"

#ifndef MODALTYRE_FUZZ_SOURCE_DIR
#error "MODALTYRE_FUZZ_SOURCE_DIR must be defined by tests/fuzz/CMakeLists.txt"
#endif

namespace modaltyre::fuzz {

/// The repository root (configs/ and its data are read from there).
inline std::string source_dir() { return MODALTYRE_FUZZ_SOURCE_DIR; }

/// Runs f; InputError and ComputationError are the readers' legitimate answers to bad input.
template <class F>
void guarded(F&& f) {
  try {
    f();
  } catch (const InputError&) {
  } catch (const ComputationError&) {
  }
}

/// The fuzz input as a string (bytes as they are, NULs included).
inline std::string as_text(const uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// A per-process file the path-only readers read the input from; removed at exit.
class ScratchFile {
 public:
  explicit ScratchFile(const std::string& target) {
    const char* tmp = std::getenv("TMPDIR");
    path_ = std::string(tmp && *tmp ? tmp : "/tmp") + "/modaltyre-" + target + "-" +
            std::to_string(static_cast<long>(::getpid())) + ".csv";
  }
  ~ScratchFile() { std::remove(path_.c_str()); }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  /// Replaces the file's content with the input and returns its path.
  const std::string& write(const uint8_t* data, std::size_t size) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) {
      std::fprintf(stderr, "fuzz: cannot write scratch file %s\n", path_.c_str());
      std::abort();  // an environment problem, not a finding: stop loudly
    }
    return path_;
  }

 private:
  std::string path_;
};

/// Lines of the form "#set dotted.key=value" (YAML comments, so the text still parses) become
/// --set overrides; the fuzzer mutates them like the rest of the text.
inline std::vector<std::string> overrides_in(const std::string& text) {
  std::vector<std::string> out;
  std::size_t pos = 0;
  while (pos < text.size() && out.size() < 16) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(pos, end - pos);
    if (line.rfind("#set ", 0) == 0) out.push_back(line.substr(5));
    pos = end + 1;
  }
  return out;
}

}  // namespace modaltyre::fuzz
