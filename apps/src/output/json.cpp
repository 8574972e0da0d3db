#include "fsi_app/output/json.hpp"

#include <cmath>
#include <cstdio>
#include <iomanip>

namespace fsi::app {

std::string JsonObject::quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
    case '"':
      out += "\\\"";
      break;
    case '\\':
      out += "\\\\";
      break;
    case '\n':
      out += "\\n";
      break;
    case '\t':
      out += "\\t";
      break;
    default:
      if (static_cast<unsigned char>(c) < 0x20) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04x", c);
        out += buf;
      } else {
        out += c;
      }
    }
  }
  return out + "\"";
}

std::string JsonObject::str() const {
  std::string out(1, '{');
  out.append(body_.str());
  out.push_back('}');
  return out;
}

void JsonObject::key(const std::string& k) {
  if (!first_) body_ << ", ";
  first_ = false;
  body_ << quote(k) << ": ";
}

JsonObject& JsonObject::add(const std::string& k, const std::string& value) {
  key(k);
  body_ << quote(value);
  return *this;
}

JsonObject& JsonObject::add(const std::string& k, double value) {
  key(k);
  if (std::isfinite(value))
    body_ << std::setprecision(12) << value;
  else
    body_ << "null";
  return *this;
}

JsonObject& JsonObject::add(const std::string& k, long long value) {
  key(k);
  body_ << value;
  return *this;
}

JsonObject& JsonObject::add(const std::string& k, bool value) {
  key(k);
  body_ << (value ? "true" : "false");
  return *this;
}

JsonObject& JsonObject::add(const std::string& k, const JsonObject& object) {
  return add_raw(k, object.str());
}

JsonObject& JsonObject::add_raw(const std::string& k, const std::string& json) {
  key(k);
  body_ << json;
  return *this;
}

} // namespace fsi::app
