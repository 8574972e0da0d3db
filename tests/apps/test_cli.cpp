// Command-line behaviour: help, version, and exit status 2 for every malformed command line.
#include "fsi_app/cli.hpp"

#include <catch2/catch.hpp>
#include <sstream>

using fsi::app::run_cli;

namespace {
int status_of(std::vector<std::string> args, std::string* err_text = nullptr) {
  std::ostringstream out, err;
  const int status = run_cli(args, out, err, false);
  if (err_text) *err_text = err.str();
  return status;
}
} // namespace

TEST_CASE("apps: help and version exit 0", "[apps][cli]") {
  std::ostringstream out, err;
  CHECK(run_cli({"--help"}, out, err, false) == 0);
  CHECK(out.str().find("fsi run SCENE --out DIR") != std::string::npos);
  out.str("");
  CHECK(run_cli({"--version"}, out, err, false) == 0);
  CHECK(out.str().rfind("fsi 0.", 0) == 0);
}

TEST_CASE("apps: malformed command lines exit 2 with one line", "[apps][cli]") {
  const std::string scene = FSI_TEST_DATA "/valid_structure.yaml";
  std::string err;
  CHECK(status_of({}, &err) == 2);
  CHECK(err == "fsi: missing command (see fsi --help)\n");
  CHECK(status_of({"frobnicate"}, &err) == 2);
  CHECK(err.find("unknown command 'frobnicate'") != std::string::npos);
  CHECK(status_of({"run", scene}, &err) == 2);
  CHECK(err == "fsi run: missing --out DIR\n");
  CHECK(status_of({"check"}, &err) == 2);
  CHECK(status_of({"check", scene, "--bogus"}, &err) == 2);
  CHECK(err.find("unknown option '--bogus'") != std::string::npos);
  CHECK(status_of({"run", scene, "--out", "x", "--threads", "zero"}, &err) == 2);
  CHECK(status_of({"check", "/nonexistent/scene.yaml"}, &err) == 2);
  CHECK(err == "/nonexistent/scene.yaml: cannot open scene file\n");
}
