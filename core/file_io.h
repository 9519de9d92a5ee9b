#pragma once
// Whole-file input and output with the project's error conventions: a file that cannot be read
// throws Error("<file>: cannot open: <system reason>"), and writers never leave a partial file
// under the final name (they write a unique "<file>.tmp-XXXXXX" and rename it, which POSIX makes
// atomic; temporary_files.h removes it on an interrupt), and never replace what is not a regular
// file (a device node, a FIFO, a folder).

#include <filesystem>
#include <functional>
#include <vector>

namespace iblkit {

// Every byte of `file`: readInputFile(file, kMaxBinaryInputBytes) (input_file.h), so a file that
// is not regular (a FIFO, /dev/zero) or is over 4 GiB is refused. Throws Error for a file that
// cannot be opened or read, and for an empty (0-byte) file, which no format we read accepts.
std::vector<char> readFileBytes(const std::filesystem::path& file);

// Throws Error("<file>: exists and is not a regular file (not replaced)") or
// Error("<file>: is a folder") when `file` (followed through links) exists and is not a regular
// file; nothing for a new path.
void refuseNonRegularOutput(const std::filesystem::path& file);

// Calls write(temporary) with temporary a new, empty "<file>.tmp-XXXXXX" (createTemporaryFile),
// then renames it to `file`. If `write` throws, the temporary is removed and the exception
// propagates; `file` is left untouched. Throws Error("<file>: exists and is not a regular file
// (not replaced)") or Error("<file>: is a folder") (refuseNonRegularOutput), checked before
// writing and again just before the rename.
void writeAtomically(const std::filesystem::path& file,
                     const std::function<void(const std::filesystem::path& temporary)>& write);

}  // namespace iblkit
