// libFuzzer target: any bytes as a --set "Sublist/name=value" argument, applied to an empty
// input and validated.
#include <cstddef>
#include <cstdint>

#include <Teuchos_ParameterList.hpp>

#include "core/ParameterValidation.hpp"
#include "driver/Application.hpp"
#include "fuzz/FuzzInput.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Teuchos::ParameterList valid = signorini::validTopLevelParameters();
  signorini::fuzz::expectInputErrorOrNothing([&] {
    Teuchos::ParameterList user;
    signorini::applyOverride(user, signorini::fuzz::text(data, size), valid);
    signorini::validatedParameters(user, valid, "");
  });
  return 0;
}
