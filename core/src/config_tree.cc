#include "modaltyre/core/config_tree.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/input_file.h"
#include "modaltyre/core/yaml_guard.h"

namespace modaltyre {
namespace {

std::vector<std::string> split_dotted(const std::string& key) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(key);
  while (std::getline(in, part, '.')) parts.push_back(part);
  return parts;
}

void apply_override(ConfigTree::State& st, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InputError({"--set", 0, assignment}, "expected dotted.key=value");
  }
  const std::string key = assignment.substr(0, eq);
  const std::string value = assignment.substr(eq + 1);
  const auto parts = split_dotted(key);
  for (const auto& p : parts) {
    if (p.empty()) throw InputError({"--set", 0, key}, "empty component in dotted key");
  }
  const YAML::Node parsed = parse_set_value(value, key);
  YAML::Node cur = st.root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    if (cur[parts[i]] && !cur[parts[i]].IsMap()) {
      throw InputError({"--set", 0, key}, "'" + parts[i] + "' is not a section");
    }
    YAML::Node next = cur[parts[i]];
    cur.reset(next);
  }
  cur[parts.back()] = parsed;
  st.overridden.insert(key);
}

void init_state(YAML::Node root, const std::string& name, const std::vector<std::string>& overrides,
                ConfigTree::State* st) {
  if (!root || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  if (!root.IsMap()) throw InputError({name, 1, ""}, "top level must be a mapping of keys");
  st->file = name;
  st->root = root;
  for (const auto& o : overrides) apply_override(*st, o);
}

void collect_unconsumed(const ConfigTree::State& st, const YAML::Node& node,
                        const std::string& prefix, std::vector<std::string>& out,
                        std::vector<int>& lines) {
  if (!node.IsMap()) return;
  for (const auto& kv : node) {
    if (!kv.first.IsScalar()) {  // e.g. "[a]: 1" (found by fuzz_config)
      const int line = kv.first.Mark().line >= 0 ? kv.first.Mark().line + 1 : 0;
      throw InputError({st.file, line, prefix}, "keys must be plain names, not lists or mappings");
    }
    const std::string key = kv.first.Scalar();
    const std::string dotted = prefix.empty() ? key : prefix + "." + key;
    // "tread.modulus_MPa: 5" in a file would pass as the nested key that was read, its value
    // ignored; only --set and sweeps take dotted keys.
    if (key.find('.') != std::string::npos) {
      const int line = kv.first.Mark().line >= 0 ? kv.first.Mark().line + 1 : 0;
      throw InputError({st.file, line, dotted},
                       "a key with '.' is not read in a config file; write it nested (" +
                           key.substr(0, key.find('.')) + ":, then the rest indented below)");
    }
    if (kv.second.IsMap() && !st.consumed.count(dotted)) {
      collect_unconsumed(st, kv.second, dotted, out, lines);
    } else if (!st.consumed.count(dotted)) {
      out.push_back(dotted);
      lines.push_back(kv.first.Mark().line >= 0 ? kv.first.Mark().line + 1 : 0);
    }
  }
}

}  // namespace

std::string read_yaml_file(const std::string& path, const std::string& what) {
  // A config is a few kB: a file of megabytes is the wrong file, not a config to parse.
  constexpr std::uintmax_t kMaxConfigBytes = 16u << 20;
  return read_input_file(path, what, "YAML files", kMaxConfigBytes);
}

ConfigTree ConfigTree::load(const std::string& path, const std::vector<std::string>& overrides) {
  return from_string(read_yaml_file(path, "a YAML config"), path, overrides);
}

void refuse_repeated_overrides(const std::vector<std::string>& overrides) {
  std::map<std::string, std::string> seen;  // key -> value as first given
  for (const auto& o : overrides) {
    const auto eq = o.find('=');
    if (eq == std::string::npos) continue;  // refused with its own message where it is applied
    const std::string key = o.substr(0, eq), value = o.substr(eq + 1);
    const auto [it, fresh] = seen.emplace(key, value);
    if (!fresh) {
      throw InputError({"--set", 0, key}, "given twice ('" + printable(it->second) + "' and '" +
                                              printable(value) + "'); state it once");
    }
  }
}

YAML::Node parse_set_value(const std::string& value, const std::string& key) {
  try {
    check_yaml_structure(value, "--set");
    return YAML::Load(value);
  } catch (const InputError& e) {
    const std::string all = e.what(), prefix = format_location(e.where(), "");
    throw InputError({"--set", 0, key},
                     all.rfind(prefix, 0) == 0 ? all.substr(prefix.size()) : all);
  } catch (const YAML::Exception& e) {
    const std::string shown = value.size() > 60 ? value.substr(0, 60) + "..." : value;
    throw InputError({"--set", 0, key}, "cannot parse value '" + shown + "': " + e.msg);
  }
}

