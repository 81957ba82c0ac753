#pragma once
// The XML-configured run behind the signorini program: read and validate the parameter
// list (rank 0 reads, all ranks parse the broadcast text), build and assemble the problem,
// solve it with the iteration log on rank 0, write the outputs.
#include <ostream>
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "driver/CommandLine.hpp"
#include "signorini/core/TpetraTypes.hpp"
#include "signorini/solver/SolveResult.hpp"

namespace signorini {

// The top level: sublists "Problem", "Solver" and "Output" with every default and doc.
Teuchos::ParameterList validTopLevelParameters();

// The parameters with their defaults and documentation as an XML parameter list: the
// common ones (signorini --defaults), or all of them, the expert ones (isExpert(), their
// documentation headed "Expert: ") included (signorini --defaults=all; xml/defaults.xml).
std::string defaultsXml(bool all = false);

// Reads an XML parameter file on rank 0 and broadcasts it; throws InputError on every rank
// if it cannot be read or parsed.
Teuchos::ParameterList readParameterFile(const std::string& path, const Comm& comm);

// Parses the text of an XML parameter list; throws InputError naming `path` if it is not one.
Teuchos::ParameterList parseParameterXml(const std::string& text, const std::string& path);

// Applies "Path/To/name=value": the type is taken from the valid list where the parameter
// is known, else from the existing entry, else inferred (int, double, bool, string).
void applyOverride(Teuchos::ParameterList& list, const std::string& assignment,
                   const Teuchos::ParameterList& valid);

// Runs the whole job; returns the solver result (also written as the command line asks).
SolveResult runApplication(const CommandLine& commandLine, const RCP<const Comm>& comm, std::ostream& out);

}  // namespace signorini
