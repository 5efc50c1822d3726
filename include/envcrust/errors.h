// The exception hierarchy of the library: every stage throws only these.
#pragma once

#include <stdexcept>
#include <string>

namespace envcrust {

/// Base of every envcrust error; what() is a one-line message meant for the user.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The input data is malformed (non-finite coordinates, bad indices, wrong columns, ...).
class InvalidInput : public Error {
 public:
  using Error::Error;
};

/// The input is well formed but geometrically degenerate (too few points, all coplanar, ...).
class DegenerateInput : public Error {
 public:
  using Error::Error;
};

/// An options field has a value outside its valid range; the message names field and value.
class InvalidOptions : public Error {
 public:
  using Error::Error;
};

/// A numerical computation failed although the input was valid.
class NumericalFailure : public Error {
 public:
  using Error::Error;
};

/// Reading or writing a file failed; the message names the file (and line, when known).
class IoError : public Error {
 public:
  using Error::Error;
};

}  // namespace envcrust
