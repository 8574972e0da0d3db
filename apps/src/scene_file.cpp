// The scene file: read whole (bounded in size, a regular file) and parsed as one YAML document.
#include "fsi_app/scene_reader.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

#include "fsi/core/error.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

namespace fsi::app {

std::string read_scene_file(const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  const std::string name = file.string();
  std::error_code ec;
  const fs::file_status st = fs::status(file, ec);
  if (ec || !fs::exists(st)) throw InputError(name + ": cannot open scene file");
  if (fs::is_directory(st)) throw InputError(name + ": is a directory; give a scene file (.yaml)");
  if (!fs::is_regular_file(st))
    throw InputError(name + ": not a regular file (a FIFO, device or socket); give a scene file");
  const std::uintmax_t size = fs::file_size(file, ec);
  if (ec) throw InputError(name + ": cannot open scene file (" + ec.message() + ")");
  if (size > kMaxSceneBytes)
    throw InputError(name + ": " + std::to_string(size) + " bytes; a scene file is at most " +
                     std::to_string(kMaxSceneBytes >> 20) + " MiB");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(name + ": cannot open scene file (" + std::strerror(errno) + ")");
  std::string text;
  text.reserve(static_cast<std::size_t>(size));
  text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad() || text.size() > kMaxSceneBytes) throw InputError(name + ": cannot read scene file");
  return text;
}

namespace {
/// Where each YAML document starts; the content of the documents is not kept.
struct DocumentStarts final : YAML::EventHandler {
  std::vector<YAML::Mark> marks;
  void OnDocumentStart(const YAML::Mark& mark) override { marks.push_back(mark); }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};
} // namespace

std::size_t yaml_documents(const std::string& text, std::size_t at_most) {
  DocumentStarts starts;
  std::istringstream in(text);
  YAML::Parser parser(in);
  while (starts.marks.size() < at_most && parser.HandleNextDocument(starts)) {
  }
  return starts.marks.size();
}

YAML::Node load_scene_yaml(const std::string& text, const std::string& file) {
  // The first document, then whether a second one starts: at most two documents are parsed
  // (YAML::LoadAll runs out of memory on some malformed inputs, making empty documents forever).
  YAML::Node first;
  DocumentStarts starts;
  try {
    first = YAML::Load(text);
    std::istringstream in(text);
    YAML::Parser parser(in);
    while (starts.marks.size() < 2 && parser.HandleNextDocument(starts)) {
    }
  } catch (const YAML::DeepRecursion& e) {
    throw InputError(file + ":" + std::to_string(e.mark.line + 1) + ": yaml: nested too deeply (" +
                     std::to_string(e.depth()) + " levels)");
  } catch (const YAML::ParserException& e) {
    throw InputError(file + ":" + std::to_string(e.mark.line + 1) + ": yaml: " + e.msg);
  }
  if (starts.marks.size() > 1) {
    // The line of the '---' that opens the second document: the last separator line at or
    // before its content (a document of nothing but '---' has no mark).
    const int content = starts.marks[1].line + 1;
    int second = content, line = 1;
    for (std::size_t i = 0; i <= text.size(); ++i) {
      const bool start = i == 0 || text[i - 1] == '\n';
      if (start && text.compare(i, 3, "---") == 0 &&
          (i + 3 >= text.size() || std::isspace(static_cast<unsigned char>(text[i + 3]))) &&
          (content <= 0 || line <= content))
        second = line;
      if (i < text.size() && text[i] == '\n') ++line;
    }
    throw InputError(file + ":" + std::to_string(std::max(second, 1)) +
                     ": yaml: a second YAML document (the scene is the document of line " +
                     std::to_string(std::max(starts.marks[0].line + 1, 1)) +
                     "); a scene file holds one document: remove the '---' and what follows");
  }
  return first;
}

} // namespace fsi::app
