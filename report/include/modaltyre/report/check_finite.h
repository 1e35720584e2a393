#pragma once
// Non-finite numbers are refused in every JSON document: JSON writes them as null, which would
// silently corrupt a researcher's pipeline (the CLI's --json and the Python dicts alike).
#include <nlohmann/json.hpp>
#include <string>

namespace modaltyre::report {

/// Throws ComputationError if any number in the document is not finite; `where` names the
/// path of the offending value in the message.
void check_finite(const nlohmann::json& j, const std::string& where = "output");

}  // namespace modaltyre::report
