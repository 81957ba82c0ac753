// libFuzzer target: any bytes as a Gmsh .msh file, read through the Gmsh SDK into a
// simplex mesh with its boundary tags. Gmsh runs in the child process readGmshMesh starts,
// so its own code adds no coverage here: what is checked is the contract, a mesh or an
// InputError whatever Gmsh does with the file.
#include <unistd.h>

#include <cstddef>
#include <cstdio>
#include <cstdint>
#include <fstream>
#include <string>

#include "fe/GmshMesh.hpp"
#include "fuzz/FuzzInput.hpp"

namespace {

// The file every input is written to in turn, removed when the fuzzer exits.
struct InputFile {
  std::string path = "/tmp/signorini-fuzz-" + std::to_string(getpid()) + ".msh";
  ~InputFile() { std::remove(path.c_str()); }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const InputFile file;
  std::ofstream(file.path, std::ios::binary)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  signorini::fuzz::expectInputErrorOrNothing([&] { signorini::readGmshMesh(file.path); });
  return 0;
}