YAML::Node parse_yaml(const std::string& text, const std::string& name) {
  check_yaml_structure(text, name);
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError({name, e.mark.line >= 0 ? e.mark.line + 1 : 0, ""},
                     "YAML syntax error: " + e.msg);
  }
}

ConfigTree ConfigTree::from_string(const std::string& yaml, const std::string& name,
                                   const std::vector<std::string>& overrides) {
  const YAML::Node root = parse_yaml(yaml, name);
  ConfigTree tree;
  tree.state_ = std::make_shared<State>();
  init_state(root, name, overrides, tree.state_.get());
  return tree;
}

ConfigSection ConfigTree::root() const { return ConfigSection(state_, state_->root, ""); }

void ConfigTree::reject_unknown_keys() const {
  std::vector<std::string> keys;
  std::vector<int> lines;
  collect_unconsumed(*state_, state_->root, "", keys, lines);
  if (keys.empty()) return;
  const bool from_cli = state_->overridden.count(keys.front()) > 0;
  throw InputError({from_cli ? "--set" : state_->file, from_cli ? 0 : lines.front(), keys.front()},
                   "unknown key (misspelt, or not supported here)");
}

std::filesystem::path ConfigTree::resolve_path(const std::string& relative) const {
  const std::filesystem::path p(relative);
  if (p.is_absolute()) return p;
  return std::filesystem::path(state_->file).parent_path() / p;
}

std::string ConfigTree::dump() const {
  YAML::Emitter out;
  out << state_->root;
  return std::string(out.c_str()) + "\n";
}

ConfigSection::ConfigSection(std::shared_ptr<ConfigTree::State> state, YAML::Node node,
                             std::string prefix)
    : state_(std::move(state)), node_(node), prefix_(std::move(prefix)) {}

std::string ConfigSection::dotted(const std::string& key) const {
  return prefix_.empty() ? key : prefix_ + "." + key;
}

InputLocation ConfigSection::where(const std::string& key) const {
  const std::string d = dotted(key);
  if (state_->overridden.count(d)) return {"--set", 0, d};
  int line = 0;
  if (node_ && node_.IsMap()) {
    for (const auto& kv : node_) {
      if (kv.first.IsScalar() && kv.first.Scalar() == key) line = kv.first.Mark().line + 1;
    }
    if (line == 0) line = node_.Mark().line + 1;
  }
  return {state_->file, std::max(line, 0), d};
}

void ConfigSection::fail(const std::string& key, const std::string& message) const {
  throw InputError(where(key), message);
}

