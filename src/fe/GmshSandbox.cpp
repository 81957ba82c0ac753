#include "fe/GmshSandbox.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <sstream>
#include <thread>

#include "signorini/core/Error.hpp"

namespace signorini::detail {

void writeAll(int fd, const void* data, std::size_t size) {
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t written = ::write(fd, bytes, size);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) _exit(3);  // the parent is gone
    bytes += written;
    size -= static_cast<std::size_t>(written);
  }
}

bool readAll(int fd, void* data, std::size_t size) {
  char* bytes = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t got = ::read(fd, bytes, size);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    bytes += got;
    size -= static_cast<std::size_t>(got);
  }
  return true;
}

namespace {

void sendError(int fd, char kind, const std::string& message) {
  writeAll(fd, &kind, 1);
  writeAll(fd, message.data(), message.size());
}

// Runs in the child: `work` writes the answer (or an error) to fd. Never returns.
[[noreturn]] void answerInChild(int fd, const std::function<void(int)>& work) {
  // A crash ends the child quietly; the parent reports it (MPI's or a sanitizer's handlers
  // would print a report of their own).
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(sig, SIG_DFL);
  try {
    work(fd);
  } catch (const InputError& e) {
    sendError(fd, 'I', e.what());
  } catch (const std::exception& e) {
    sendError(fd, 'E', e.what());
  } catch (...) {
    sendError(fd, 'E', "unknown error");
  }
  ::close(fd);
  _exit(0);  // no exit handlers: they belong to the parent (MPI, buffered output)
}

// Waits until `fd` can be read (data, or the end of the stream when the child is gone) or
// `seconds` have passed (negative: no limit); false on the time limit.
bool readableWithin(int fd, double seconds) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                        std::chrono::duration<double>(std::max(seconds, 0.0)));
  for (;;) {
    int wait = -1;
    if (seconds >= 0) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) return false;
      wait = static_cast<int>(std::min<long long>(left, 60000));
    }
    pollfd request{fd, POLLIN, 0};
    const int ready = ::poll(&request, 1, wait);
    if (ready > 0) return true;
    if (ready < 0 && errno != EINTR) return true;  // let the read report it
  }
}

}  // namespace

namespace {

// How one child ended: its answer received, an error it reported ('I', 'E' and the message),
// or neither (its exit status or signal in `status`, the end of what it printed in `printed`).
struct ChildEnd {
  bool complete = false;
  char kind = 0;
  std::string message;
  int status = 0;
  std::string printed;  // " (it printed: ...)" or ""
};

// The last lines (at most `limit` characters, whole lines) written to `file`, on one line.
std::string lastLinesOf(std::FILE* file, long limit = 600) {
  if (std::fseek(file, 0, SEEK_END) != 0) return "";
  const long size = std::ftell(file);
  std::fseek(file, std::max(0L, size - limit), SEEK_SET);
  std::string text;
  for (int c; (c = std::fgetc(file)) != EOF;) text += static_cast<char>(c);
  if (size > limit && text.find('\n') != std::string::npos) text.erase(0, text.find('\n') + 1);
  std::replace(text.begin(), text.end(), '\n', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

// " (it printed: <its last lines>)", or "" if the child printed nothing.
std::string printedBy(std::FILE* file) {
  const std::string text = file ? lastLinesOf(file) : "";
  return text.empty() ? "" : " (it printed: " + text + ")";
}

ChildEnd runChild(const std::string& subject, const std::string& doing, double limit,
                  const std::function<void(int)>& work, const std::function<bool(int)>& receive) {
  int fds[2];
  if (::pipe(fds) != 0) throw Error(subject + ": cannot create a pipe for " + doing);
  // The child's standard error: what Gmsh says before it exits is shown if the child fails.
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> printed(std::tmpfile(), &std::fclose);
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw Error(subject + ": cannot start the process for " + doing);
  }
  if (child == 0) {
    ::close(fds[0]);
    if (printed) ::dup2(::fileno(printed.get()), STDERR_FILENO);
    answerInChild(fds[1], work);
  }
  ::close(fds[1]);
  ChildEnd end;
  if (!readableWithin(fds[0], limit)) {
    ::kill(child, SIGKILL);
    while (::waitpid(child, &end.status, 0) < 0 && errno == EINTR) {
    }
    ::close(fds[0]);
    std::ostringstream seconds;
    seconds << limit;
    throw InputError(subject + ": Gmsh did not finish " + doing + " within " + seconds.str() + " s" +
                     printedBy(printed.get()) + "; check that it is a valid Gmsh file (gmsh -check FILE)");
  }
  const bool answered = readAll(fds[0], &end.kind, 1);
  end.complete = answered && end.kind == 'A' && receive(fds[0]);
  if (answered && end.kind != 'A')
    for (char c; readAll(fds[0], &c, 1);) end.message += c;
  ::close(fds[0]);
  while (::waitpid(child, &end.status, 0) < 0 && errno == EINTR) {
  }
  end.printed = printedBy(printed.get());
  return end;
}

}  // namespace

// A child that ends without an answer or an error of its own is started again, after a
// pause, before the file is blamed: such an end can come from the machine (a transient
// failure of the process under load) as well as from the file, and a file that makes Gmsh
// fail does so every time.
void answerFromChild(const std::string& subject, const std::string& doing, double limit,
                     const std::function<void(int)>& work, const std::function<bool(int)>& receive) {
  constexpr int kAttempts = 3;
  ChildEnd end;
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    if (attempt > 0) std::this_thread::sleep_for(std::chrono::milliseconds(500 * attempt));
    end = runChild(subject, doing, limit, work, receive);
    if (end.complete) return;
    if (end.kind == 'I') throw InputError(end.message);
    if (end.kind == 'E') throw Error(end.message);
  }
  const std::string how = WIFSIGNALED(end.status)
                              ? std::string("crashed (") + strsignal(WTERMSIG(end.status)) + ")"
                              : "stopped with exit status " + std::to_string(WEXITSTATUS(end.status));
  throw InputError(subject + ": Gmsh " + how + " while " + doing + end.printed +
                   "; check that it is a valid Gmsh file (gmsh -check FILE)");
}

}  // namespace signorini::detail
