// Checking that a call throws one error type with one exact message.
#pragma once

#include <gtest/gtest.h>

#include <string>

namespace envcrust {

/// `call()` throws `Error` whose what() is `message`, word for word.
template <class Error, class Call>
void expect_refusal(Call&& call, const std::string& message) {
  try {
    call();
    ADD_FAILURE() << "no exception; expected: " << message;
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

}  // namespace envcrust
