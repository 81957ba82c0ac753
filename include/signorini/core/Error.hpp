#pragma once
/// \file
/// The one exception hierarchy of Signorini. main() catches Error, prints its message once
/// on rank 0 and ends every rank with a non-zero code.
#include <stdexcept>
#include <string>

namespace signorini {

/// Base of every error Signorini throws on purpose.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The user's input is wrong (XML, mesh file, parameter value): the message says what to fix.
struct InputError : Error {
  using Error::Error;
};

/// Writing a result failed for a reason of the system (a full disk, a file size limit, a
/// directory removed or made read-only during the run): the message names the file and says
/// what the system said.
struct OutputError : Error {
  using Error::Error;
};

/// A numerical method could not do its job (breakdown, non-convergence where it is fatal).
struct SolverError : Error {
  using Error::Error;
};

}  // namespace signorini
