#pragma once
// Structural checks of YAML input before it is loaded into a tree (issue 16):
//  - a key given twice in one mapping (or a section twice) is an error naming both lines;
//    yaml-cpp would silently keep the first value;
//  - aliases (*name, and merge keys <<: *name) are refused: a few lines of anchors and aliases
//    expand into exponentially many nodes ("billion laughs"), and a config never needs them;
//  - a second document ("---") is refused instead of being silently ignored;
//  - the number of nodes is bounded, and so is their nesting: yaml-cpp gives up on 10 000 nested
//    '[' or '{' with "bad file" (its parser recurses per level), named here at the line;
//  - text that is not UTF-8 text (core/input_file.h, text_problem: a NUL byte, a Latin-1 byte,
//    CR-only line ends) is refused at its line, with the key whose value or name holds the byte,
//    instead of failing later in the JSON writer or with yaml-cpp's unrelated message.
#include <string>

namespace modaltyre {

/// Maximum number of YAML nodes (keys, values, list items) in one input.
inline constexpr long kMaxYamlNodes = 1'000'000;

/// Maximum nesting of lists and mappings inside each other (a config nests 4 deep, a sweep 5).
inline constexpr int kMaxYamlDepth = 64;

/// Throws InputError({name, line, dotted key}, ...) for the first problem above; YAML syntax
/// errors are left to the loader (not reported here).
void check_yaml_structure(const std::string& text, const std::string& name);

}  // namespace modaltyre
