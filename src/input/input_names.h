// Naming the input at the head of the stage's messages, as io names a file
// (InputOptions::name, GivenBoundary::name).
#pragma once

#include "envcrust/errors.h"

#include <string>

namespace envcrust::input {

/// "scan.xyz: what"; `what` alone when `name` is empty or `what` starts with it already.
std::string named(const std::string& name, const std::string& what);

/// Runs `step`, naming `name` at the head of the InvalidInput, DegenerateInput or
/// NumericalFailure it throws (a library step that knows no file, e.g. the coordinate checks).
template <class Step>
auto naming(const std::string& name, Step&& step) {
  try {
    return step();
  } catch (const DegenerateInput& e) {
    throw DegenerateInput(named(name, e.what()));
  } catch (const NumericalFailure& e) {
    throw NumericalFailure(named(name, e.what()));
  } catch (const InvalidInput& e) {
    throw InvalidInput(named(name, e.what()));
  }
}

}  // namespace envcrust::input
