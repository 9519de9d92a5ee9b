#pragma once
// An output folder that appears whole or not at all: the baker writes everything into a fresh
// sibling "<folder>.tmp-XXXXXX" and renames it to <folder> only once every file is written, so a
// failed or interrupted bake never leaves a partial folder under the final name, and an existing
// folder from an earlier bake is replaced only after success.

#include <filesystem>
#include <functional>

namespace iblkit {

// Creates "<directory>.tmp-XXXXXX" (mkdtemp, beside `directory`; missing parent folders are
// created), calls fill(temporary), then puts the temporary folder in place of `directory`: an
// existing `directory` is first renamed aside to "<directory>.old-XXXXXX" and deleted once the new
// one is in place (restored if that rename fails). If fill throws, the temporary folder is deleted,
// `directory` is untouched and the exception propagates. Throws Error("<directory>: ...") when
// `directory` exists but is not a folder, or a folder cannot be created or renamed.
void writeDirectoryAtomically(const std::filesystem::path& directory,
                              const std::function<void(const std::filesystem::path& temporary)>& fill);

}  // namespace iblkit
