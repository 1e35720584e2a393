#include "modaltyre/core/atomic_file.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "modaltyre/core/errors.h"

namespace modaltyre {

void write_file_atomically(const std::string& path, const std::string& content) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError({path, 0, ""}, "output path is a directory");
  const fs::path target(path);
  std::string tmp_name = ".";
  tmp_name.append(target.filename().string()).append(".tmp").append(std::to_string(getpid()));
  const fs::path tmp = target.parent_path() / tmp_name;
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError({path, 0, ""}, "cannot write output file (folder missing?)");
    out << content;
    out.flush();
    if (!out) {
      fs::remove(tmp, ec);
      throw InputError({path, 0, ""}, "writing the output file failed");
    }
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw InputError({path, 0, ""}, "cannot move the finished output into place");
  }
}

}  // namespace modaltyre
