// Inputs the fuzzers found (tests/data/fuzz_regressions/TARGET/, see scripts/fuzz): each must be
// refused with a one-line InputError naming the file and line (or the --set argument), or parse;
// any other exception, a crash or a sanitizer report fails.
#include "inputs.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> regressions(const std::string& target) {
  std::vector<fs::path> files;
  for (const auto& entry :
       fs::directory_iterator(FSI_SOURCE_DIR "/tests/data/fuzz_regressions/" + target))
    files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string contents(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

template <class Parse> void check_all(const std::string& target, Parse parse) {
  const auto files = regressions(target);
  CHECK(!files.empty());
  for (const auto& file : files) {
    INFO(file.string());
    std::string message;
    REQUIRE_NOTHROW(message = parse(contents(file)));
    INFO(message);
    CHECK(fsi::fuzz::well_formed(target, message));
    if (std::getenv("FSI_SHOW_MESSAGES")) std::cout << file.filename() << ": " << message << "\n";
  }
}

} // namespace

TEST_CASE("apps: fuzz regressions: scene files", "[apps][fuzz]") {
  check_all("scene", fsi::fuzz::scene_input);
}

TEST_CASE("apps: fuzz regressions: --set overrides", "[apps][fuzz]") {
  check_all("override", fsi::fuzz::override_input);
}

TEST_CASE("apps: fuzz regressions: Gmsh files", "[apps][fuzz]") {
  check_all("gmsh", fsi::fuzz::gmsh_input);
}
