#include "io/AtomicFile.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "signorini/core/Error.hpp"

namespace signorini::detail {
namespace {

namespace fs = std::filesystem;

// What the system said of the last failed call, or a generic reason where it said nothing.
std::string systemReason() {
  return errno != 0 ? std::strerror(errno) : "the system gave no reason";
}

// Writes and closes with the C library, whose calls report the system's error number at
// once (a stream's buffered writes may fail only when it is destroyed).
std::string writeWhole(const std::string& path, const std::string& text) {
  errno = 0;
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return "cannot open '" + path + "' for writing: " + systemReason();
  errno = 0;
  const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size() && std::fflush(file) == 0;
  const std::string reason = written ? "" : systemReason();
  errno = 0;
  const bool closed = std::fclose(file) == 0;
  if (written && closed) return "";
  return "cannot write '" + path + "': " + (written ? systemReason() : reason);
}

}  // namespace

std::string tryWriteFileAtomically(const std::string& path, const std::string& text) {
  const fs::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) {
    fs::create_directories(target.parent_path(), ec);
    if (ec) return "cannot create directory '" + target.parent_path().string() + "': " + ec.message();
  }
  const std::string temporary = path + ".tmp";
  std::string error = writeWhole(temporary, text);
  if (error.empty()) {
    fs::rename(temporary, target, ec);
    if (ec) error = "cannot rename '" + temporary + "' to '" + path + "': " + ec.message();
  }
  if (!error.empty()) fs::remove(temporary, ec);
  return error;
}

void writeFileAtomically(const std::string& path, const std::string& text) {
  const std::string error = tryWriteFileAtomically(path, text);
  if (!error.empty()) throw OutputError(error);
}

}  // namespace signorini::detail
