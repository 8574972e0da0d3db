#pragma once
// The message of the InputError a call throws, for tests that compare whole messages.
#include <functional>
#include <string>

#include "fsi/core/error.hpp"

/// The InputError's text, or "(no error)" when `f` returns.
inline std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const fsi::InputError& e) {
    return e.what();
  }
  return "(no error)";
}
