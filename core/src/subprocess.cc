#include "modaltyre/core/subprocess.h"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <ctime>

extern char** environ;

namespace modaltyre {
namespace {

constexpr std::size_t kMaxErrBytes = 64 * 1024;

// Closes an fd once; -1 marks "already closed".
void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

// A write to a pipe whose reader has exited raises SIGPIPE, which would kill the program:
// block it in this thread for the duration and discard a pending one afterwards.
class SigpipeGuard {
 public:
  SigpipeGuard() {
    sigemptyset(&pipe_set_);
    sigaddset(&pipe_set_, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_set_, &old_);
  }
  ~SigpipeGuard() {
    const timespec zero{0, 0};
    while (sigtimedwait(&pipe_set_, nullptr, &zero) > 0) {
    }
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  SigpipeGuard(const SigpipeGuard&) = delete;
  SigpipeGuard& operator=(const SigpipeGuard&) = delete;

 private:
  sigset_t pipe_set_{}, old_{};
};

}  // namespace

SubprocessResult run_subprocess(const std::vector<std::string>& argv, const std::string& input,
                                double timeout_s, std::size_t max_out_bytes) {
  SubprocessResult result;
  if (argv.empty()) return result;
  int in_pipe[2], out_pipe[2], err_pipe[2];
  if (pipe2(in_pipe, O_CLOEXEC) != 0) return result;
  if (pipe2(out_pipe, O_CLOEXEC) != 0) {
    ::close(in_pipe[0]);
    ::close(in_pipe[1]);
    return result;
  }
  if (pipe2(err_pipe, O_CLOEXEC) != 0) {
    for (int fd : {in_pipe[0], in_pipe[1], out_pipe[0], out_pipe[1]}) ::close(fd);
    return result;
  }
  SigpipeGuard sigpipe_guard;

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in_pipe[0], 0);
  posix_spawn_file_actions_adddup2(&actions, out_pipe[1], 1);
  posix_spawn_file_actions_adddup2(&actions, err_pipe[1], 2);
  // The child starts with SIGPIPE at its default, whatever this thread blocks.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK);

  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = -1;
  const int spawn_rc = posix_spawnp(&pid, args[0], &actions, &attr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  ::close(in_pipe[0]);
  ::close(out_pipe[1]);
  ::close(err_pipe[1]);
  int to_child = in_pipe[1], from_out = out_pipe[0], from_err = err_pipe[0];
  if (spawn_rc != 0) {
    close_fd(to_child);
    close_fd(from_out);
    close_fd(from_err);
    return result;
  }
  result.started = true;
  fcntl(to_child, F_SETFL, fcntl(to_child, F_GETFL) | O_NONBLOCK);

  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  std::size_t written = 0;
  if (input.empty()) close_fd(to_child);
  bool overflow = false;
  char buf[65536];
  while ((from_out >= 0 || from_err >= 0) && !overflow) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      result.timed_out = true;
      break;
    }
    pollfd fds[3];
    int n = 0;
    int i_in = -1, i_out = -1, i_err = -1;
    if (to_child >= 0) fds[i_in = n++] = {to_child, POLLOUT, 0};
    if (from_out >= 0) fds[i_out = n++] = {from_out, POLLIN, 0};
    if (from_err >= 0) fds[i_err = n++] = {from_err, POLLIN, 0};
    const int ready = ::poll(fds, n, static_cast<int>(std::min<long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) continue;
    if (i_in >= 0 && fds[i_in].revents) {
      const ssize_t w = ::write(to_child, input.data() + written, input.size() - written);
      if (w > 0) written += static_cast<std::size_t>(w);
      if ((w < 0 && errno != EAGAIN && errno != EINTR) || written == input.size()) {
        close_fd(to_child);  // done, or the reader is gone (EPIPE)
      }
    }
    if (i_out >= 0 && fds[i_out].revents) {
      const ssize_t r = ::read(from_out, buf, sizeof buf);
      if (r > 0) {
        result.out.append(buf, static_cast<std::size_t>(r));
        overflow = result.out.size() > max_out_bytes;
      } else if (r == 0 || (errno != EAGAIN && errno != EINTR)) {
        close_fd(from_out);
      }
    }
    if (i_err >= 0 && fds[i_err].revents) {
      const ssize_t r = ::read(from_err, buf, sizeof buf);
      if (r > 0) {
        if (result.err.size() < kMaxErrBytes) result.err.append(buf, static_cast<std::size_t>(r));
      } else if (r == 0 || (errno != EAGAIN && errno != EINTR)) {
        close_fd(from_err);
      }
    }
  }
  close_fd(to_child);
  close_fd(from_out);
  close_fd(from_err);
  if (result.timed_out || overflow) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.exit_status = (WIFEXITED(status) && !result.timed_out && !overflow)
                           ? WEXITSTATUS(status)
                           : -1;
  return result;
}

}  // namespace modaltyre
