#pragma once
// Error types shared by every module.
//
// InputError: what the user gave us is wrong (file, line, key). The CLI maps it to exit code 2.
// ComputationError: the input was valid but a computation failed (no convergence, singular
// system); the CLI maps it to exit code 1. Expected numerical outcomes (e.g. a solve that did not
// converge) are returned as result summaries by the library; the CLI turns them into this error.
#include <stdexcept>
#include <string>

namespace modaltyre {

/// Where in an input a problem was found. line == 0 means "not tied to a line"
/// (e.g. a --set override or a whole-file problem).
struct InputLocation {
  std::string file;  ///< path as the user gave it, or "--set" for command-line overrides
  int line = 0;      ///< 1-based line, 0 if unknown
  std::string key;   ///< dotted config key or CSV column, may be empty
};

class InputError : public std::runtime_error {
 public:
  InputError(InputLocation where, const std::string& message);
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
  const InputLocation& where() const { return where_; }

 private:
  InputLocation where_;
};

class ComputationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Formats "file:line: key: message" leaving out the parts that are empty.
std::string format_location(const InputLocation& where, const std::string& message);

}  // namespace modaltyre

/// Always-on internal invariant check (a failure is a bug in ModalTyre, not a user error).
#define MODALTYRE_CHECK(cond, msg)                                                        \
  do {                                                                                    \
    if (!(cond))                                                                          \
      throw ::modaltyre::ComputationError(std::string("internal error at ") + __FILE__ + \
                                          ":" + std::to_string(__LINE__) + ": " + (msg)); \
  } while (0)
