#pragma once
// Strict YAML configuration reading.
//
// A missing key keeps its default; an unknown key, a wrong type or an out-of-range value is an
// InputError naming the file, the line and the dotted key (e.g. "tread.modulus_MPa").
// Command-line overrides "--set dotted.key=value" are applied to the tree before it is read and
// are reported as coming from "--set".
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "modaltyre/core/errors.h"

namespace modaltyre {

class ConfigSection;

/// Parses YAML text; a syntax error, a duplicate key or an alias is an InputError naming
/// `name` and the line (see yaml_guard.h).
YAML::Node parse_yaml(const std::string& text, const std::string& name);

/// Reads a YAML file whole: refuses a missing file, a directory (naming `what`, e.g. "a sweep
/// file"), a pipe or device, and files over 16 MB, each an InputError naming the path.
std::string read_yaml_file(const std::string& path, const std::string& what);

/// Parses the value of "--set key=value" with the same checks; errors name "--set" and `key`.
YAML::Node parse_set_value(const std::string& value, const std::string& key);

/// Refuses the same key twice among "--set key=value" assignments as given on one command line
/// (InputError at "--set", key, naming both values; exit 2): which one was meant is unknown.
void refuse_repeated_overrides(const std::vector<std::string>& overrides);

class ConfigTree {
 public:
  /// Loads a YAML file and applies overrides of the form "a.b.c=value" (value parsed as YAML).
  static ConfigTree load(const std::string& path, const std::vector<std::string>& overrides = {});
  /// Builds a tree from YAML text (for tests and sweeps); `name` is used in messages.
  static ConfigTree from_string(const std::string& yaml, const std::string& name,
                                const std::vector<std::string>& overrides = {});

  ConfigSection root() const;
  /// Throws InputError for the first key nobody read (a misspelt or unsupported key).
  void reject_unknown_keys() const;
  const std::string& file() const { return state_->file; }
  /// Resolves a path written in the config relative to the config file's folder.
  std::filesystem::path resolve_path(const std::string& relative) const;
  /// The tree as YAML text (after overrides), e.g. to write an augmented config.
  std::string dump() const;

  struct State {
    std::string file;
    YAML::Node root;
    std::set<std::string> consumed;    // dotted keys that were read
    std::set<std::string> overridden;  // dotted keys set on the command line
  };

 private:
  std::shared_ptr<State> state_;
};

/// A mapping inside the tree, addressed by its dotted prefix ("" for the root).
class ConfigSection {
 public:
  ConfigSection(std::shared_ptr<ConfigTree::State> state, YAML::Node node, std::string prefix);

  bool has(const std::string& key) const;
  ConfigSection section(const std::string& key) const;

  double number(const std::string& key, double fallback, double min, double max) const;
  /// Like number() but the value must be strictly greater than min.
  double positive(const std::string& key, double fallback, double max = 1e300) const;
  long integer(const std::string& key, long fallback, long min, long max) const;
  bool boolean(const std::string& key, bool fallback) const;
  std::string text(const std::string& key, const std::string& fallback) const;
  std::string choice(const std::string& key, const std::string& fallback,
                     const std::vector<std::string>& allowed) const;
  std::vector<double> numbers(const std::string& key, const std::vector<double>& fallback,
                              double min, double max) const;
  std::vector<long> integers(const std::string& key, const std::vector<long>& fallback, long min,
                             long max) const;
  std::vector<std::string> texts(const std::string& key,
                                 const std::vector<std::string>& fallback) const;
  /// A list of integer lists, e.g. [[1, 2, 3], [2, 3, 4]]: empty when absent; at most
  /// `max_lists` lists, every item an integer in [min, max].
  std::vector<std::vector<long>> integer_lists(const std::string& key, long min, long max,
                                               std::size_t max_lists) const;

  /// Location of a key for error messages (file:line or --set).
  InputLocation where(const std::string& key) const;
  std::string dotted(const std::string& key) const;
  const std::string& prefix() const { return prefix_; }
  /// Error for a value that is syntactically fine but inconsistent with others.
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 private:
  YAML::Node child(const std::string& key) const;
  std::shared_ptr<ConfigTree::State> state_;
  YAML::Node node_;
  std::string prefix_;
};

}  // namespace modaltyre
