#include "fsi_app/output/text_file.hpp"

#include "fsi/core/error.hpp"

#include <fstream>
#include <string>

namespace fsi::app {

void keep_lines(const std::filesystem::path& file, std::size_t lines) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": missing (a restart continues the files of its run)");
  std::string kept, line;
  std::size_t count = 0;
  while (count < lines && std::getline(in, line)) kept += line + '\n', ++count;
  if (count < lines)
    throw InputError(file.string() + ": has " + std::to_string(count) +
                     " lines, the checkpoint needs " + std::to_string(lines));
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << kept;
    if (!out) throw RunError("output: " + tmp.string() + ": cannot write");
  }
  std::filesystem::rename(tmp, file);
}

} // namespace fsi::app
