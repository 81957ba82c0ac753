#pragma once
// The command line of the signorini program:
//   signorini FILE.xml [--output DIR] [--summary FILE.json] [--export-qp DIR]
//             [--set "Sublist/name=value" ...] [--help] [--version] [--defaults[=all]]
//   signorini --qp DIR [FILE.xml] [--output DIR] [--summary FILE.json] [--set ...]
#include <string>
#include <vector>

namespace signorini {

struct CommandLine {
  std::string input;
  std::string output;     // overrides Output/directory
  std::string summary;    // also write summary.json here
  std::string exportQp;   // Matrix Market export directory
  std::string qp;         // solve the QP of this directory instead of FILE.xml's problem
  std::vector<std::string> overrides;  // "Path/To/name=value"
  bool help = false, version = false, defaults = false;
  bool allDefaults = false;  // --defaults=all

  // Throws InputError with the usage on a malformed command line.
  static CommandLine parse(int argc, const char* const* argv);
  static std::string usage();
};

}  // namespace signorini
