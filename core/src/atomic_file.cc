#include "modaltyre/core/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "modaltyre/core/command_files.h"
#include "modaltyre/core/errors.h"

namespace modaltyre {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, const std::string& what, int err) {
  throw InputError({path, 0, ""}, what + (err ? std::string(" (") + std::strerror(err) + ")" : ""));
}

// Writes all of `content` to `fd`; returns 0 or the errno of the failed write (a full disk is
// ENOSPC, a file-size limit EFBIG).
int write_all(int fd, const std::string& content) {
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t w = ::write(fd, content.data() + done, content.size() - done);
    if (w < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    done += static_cast<std::size_t>(w);
  }
  return 0;
}

// A device, pipe or socket (e.g. /dev/stdout, /dev/null, a FIFO) cannot be replaced by a
// rename and must not be: it is written in place.
bool is_stream_target(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return false;
  return S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode) || S_ISBLK(st.st_mode);
}

// /dev/stdout, /dev/fd/N and /proc/self/fd/N name a descriptor of this process; when it is
// redirected to a regular file, that file must be written through the descriptor, not
// replaced (the shell would still hold the old file).
bool names_a_descriptor(const std::string& path) {
  return path.rfind("/dev/", 0) == 0 || path.rfind("/proc/", 0) == 0;
}

void write_in_place(const std::string& path, const std::string& content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) fail(path, "cannot open the output for writing", errno);
  const int werr = write_all(fd, content);
  const int cerr = ::close(fd) != 0 ? errno : 0;
  if (werr || cerr) fail(path, "writing the output failed", werr ? werr : cerr);
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& content) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError({path, 0, ""}, "output path is a directory");
  if (is_stream_target(path) || (names_a_descriptor(path) && fs::exists(path, ec))) {
    write_in_place(path, content);
    return;
  }
  // A symbolic link stays a link: the file it points to is replaced (or created, when the link
  // dangles), the one CommandFiles compared with the command's other files.
  fs::path target(path);
  if (fs::is_symlink(fs::symlink_status(target, ec))) target = final_target(path);
  static std::atomic<unsigned> counter{0};
  std::string tmp_name = ".";
  tmp_name.append(target.filename().string())
      .append(".tmp")
      .append(std::to_string(::getpid()))
      .append("_")
      .append(std::to_string(counter++));
  const fs::path tmp = target.parent_path() / tmp_name;
  struct stat old {};
  const bool existed = ::stat(target.c_str(), &old) == 0;
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) fail(path, "cannot write the output file (folder missing or not writable?)", errno);
  if (existed) (void)::fchmod(fd, old.st_mode & 07777);  // an overwrite keeps the permissions
  const int werr = write_all(fd, content);
  const int cerr = ::close(fd) != 0 ? errno : 0;
  if (werr || cerr) {
    fs::remove(tmp, ec);
    fail(path, "writing the output file failed; nothing was written", werr ? werr : cerr);
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    const int rerr = ec.value();
    fs::remove(tmp, ec);
    fail(path, "cannot move the finished output into place", rerr);
  }
}

}  // namespace modaltyre
