#pragma once
// The message of the InputError a callable throws, for tests that check what an error says.
#include <gtest/gtest.h>

#include <string>

#include "harness/core/error.hpp"

namespace vsgl::test {

// The message of the InputError `f` throws ("" when it throws none, which fails the test).
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

}  // namespace vsgl::test
