// The main of every test program that has no main of its own (Catch2's default main).
#include "catch_session.hpp"

int main(int argc, char* argv[]) {
  return fsi_test::run_catch_session(argc, argv);
}
