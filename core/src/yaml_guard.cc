#include "modaltyre/core/yaml_guard.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/parser.h>

#include <map>
#include <sstream>
#include <vector>

#include "modaltyre/core/errors.h"
#include "modaltyre/core/input_file.h"

namespace modaltyre {
namespace {

int line_of(const YAML::Mark& m) { return m.line >= 0 ? m.line + 1 : 0; }

// Walks the parser's events with a stack of open mappings and lists. In a mapping, events
// alternate key, value; the scalar keys seen so far are kept with their lines.
class StructureChecker : public YAML::EventHandler {
 public:
  explicit StructureChecker(std::string name, int locate_line = 0)
      : name_(std::move(name)), locate_line_(locate_line) {}

  /// The dotted key of the first scalar on line `locate_line` (its name or the key it is the
  /// value of); empty if none was seen.
  const std::string& located_key() const { return located_; }

  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents_ > 1) {
      throw InputError({name_, line_of(mark), ""},
                       "a second YAML document ('---'): give one document per file");
    }
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { child(mark, nullptr); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override {
    throw InputError({name_, line_of(mark), dotted(-1)},
                     "YAML aliases (*name, <<: *name) are not accepted: write the values out "
                     "(aliases can expand a few lines into billions of nodes)");
  }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                const std::string& value) override {
    child(mark, &value);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    open(mark, false);
  }
  void OnSequenceEnd() override { stack_.pop_back(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    open(mark, true);
  }
  void OnMapEnd() override { stack_.pop_back(); }

 private:
  struct Frame {
    bool is_map;
    long children;                    // events seen directly inside
    std::map<std::string, int> keys;  // scalar key -> line (mappings)
    std::string last_key;             // the key whose value comes next (mappings)
  };

  // The dotted key of the open mappings (for messages), up to frame `upto` (-1: all).
  std::string dotted(int upto) const {
    std::string d;
    const int n = upto < 0 ? static_cast<int>(stack_.size()) : upto;
    for (int i = 0; i < n; ++i) {
      if (!stack_[i].is_map || stack_[i].last_key.empty()) continue;
      d += (d.empty() ? "" : ".") + stack_[i].last_key;
    }
    return d;
  }

  // A list or mapping starts: the events come as the parser descends, so the depth is refused
  // before yaml-cpp's own limit (or the stack) is reached.
  void open(const YAML::Mark& mark, bool is_map) {
    child(mark, nullptr);
    if (static_cast<int>(stack_.size()) >= kMaxYamlDepth) {
      throw InputError({name_, line_of(mark), dotted(-1)},
                       "nesting deeper than " + std::to_string(kMaxYamlDepth) +
                           " levels (lists and sections inside each other); a config needs a few");
    }
    stack_.push_back(Frame{is_map, 0, {}, {}});
  }

  void child(const YAML::Mark& mark, const std::string* scalar) {
    if (locate_line_ > 0) {
      locate(mark, scalar);
      return;
    }
    if (++nodes_ > kMaxYamlNodes) {
      throw InputError({name_, line_of(mark), ""},
                       "more than " + std::to_string(kMaxYamlNodes) +
                           " YAML nodes; an input this large is not a config");
    }
    if (stack_.empty()) return;
    Frame& f = stack_.back();
    const bool is_key = f.is_map && f.children % 2 == 0;
    ++f.children;
    if (!is_key) return;
    f.last_key = scalar ? *scalar : std::string();
    if (!scalar) return;  // a list or mapping as key is reported by the config reader
    const auto [it, fresh] = f.keys.emplace(*scalar, line_of(mark));
    if (!fresh) {
      const std::string here = dotted(-1);
      if (name_ == "--set") throw InputError({name_, 0, here}, "given twice in one value");
      throw InputError({name_, line_of(mark), here},
                       "given twice in the same " +
                           std::string(stack_.size() == 1 ? "file" : "section") +
                           " (first at line " + std::to_string(it->second) + ", again at line " +
                           std::to_string(line_of(mark)) + "); give each key once");
    }
  }

  // Only bookkeeping of the keys, to name the one at locate_line_.
  void locate(const YAML::Mark& mark, const std::string* scalar) {
    if (stack_.empty()) return;
    Frame& f = stack_.back();
    const bool is_key = f.is_map && f.children % 2 == 0;
    ++f.children;
    if (is_key) f.last_key = scalar ? *scalar : std::string();
    if (located_.empty() && scalar && line_of(mark) == locate_line_) located_ = dotted(-1);
  }

  std::string name_;
  int locate_line_ = 0;
  std::string located_;
  std::vector<Frame> stack_;
  long nodes_ = 0;
  int documents_ = 0;
};

}  // namespace

void check_yaml_structure(const std::string& text, const std::string& name) {
  if (const auto problem = text_problem(text)) {
    std::string key;
    if (problem->message.find("UTF-8") != std::string::npos) {
      std::istringstream in(text);
      YAML::Parser parser(in);
      StructureChecker locator(name, problem->line);
      try {
        while (parser.HandleNextDocument(locator)) {
        }
      } catch (const std::exception&) {
        // The key is named if the parser reached the line; the refusal stands either way.
      }
      key = locator.located_key();
    }
    throw InputError({name, name == "--set" ? 0 : problem->line, key}, problem->message);
  }
  std::istringstream in(text);
  YAML::Parser parser(in);
  StructureChecker checker(name);
  try {
    while (parser.HandleNextDocument(checker)) {
    }
  } catch (const YAML::Exception&) {
    // Syntax errors are reported by the loader with its own message.
  }
}

}  // namespace modaltyre
