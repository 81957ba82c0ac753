#pragma once
// Gmsh runs in a forked child process: a file that makes Gmsh crash, abort or hang ends the
// child, not the MPI rank, and is reported as an error of the file. The child answers through
// a pipe: 'A' and the answer's data, or 'I' (an input error) or 'E' (any other error) and the
// message.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace signorini::detail {

// Writes `size` bytes (in the child: ends it if the parent is gone).
void writeAll(int fd, const void* data, std::size_t size);
// Reads `size` bytes; false at the end of the stream.
bool readAll(int fd, void* data, std::size_t size);

template <class T>
void sendArray(int fd, const std::vector<T>& values) {
  const std::uint64_t count = values.size();
  writeAll(fd, &count, sizeof count);
  writeAll(fd, values.data(), count * sizeof(T));
}

template <class T>
bool receiveArray(int fd, std::vector<T>& values) {
  std::uint64_t count = 0;
  if (!readAll(fd, &count, sizeof count)) return false;
  values.resize(count);
  return readAll(fd, values.data(), count * sizeof(T));
}

// Runs `work` in a forked child and `receive` on its answer ('A' and the data); the child's
// errors, crash or silence past `limit` seconds (negative: none) are thrown here, naming
// the file (`subject`, e.g. "Gmsh mesh file 'x.msh'") and what the child was `doing` with it.
// A child that crashes or exits without answering is run twice more before that is thrown.
void answerFromChild(const std::string& subject, const std::string& doing, double limit,
                     const std::function<void(int)>& work, const std::function<bool(int)>& receive);

}  // namespace signorini::detail
