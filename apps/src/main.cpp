#include "fsi_app/version.hpp"
#include <iostream>

int main() { std::cout << "fsi " << fsi::app::version() << "\n"; }
