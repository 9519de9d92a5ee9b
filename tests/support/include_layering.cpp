#include "support/include_layering.h"

#include <algorithm>
#include <fstream>
#include <regex>

namespace iblkit::test {

namespace fs = std::filesystem;

namespace {

bool underFolder(const std::string& path, const std::string& folder) {
  return path.size() > folder.size() && path.compare(0, folder.size(), folder) == 0 && path[folder.size()] == '/';
}

// The layer whose folder is the longest prefix of `path`, or nullptr.
const Layer* layerOf(const std::string& path, const std::vector<Layer>& layers) {
  const Layer* best = nullptr;
  for (const Layer& layer : layers)
    if (underFolder(path, layer.folder) && (!best || layer.folder.size() > best->folder.size())) best = &layer;
  return best;
}

bool skipped(const fs::path& relative) {
  for (const fs::path& part : relative) {
    const std::string name = part.string();
    if (name.rfind("build", 0) == 0 || name == ".git" || name == "out" || name == "assets") return true;
  }
  return false;
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

}  // namespace

std::vector<std::string> layeringViolations(const fs::path& root, const std::vector<Layer>& layers,
                                            const std::vector<std::string>& unchecked) {
  static const std::regex include(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
  std::vector<std::string> violations;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
    const fs::path relative = fs::relative(it->path(), root);
    if (it->is_directory()) {
      if (skipped(relative)) it.disable_recursion_pending();
      continue;
    }
    const std::string extension = relative.extension().string();
    if (extension != ".h" && extension != ".cpp" && extension != ".cc") continue;
    const std::string file = relative.generic_string();
    if (std::any_of(unchecked.begin(), unchecked.end(), [&](const std::string& f) { return underFolder(file, f); }))
      continue;
    const Layer* layer = layerOf(file, layers);
    if (!layer) {
      violations.push_back(file + ": in no layer");
      continue;
    }
    std::ifstream stream(it->path());
    int lineNumber = 0;
    for (std::string line; std::getline(stream, line);) {
      ++lineNumber;
      std::smatch match;
      if (!std::regex_search(line, match, include)) continue;
      const std::string target = match[2];
      const std::string where = file + ":" + std::to_string(lineNumber) + ": includes ";
      if (match[1] == "<") {
        for (const std::string& prefix : layer->forbiddenSystem)
          if (target.rfind(prefix, 0) == 0)
            violations.push_back(where + "<" + target + "> (" + layer->folder + " must not use " + prefix + ")");
        continue;
      }
      const Layer* included = layerOf(target, layers);
      const bool allowed = included && (included == layer || std::find(layer->mayInclude.begin(), layer->mayInclude.end(),
                                                                       included->folder) != layer->mayInclude.end());
      // A quoted include with no folder names a file beside the includer.
      if (!allowed && target.find('/') != std::string::npos)
        violations.push_back(where + "\"" + target + "\" (" + layer->folder + " may include only " +
                             (layer->mayInclude.empty() ? "its own headers" : joined(layer->mayInclude)) + ")");
    }
  }
  std::sort(violations.begin(), violations.end());
  return violations;
}

}  // namespace iblkit::test
