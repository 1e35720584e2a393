#include "modaltyre/core/command_files.h"

#include <filesystem>

#include "modaltyre/core/errors.h"

namespace modaltyre {
namespace {

namespace fs = std::filesystem;

/// Links followed at most (Linux's own limit on a path's symbolic links, MAXSYMLINKS).
constexpr int kMaxLinkHops = 40;

}  // namespace

std::string final_target(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::absolute(fs::path(path), ec);
  if (ec) return fs::path(path).lexically_normal().string();
  for (int hop = 0; hop <= kMaxLinkHops; ++hop) {
    // The folders' links resolved (they exist or the output is refused), then the last part's.
    const fs::path folder = fs::weakly_canonical(p.parent_path(), ec);
    if (!ec) p = folder / p.filename();
    if (!fs::is_symlink(fs::symlink_status(p, ec))) break;
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) break;
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  return p.lexically_normal().string();
}

namespace {

// Streams (/dev/stdout, /dev/null, a pipe) are written in place and read nothing back: two
// outputs to /dev/null do not clobber each other.
bool is_stream(const std::string& path) {
  std::error_code ec;
  const auto type = fs::status(path, ec).type();
  return !ec && (type == fs::file_type::character || type == fs::file_type::fifo ||
                 type == fs::file_type::socket || type == fs::file_type::block);
}

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return false;
  std::error_code ea, eb, ec;
  if (fs::exists(a, ea) && fs::exists(b, eb)) {
    const bool eq = fs::equivalent(a, b, ec);
    if (!ec) return eq;
  }
  return final_target(a) == final_target(b);
}

void CommandFiles::input(const std::string& path, const std::string& role) {
  if (!path.empty()) inputs_.push_back({path, role});
}

void CommandFiles::inputs(const CommandFiles& other) {
  for (const auto& e : other.inputs_) inputs_.push_back(e);
}

void CommandFiles::output(const std::string& path, const std::string& option) {
  outputs_.push_back({path, option});
}

void CommandFiles::check() const {
  for (std::size_t i = 0; i < outputs_.size(); ++i) {
    const Entry& out = outputs_[i];
    if (out.path.empty()) {
      throw InputError({"", 0, out.role}, "the output path is empty; name a file to write");
    }
    std::error_code ec;
    if (fs::is_directory(out.path, ec)) {
      throw InputError({out.path, 0, out.role}, "output path is a directory, not a file");
    }
    const fs::path folder = fs::absolute(fs::path(out.path), ec).parent_path();
    if (!ec && !fs::is_directory(folder, ec)) {
      throw InputError({out.path, 0, out.role},
                       "output folder '" + folder.string() + "' does not exist");
    }
    if (is_stream(out.path)) continue;
    for (const Entry& in : inputs_) {
      if (same_file(out.path, in.path)) {
        throw InputError({out.path, 0, out.role},
                         "refusing to write over an input: this is the same file as " + in.role +
                             " ('" + in.path + "'); name another output file");
      }
    }
    for (std::size_t k = 0; k < i; ++k) {
      if (same_file(out.path, outputs_[k].path)) {
        throw InputError({out.path, 0, out.role}, "the same file as the output of " +
                                                      outputs_[k].role + " ('" + outputs_[k].path +
                                                      "'); each output needs a file of its own");
      }
    }
  }
}

}  // namespace modaltyre
