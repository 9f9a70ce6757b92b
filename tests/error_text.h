#pragma once
// Shared by the unit tests that check messages: the one line an InputError carries.
#include <string>

#include "marble/core/error.h"

namespace marble::test {

// What `f` throws as an InputError, or "(no error)" when it returns.
template <typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace marble::test
