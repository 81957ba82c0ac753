#include "driver/CommandLine.hpp"

#include "signorini/core/Error.hpp"

namespace signorini {

std::string CommandLine::usage() {
  return "usage: signorini FILE.xml [--output DIR] [--summary FILE.json] [--export-qp DIR]\n"
         "                 [--set \"Sublist/name=value\" ...] [--help] [--version] [--defaults[=all]]\n"
         "       signorini --qp DIR [FILE.xml] [--output DIR] [--summary FILE.json] [--set ...]\n"
         "  FILE.xml      parameter list with the sublists Problem, Solver and Output\n"
         "                (xml/defaults.xml documents every parameter)\n"
         "  --output      directory for solution.pvtu, summary.json, history.csv\n"
         "  --summary     also write the JSON summary to this file\n"
         "  --export-qp   write Q, b, A, d and the node coordinates in Matrix Market format\n"
         "                (doc/qp-format.md)\n"
         "  --qp          solve the QP that DIR holds in that format, with FILE.xml's Solver and\n"
         "                Output lists if given (its Problem list is not used)\n"
         "  --set         override one parameter, e.g. --set \"Solver/method=primal\"\n"
         "  --defaults    print the common parameters with their defaults and documentation (XML);\n"
         "                --defaults=all every parameter, the expert ones too\n"
         "exit status: 0 converged, 1 the solver did not converge (summary.json says why),\n"
         "             2 bad input (one line names the parameter or file), 3 internal error,\n"
         "             4 the results could not be written (the file and the system's reason)\n";
}

CommandLine CommandLine::parse(int argc, const char* const* argv) {
  CommandLine cl;
  std::string inlineValue;  // of "--flag=value"
  bool hasInlineValue = false;
  auto value = [&](int& i, const std::string& flag) -> std::string {
    if (hasInlineValue) return inlineValue;
    if (i + 1 >= argc) throw InputError(flag + " needs a value\n" + usage());
    return argv[++i];
  };
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    // The valued options also take their value after "=", as in --output=DIR.
    const std::size_t equals = arg.find('=');
    hasInlineValue = arg.rfind("--", 0) == 0 && equals != std::string::npos && arg != "--defaults=all";
    if (hasInlineValue) {
      inlineValue = arg.substr(equals + 1);
      arg.resize(equals);
      if (arg == "--help" || arg == "--defaults" || arg == "--version")
        throw InputError(arg + " takes no value\n" + usage());
    }
    if (arg == "--help" || arg == "-h") {
      cl.help = true;
    } else if (arg == "--defaults" || arg == "--defaults=all") {
      cl.defaults = true;
      cl.allDefaults = arg == "--defaults=all";
    } else if (arg == "--version") {
      cl.version = true;
    } else if (arg == "--output") {
      cl.output = value(i, arg);
    } else if (arg == "--summary") {
      cl.summary = value(i, arg);
    } else if (arg == "--export-qp") {
      cl.exportQp = value(i, arg);
    } else if (arg == "--qp") {
      cl.qp = value(i, arg);
    } else if (arg == "--set") {
      cl.overrides.push_back(value(i, arg));
    } else if (!arg.empty() && arg[0] == '-') {
      throw InputError("unknown option " + arg + "\n" + usage());
    } else if (cl.input.empty()) {
      cl.input = arg;
    } else {
      throw InputError("more than one input file (" + cl.input + ", " + arg + ")\n" + usage());
    }
  }
  if (cl.input.empty() && cl.qp.empty() && !cl.help && !cl.version && !cl.defaults)
    throw InputError("no input file\n" + usage());
  if (!cl.qp.empty() && !cl.exportQp.empty()) throw InputError("--qp and --export-qp exclude each other\n" + usage());
  return cl;
}

}  // namespace signorini
