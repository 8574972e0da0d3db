#pragma once
// The folder of the apps tests' scenes and meshes (tests/apps/data/), with its trailing slash.
#include <string>

namespace fsi::app::test {

inline const std::string data_dir = FSI_TEST_DATA "/";

} // namespace fsi::app::test
