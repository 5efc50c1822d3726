// Naming the input at the head of the stage's messages.
#include "input_names.h"

namespace envcrust::input {

std::string named(const std::string& name, const std::string& what) {
  if (name.empty() || what.rfind(name + ":", 0) == 0) return what;
  return name + ": " + what;
}

}  // namespace envcrust::input
