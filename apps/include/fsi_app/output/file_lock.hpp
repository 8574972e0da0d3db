#pragma once
// Why an HDF5 file would not open. HDF5 (1.10 and later) takes a lock on each file it opens
// (flock: shared to read, exclusive to write) and fails the open when another process holds a
// lock in the way (a viewer, h5py, another run), saying no more than that the open failed.
#include <filesystem>
#include <string>

namespace fsi::app {

/// ": FILE is locked by another process (...)" when another process holds a lock on `file` that
/// keeps it from being opened for writing (`write`) or for reading; "" otherwise (no such file,
/// or no lock in the way).
std::string lock_note(const std::filesystem::path& file, bool write);

} // namespace fsi::app
