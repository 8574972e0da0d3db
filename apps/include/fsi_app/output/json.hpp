#pragma once
// A minimal JSON object writer for run.json: keys in insertion order, numbers, strings, nesting.
#include <sstream>
#include <string>

namespace fsi::app {

class JsonObject {
public:
  JsonObject& add(const std::string& key, const std::string& value);
  JsonObject& add(const std::string& key, const char* value) {
    return add(key, std::string(value));
  }
  JsonObject& add(const std::string& key, double value);
  JsonObject& add(const std::string& key, long long value);
  JsonObject& add(const std::string& key, int value) {
    return add(key, static_cast<long long>(value));
  }
  JsonObject& add(const std::string& key, bool value);
  JsonObject& add(const std::string& key, const JsonObject& object);
  JsonObject& add_raw(const std::string& key, const std::string& json);
  std::string str() const;

  static std::string quote(const std::string& s);

private:
  void key(const std::string& k);
  std::ostringstream body_;
  bool first_ = true;
};

} // namespace fsi::app