YAML::Node ConfigSection::child(const std::string& key) const {
  if (!node_ || !node_.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
  state_->consumed.insert(dotted(key));
  const YAML::Node& const_node = node_;
  return const_node[key];
}

bool ConfigSection::has(const std::string& key) const {
  if (!node_ || !node_.IsMap()) return false;
  const YAML::Node& const_node = node_;
  return static_cast<bool>(const_node[key]);
}

ConfigSection ConfigSection::section(const std::string& key) const {
  YAML::Node n = child(key);
  if (n && !n.IsMap() && !n.IsNull()) fail(key, "expected a section (a mapping of keys)");
  // Reading a section does not consume its children: they are checked one by one.
  state_->consumed.erase(dotted(key));
  return ConfigSection(state_, n, dotted(key));
}

double ConfigSection::number(const std::string& key, double fallback, double min,
                             double max) const {
  const YAML::Node n = child(key);
  if (!n) return fallback;
  if (!n.IsScalar()) fail(key, "expected a number");
  const auto v = parse_finite_double(n.Scalar());
  if (!v)
    fail(key, "expected a finite number, got '" + printable(n.Scalar()) + "'" +
                  decimal_hint(n.Scalar()));
  if (*v < min || *v > max) {
    std::ostringstream msg;
    msg << "value " << *v << " is out of range [" << min << ", " << max << "]";
    fail(key, msg.str());
  }
  return *v;
}

double ConfigSection::positive(const std::string& key, double fallback, double max) const {
  const double v = number(key, fallback, -1e300, max);
  if (!(v > 0.0)) {
    std::ostringstream msg;
    msg << "value " << v << " must be greater than 0";
    fail(key, msg.str());
  }
  return v;
}

long ConfigSection::integer(const std::string& key, long fallback, long min, long max) const {
  const YAML::Node n = child(key);
  if (!n) return fallback;
  if (!n.IsScalar()) fail(key, "expected an integer");
  const auto v = parse_finite_double(n.Scalar());
  if (!v || std::floor(*v) != *v || std::abs(*v) > 9e15) {
    fail(key,
         "expected an integer, got '" + printable(n.Scalar()) + "'" + decimal_hint(n.Scalar()));
  }
  if (*v < static_cast<double>(min) || *v > static_cast<double>(max)) {
    fail(key, "value " + n.Scalar() + " is out of range [" + std::to_string(min) + ", " +
                  std::to_string(max) + "]");
  }
  return static_cast<long>(*v);
}

bool ConfigSection::boolean(const std::string& key, bool fallback) const {
  const YAML::Node n = child(key);
  if (!n) return fallback;
  if (!n.IsScalar()) fail(key, "expected true or false");
  const std::string s = n.Scalar();
  if (s == "true" || s == "True" || s == "yes" || s == "on") return true;
  if (s == "false" || s == "False" || s == "no" || s == "off") return false;
  fail(key, "expected true or false, got '" + s + "'");
}

std::string ConfigSection::text(const std::string& key, const std::string& fallback) const {
  const YAML::Node n = child(key);
  if (!n) return fallback;
  if (!n.IsScalar()) fail(key, "expected a text value");
  return n.Scalar();
}

std::string ConfigSection::choice(const std::string& key, const std::string& fallback,
                                  const std::vector<std::string>& allowed) const {
  const std::string v = text(key, fallback);
  for (const auto& a : allowed) {
    if (a == v) return v;
  }
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
  fail(key, "'" + v + "' is not one of: " + list);
}

std::vector<double> ConfigSection::numbers(const std::string& key,
                                           const std::vector<double>& fallback, double min,
                                           double max) const {
  const YAML::Node n = child(key);
  if (!n) return fallback;
  if (!n.IsSequence()) fail(key, "expected a list of numbers, e.g. [1, 2, 3]");
  std::vector<double> out;
  for (const auto& item : n) {
    const auto v = item.IsScalar() ? parse_finite_double(item.Scalar()) : std::nullopt;
    if (!v) {
      fail(key, "every list item must be a finite number" +
                    (item.IsScalar()
                         ? ", got '" + printable(item.Scalar()) + "'" + decimal_hint(item.Scalar())
                         : std::string()));
    }
    if (*v < min || *v > max) {
      std::ostringstream msg;
      msg << "list value " << *v << " is out of range [" << min << ", " << max << "]";
      fail(key, msg.str());
    }
    out.push_back(*v);
  }
  return out;
}

std::vector<long> ConfigSection::integers(const std::string& key, const std::vector<long>& fallback,
                                          long min, long max) const {
  std::vector<double> fb(fallback.begin(), fallback.end());
  const auto vals = numbers(key, fb, static_cast<double>(min), static_cast<double>(max));
  std::vector<long> out;
  for (double v : vals) {
    if (std::floor(v) != v) fail(key, "every list item must be an integer");
    out.push_back(static_cast<long>(v));
  }
  return out;
}

std::vector<std::string> ConfigSection::texts(const std::string& key,
                                              const std::vector<std::string>& fallback) const {
  const YAML::Node n = child(key);
  if (!n) return fallback;
  if (!n.IsSequence()) fail(key, "expected a list, e.g. [a, b]");
  std::vector<std::string> out;
  for (const auto& item : n) {
    if (!item.IsScalar()) fail(key, "every list item must be a text value");
    out.push_back(item.Scalar());
  }
  return out;
}

std::vector<std::vector<long>> ConfigSection::integer_lists(const std::string& key, long min,
                                                            long max, std::size_t max_lists) const {
  const YAML::Node n = child(key);
  if (!n) return {};
  if (!n.IsSequence()) fail(key, "expected a list of lists, e.g. [[1, 2, 3], [2, 3, 4]]");
  if (n.size() > max_lists) {
    fail(key, "at most " + std::to_string(max_lists) + " lists, got " + std::to_string(n.size()));
  }
  std::vector<std::vector<long>> out;
  for (const auto& list : n) {
    if (!list.IsSequence()) fail(key, "every item must be a list, e.g. [1, 2, 3]");
    std::vector<long> v;
    for (const auto& item : list) {
      const auto x = item.IsScalar() ? parse_finite_double(item.Scalar()) : std::nullopt;
      if (!x || std::floor(*x) != *x) fail(key, "every list item must be an integer");
      if (*x < static_cast<double>(min) || *x > static_cast<double>(max)) {
        // Written as a double: a value beyond long long's range has no integer conversion (UB).
        char value[40];  // shortest round trip, e.g. 1001 or 1e+300
        const auto end = std::to_chars(value, value + sizeof value, *x).ptr;
        fail(key, "list value " + std::string(value, end) + " is out of range [" +
                      std::to_string(min) + ", " + std::to_string(max) + "]");
      }
      v.push_back(static_cast<long>(*x));
    }
    out.push_back(std::move(v));
  }
  return out;
}

}  // namespace modaltyre
