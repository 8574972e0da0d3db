#pragma once
// The one entry into Catch2's implementation (compiled once, in catch_session.cpp, for every test
// program): Catch2 v2 declares Catch::Session only with its implementation, so a main of its own
// (the MPI tests', the CalculiX comparison's) runs the tests through this.

namespace fsi_test {

/// Runs the test cases selected by the command line, as Catch::Session().run(argc, argv); with
/// `output_file` set, the report goes there instead of stdout. Returns the number of failed
/// test cases (at most 255).
int run_catch_session(int argc, char* argv[], const char* output_file = nullptr);

} // namespace fsi_test
