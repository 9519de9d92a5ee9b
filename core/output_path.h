#pragma once
// Outputs that never overwrite or delete what the program did not write. Each program declares,
// after parsing and before it writes anything, the files and folders it reads and the outputs it
// will write (cli/program.h runs it through checkOutputs):
//   - an output that is an input (the same file by device and inode, through any path or link),
//     lies inside an input folder, or (a folder output the program replaces whole) holds an
//     input, is refused;
//   - an output file must be a regular file or a new path, an output folder a folder or a new
//     path: `-o /dev/full` is refused, not replaced;
//   - an existing, non-empty output folder must be an iblkit output of the same kind (it holds
//     the kind's marker file), unless the program was given --force.
// Every refusal is an Error naming the output and the reason, e.g.
//   "out.exr: output is the same file as the input scene.exr"
//   "out: exists and is not an iblkit bake folder (use --force to replace it)".

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace iblkit {

// The kind of an output folder: what it is called and the files that mark one (any of them).
struct OutputFolderKind {
  std::string noun;                  // "iblkit bake folder"
  std::vector<std::string> markers;  // "bake.json"
};

struct OutputFolder {
  OutputFolder(std::filesystem::path path, OutputFolderKind kind, bool replaced = true)
      : path(std::move(path)), kind(std::move(kind)), replaced(replaced) {}
  std::filesystem::path path;
  OutputFolderKind kind;
  bool replaced;  // the program replaces the whole folder (else: writes into it)
};

// Checks what a program reads (`inputs`: files or folders) against what it will write; empty
// paths are ignored. `force` (--force): an existing folder of another kind may be replaced.
// Throws Error for the first output that breaks a rule above, or when two outputs share a path.
void checkOutputs(const std::vector<std::filesystem::path>& inputs,
                  const std::vector<std::filesystem::path>& outputFiles,
                  const std::vector<OutputFolder>& outputFolders = {}, bool force = false);

}  // namespace iblkit
