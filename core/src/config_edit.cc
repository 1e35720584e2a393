#include "modaltyre/core/config_edit.h"

#include <yaml-cpp/yaml.h>

#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"

namespace modaltyre {
namespace {

constexpr auto npos = std::string::npos;

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == npos) {
      lines.push_back(text.substr(start));
      break;
    }
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string text;
  for (const auto& l : lines) text += l + "\n";
  return text;
}

int indent_of(const std::string& line) {
  const std::size_t first = line.find_first_not_of(' ');
  return first == npos ? static_cast<int>(line.size()) : static_cast<int>(first);
}

// A line that holds YAML (not blank, not only a comment).
bool is_content(const std::string& line) {
  const std::size_t first = line.find_first_not_of(" \t");
  return first != npos && line[first] != '#';
}

// End (exclusive) of the value that starts at `col` on `line`: a quoted scalar at its closing
// quote, a flow collection at its closing bracket, a plain scalar before " #" or the line's end,
// trailing blanks excluded. npos when it does not close on this line.
std::size_t value_end(const std::string& line, std::size_t col) {
  const std::size_t n = line.size();
  if (col >= n) return npos;
  const char c = line[col];
  if (c == '"') {
    for (std::size_t i = col + 1; i < n; ++i) {
      if (line[i] == '\\')
        ++i;
      else if (line[i] == '"')
        return i + 1;
    }
    return npos;
  }
  if (c == '\'') {
    for (std::size_t i = col + 1; i < n; ++i) {
      if (line[i] != '\'') continue;
      if (i + 1 < n && line[i + 1] == '\'')
        ++i;  // '' is a quote inside
      else
        return i + 1;
    }
    return npos;
  }
  if (c == '[' || c == '{') {
    int depth = 0;
    char quote = 0;
    for (std::size_t i = col; i < n; ++i) {
      const char d = line[i];
      if (quote) {
        if (d == quote) quote = 0;
      } else if (d == '"' || d == '\'') {
        quote = d;
      } else if (d == '[' || d == '{') {
        ++depth;
      } else if ((d == ']' || d == '}') && --depth == 0) {
        return i + 1;
      }
    }
    return npos;
  }
  std::size_t e = line.find(" #", col);
  if (e == npos) e = n;
  while (e > col && (line[e - 1] == ' ' || line[e - 1] == '\t')) --e;
  return e;
}

std::vector<std::string> split_dots(const std::string& key) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t dot; (dot = key.find('.', start)) != npos; start = dot + 1)
    parts.push_back(key.substr(start, dot - start));
  parts.push_back(key.substr(start));
  return parts;
}

// Sets one key in `lines`; false when it cannot be done in place. `root` is the tree of `lines`
// with its marks, re-read only after an insertion (a value set on its line moves no other key).
// The text was checked by parse_yaml before (set_keys_in_text), so plain YAML::Load reads it.
bool set_key(std::vector<std::string>& lines, YAML::Node& root, bool& stale, const std::string& key,
             const std::string& value, const std::string& marker) {
  if (stale) {
    root.reset(YAML::Load(join_lines(lines)));
    stale = false;
  }
  if (!root.IsMap() || root.size() == 0) return false;
  const std::vector<std::string> path = split_dots(key);
  const std::string comment = marker.empty() ? "" : "  # " + marker;
  YAML::Node node;
  node.reset(root);
  int key_line = -1, key_indent = -1;  // of the mapping `node` (-1: the document's root)
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (!node.IsMap() || node.size() == 0 || node.Style() == YAML::EmitterStyle::Flow) return false;
    YAML::Node child;
    YAML::Mark child_mark;
    bool found = false;
    for (auto it = node.begin(); it != node.end() && !found; ++it) {
      if (it->first.Scalar() != path[i]) continue;
      found = true;
      child.reset(it->second);
      child_mark = it->first.Mark();
    }
    if (found && i + 1 == path.size()) {  // set the value on the key's line
      const YAML::Mark vm = child.Mark();
      if (vm.line != child_mark.line || vm.line < 0 || vm.line >= static_cast<int>(lines.size()))
        return false;
      std::string& line = lines[vm.line];
      const std::size_t end = value_end(line, static_cast<std::size_t>(vm.column));
      if (end == npos) return false;
      const std::string rest = line.substr(end);
      line = line.substr(0, vm.column) + value + rest + (rest.find('#') == npos ? comment : "");
      return true;
    }
    if (found) {
      key_line = child_mark.line;
      key_indent = child_mark.column;
      node.reset(child);
      continue;
    }
    // Insert path[i..] at the end of the block mapping `node`, at its children's indentation.
    const int child_indent = node.begin()->first.Mark().column;
    int after = -1;
    for (int l = key_line + 1; l < static_cast<int>(lines.size()); ++l) {
      if (!is_content(lines[l])) continue;
      if (key_line >= 0 && indent_of(lines[l]) <= key_indent) break;
      after = l;
    }
    if (after < 0) return false;
    std::vector<std::string> added;
    for (std::size_t j = i; j < path.size(); ++j) {
      std::string l(static_cast<std::size_t>(child_indent) + 2 * (j - i), ' ');
      l += path[j] + ":";
      if (j + 1 == path.size()) l += " " + value + comment;
      added.push_back(l);
    }
    lines.insert(lines.begin() + after + 1, added.begin(), added.end());
    stale = true;
    return true;
  }
  return false;
}

}  // namespace

std::optional<std::string> set_keys_in_text(const std::string& text, const std::string& name,
                                            const std::vector<std::string>& overrides,
                                            const std::string& marker) {
  const std::string expected = ConfigTree::from_string(text, name, overrides).dump();
  if (text.find('\r') != npos) return std::nullopt;  // keep line ends simple: \n only
  std::vector<std::string> lines = split_lines(text);
  YAML::Node root;
  bool stale = true;
  try {
    for (const auto& o : overrides) {
      const std::size_t eq = o.find('=');
      if (!set_key(lines, root, stale, o.substr(0, eq), o.substr(eq + 1), marker))
        return std::nullopt;
    }
  } catch (const YAML::Exception&) {
    return std::nullopt;  // an edit the YAML reader does not take: not in place
  }
  std::string edited = join_lines(lines);
  if (ConfigTree::from_string(edited, name).dump() != expected) return std::nullopt;
  return edited;
}

}  // namespace modaltyre
