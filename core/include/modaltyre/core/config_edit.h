#pragma once
// Setting keys of a YAML config in its text, so that a written copy keeps the source's comments,
// key order and layout (ConfigTree::dump() writes the values only).
#include <optional>
#include <string>
#include <vector>

namespace modaltyre {

/// `text` (a YAML document read as `name`) with the overrides "dotted.key=value" (the form of
/// --set; value is YAML flow text) applied in place: a key written on one line gets the new value
/// on that line, its comment kept; a missing key is inserted at the end of its deepest existing
/// block mapping, with the sections it needs. A line set or inserted without a comment of its own
/// gets "  # " + `marker` (none when `marker` is empty). The result reads as
/// ConfigTree::from_string(text, name, overrides) does (checked); nullopt when a key cannot be set
/// in place (a value spanning lines, a flow mapping on the way, anything the check refuses).
/// InputError for YAML that does not parse or an override without '='.
std::optional<std::string> set_keys_in_text(const std::string& text, const std::string& name,
                                            const std::vector<std::string>& overrides,
                                            const std::string& marker = "");

}  // namespace modaltyre
