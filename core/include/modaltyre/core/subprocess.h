#pragma once
// Runs a helper program (e.g. gnuplot) without a shell: the argument vector is passed to
// posix_spawnp as is, so no file name or text ever reaches a shell. The program's input is
// written to its stdin; its stdout and stderr are captured in memory.
#include <string>
#include <vector>

namespace modaltyre {

struct SubprocessResult {
  bool started = false;    ///< false when the program could not be found or started
  bool timed_out = false;  ///< killed after the time limit
  int exit_status = -1;    ///< exit code, or -1 when killed by a signal
  std::string out;         ///< everything the program wrote to stdout
  std::string err;         ///< everything it wrote to stderr (first 64 kB)
};

/// Runs `argv` (argv[0] looked up on PATH) with `input` on stdin. The program is killed after
/// `timeout_s` seconds; stdout beyond `max_out_bytes` is an error (the program is killed).
SubprocessResult run_subprocess(const std::vector<std::string>& argv, const std::string& input,
                                double timeout_s, std::size_t max_out_bytes);

}  // namespace modaltyre
