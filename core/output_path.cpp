#include "core/output_path.h"

#include <sys/stat.h>

#include <system_error>

#include "core/error.h"
#include "core/file_io.h"

namespace iblkit {

namespace fs = std::filesystem;

namespace {

// "out/" names the folder "out".
fs::path withoutTrailingSlash(const fs::path& path) {
  fs::path normal = path.lexically_normal();
  if (normal.filename().empty() && normal.has_parent_path()) normal = normal.parent_path();
  return normal;
}

// The absolute path with links resolved as far as it exists.
fs::path resolved(const fs::path& path) {
  std::error_code error;
  fs::path result = fs::weakly_canonical(fs::absolute(path, error), error);
  return error ? fs::absolute(path).lexically_normal() : withoutTrailingSlash(result);
}

// Whether `inner` is `outer` or lies inside it (both resolved).
bool isWithin(const fs::path& inner, const fs::path& outer) {
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i)
    if (i == inner.end() || *i != *o) return false;
  return true;
}

bool sameFile(const struct stat& a, const struct stat& b) {
  return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

struct Input {
  fs::path path, where;  // as given, resolved
  bool exists, folder;
  struct stat info;
};

std::vector<Input> describeInputs(const std::vector<fs::path>& paths) {
  std::vector<Input> inputs;
  for (const fs::path& path : paths) {
    if (path.empty()) continue;
    Input input{path, resolved(path), false, false, {}};
    input.exists = ::stat(path.c_str(), &input.info) == 0;
    input.folder = input.exists && S_ISDIR(input.info.st_mode);
    inputs.push_back(input);
  }
  return inputs;
}

void checkFile(const fs::path& output, const std::vector<Input>& inputs) {
  refuseNonRegularOutput(output);  // the rule writeAtomically checks again before its rename
  struct stat info {};
  const bool exists = ::stat(output.c_str(), &info) == 0;
  const fs::path where = resolved(output);
  for (const Input& input : inputs) {
    if (exists && input.exists && sameFile(info, input.info))
      fail(output, "output is the same file as the input " + input.path.string());
    if (input.folder && isWithin(where, input.where))
      fail(output, "output is inside the input folder " + input.path.string());
  }
}

bool isEmptyFolder(const fs::path& folder) {
  std::error_code error;
  return fs::directory_iterator(folder, error) == fs::directory_iterator();
}

void checkFolder(const OutputFolder& output, const std::vector<Input>& inputs, bool force) {
  const fs::path folder = withoutTrailingSlash(output.path);
  struct stat info {};
  const bool exists = ::stat(folder.c_str(), &info) == 0;
  if (exists && !S_ISDIR(info.st_mode)) fail(folder, "exists and is not a folder");
  const fs::path where = resolved(folder);
  for (const Input& input : inputs) {
    if (exists && input.exists && sameFile(info, input.info))
      fail(folder, "output folder is the input " + input.path.string());
    if (input.folder && isWithin(where, input.where))
      fail(folder, "output folder is inside the input folder " + input.path.string());
    if (output.replaced && isWithin(input.where, where))
      fail(folder, "output folder holds the input " + input.path.string() + " (it would be deleted)");
  }
  if (!exists || force || isEmptyFolder(folder)) return;
  std::error_code error;
  for (const std::string& marker : output.kind.markers)
    if (fs::is_regular_file(folder / marker, error)) return;
  fail(folder, "exists and is not an " + output.kind.noun + " (use --force to replace it)");
}

}  // namespace

void checkOutputs(const std::vector<fs::path>& inputPaths, const std::vector<fs::path>& outputFiles,
                  const std::vector<OutputFolder>& outputFolders, bool force) {
  const std::vector<Input> inputs = describeInputs(inputPaths);
  std::vector<fs::path> seen;
  const auto distinct = [&](const fs::path& output) {
    const fs::path where = resolved(output);
    for (const fs::path& other : seen)
      if (other == where) fail(output, "given as two outputs");
    seen.push_back(where);
  };
  for (const OutputFolder& folder : outputFolders) {
    if (folder.path.empty()) continue;
    checkFolder(folder, inputs, force);
    distinct(folder.path);
  }
  for (const fs::path& file : outputFiles) {
    if (file.empty()) continue;
    checkFile(file, inputs);
    distinct(file);
    for (const OutputFolder& folder : outputFolders)
      if (!folder.path.empty() && folder.replaced && isWithin(resolved(file), resolved(folder.path)))
        fail(file, "output is inside the output folder " + folder.path.string() + ", which is replaced");
  }
}

}  // namespace iblkit
