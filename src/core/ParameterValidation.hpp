#pragma once
// Validation of user parameter lists against the valid list a class publishes
// (Belos' getValidParameters convention): unknown names get a "did you mean" hint, wrong
// types and out-of-range values a message with the parameter's full path.
#include <string>

#include <Teuchos_ParameterList.hpp>

namespace signorini {

// Returns `valid` with the user's values put in, after checking them:
// - every user name must exist in `valid`, except inside sublists named "MueLu", "Belos"
//   or "Ifpack2", which are passed through to those packages unchanged;
// - a valid sublist holding a sublist named "<name>" accepts any number of user sublists
//   of any name, each validated against that template (e.g. one per boundary);
// - an int where a double is expected is accepted and converted;
// - validators attached to valid entries (ranges, string choices) are applied.
// `path` prefixes messages, e.g. "Problem". Throws InputError.
Teuchos::ParameterList validatedParameters(const Teuchos::ParameterList& user,
                                           const Teuchos::ParameterList& valid,
                                           const std::string& path);

// Name of the template sublist for user-named entries.
inline const char* kAnyNameSublist = "<name>";

// The candidate closest to `name` by edit distance, or "" if none is reasonably close.
std::string closestName(const std::string& name, const Teuchos::ParameterList& valid);

}  // namespace signorini
