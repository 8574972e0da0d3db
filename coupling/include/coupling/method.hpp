#pragma once
// What the registry builds by name (registry.hpp): an acceleration, a predictor or a convergence
// measure. It answers to the name it was registered under.
#include <string_view>

namespace fsi::coupling {

class Method {
public:
  explicit Method(std::string_view name) : name_(name) {}
  virtual ~Method() = default;
  std::string_view name() const { return name_; }

private:
  std::string_view name_; // a string literal
};

} // namespace fsi::coupling
