// libFuzzer target: any bytes as the XML input file. Reading and validating must end in a
// result or in an InputError (what the program reports as one line), never in a crash or in
// another exception.
#include <cstddef>
#include <cstdint>
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "core/ParameterValidation.hpp"
#include "driver/Application.hpp"
#include "fuzz/FuzzInput.hpp"
#include "signorini/core/Error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Teuchos::ParameterList valid = signorini::validTopLevelParameters();
  signorini::fuzz::expectInputErrorOrNothing([&] {
    const Teuchos::ParameterList user = signorini::parseParameterXml(signorini::fuzz::text(data, size), "fuzz.xml");
    signorini::validatedParameters(user, valid, "");
  });
  return 0;
}
