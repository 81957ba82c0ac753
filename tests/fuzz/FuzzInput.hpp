#pragma once
// Shared by the libFuzzer targets: the input as text, and the contract every input path
// keeps: a result, or an InputError (one line for the user); any other exception or a crash
// is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "signorini/core/Error.hpp"

namespace signorini::fuzz {

inline std::string text(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

template <class F>
void expectInputErrorOrNothing(F&& f) {
  try {
    f();
  } catch (const InputError&) {
  }
}

}  // namespace signorini::fuzz
