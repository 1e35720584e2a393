#include "modaltyre/core/errors.h"

#include <sstream>

namespace modaltyre {

std::string format_location(const InputLocation& where, const std::string& message) {
  std::ostringstream out;
  const char* sep = "";
  if (!where.file.empty()) {
    out << where.file;
    if (where.line > 0) out << ':' << where.line;
    sep = ": ";
  }
  if (!where.key.empty()) {
    out << sep << where.key;
    sep = ": ";
  }
  out << sep << message;
  return out.str();
}

InputError::InputError(InputLocation where, const std::string& message)
    : std::runtime_error(format_location(where, message)), where_(std::move(where)) {}

}  // namespace modaltyre
