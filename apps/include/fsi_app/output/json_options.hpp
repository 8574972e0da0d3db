#pragma once
// Writes the options a component declares (fsi/core/options.hpp) as one run.json object, each
// key with its resolved value: what the run used, defaults included.
#include "fsi/core/options.hpp"
#include "fsi_app/output/json.hpp"

namespace fsi::app {

class JsonOptions final : public OptionVisitor {
public:
  JsonObject object;
  void name(const std::string& key, std::string& value, const std::vector<std::string>&,
            const std::string&) override {
    object.add(key, value);
  }
  void real(const std::string& key, double& value, const Range&, const std::string&) override {
    object.add(key, value);
  }
  void integer(const std::string& key, int& value, const Range&, const std::string&) override {
    object.add(key, value);
  }
  void flag(const std::string& key, bool& value, const std::string&) override {
    object.add(key, value);
  }
};

} // namespace fsi::app
