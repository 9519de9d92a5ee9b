#pragma once
// The temporaries of the atomic writes (file_io.h, output_directory.h) that an interrupt must not
// leave behind. Every temporary file and folder is made here, with a unique name, and registered
// until it is renamed into place or removed; installInterruptCleanup (runProgram calls it) makes
// SIGINT and SIGTERM remove every registered temporary, stop the registered child processes and
// then end the program by the same signal. An interrupted program so leaves each output either
// as it was or complete, never partial.

#include <sys/types.h>

#include <filesystem>
#include <functional>

namespace iblkit {

// A new, empty, registered file "<target>.tmp-XXXXXX" beside `target` (mkstemp; the permissions
// of a file created under the umask). Throws Error("<target>: cannot create a temporary file
// beside it: <reason>").
std::filesystem::path createTemporaryFile(const std::filesystem::path& target);

// A new, empty, registered folder "<target><suffix>XXXXXX" beside `target` (mkdtemp). Throws
// Error("<target>: cannot create a folder beside it: <reason>").
std::filesystem::path createTemporaryFolder(const std::filesystem::path& target, const char* suffix);

// Registers `path` as a temporary an interrupt removes; with `restoreTo`, an interrupt instead
// renames it back to `restoreTo` when nothing is there (a previous output moved aside).
void registerTemporary(const std::filesystem::path& path, const std::filesystem::path& restoreTo = {});
// Forgets `path` (it was renamed into place).
void unregisterTemporary(const std::filesystem::path& path);
// Removes `path` (a file or a whole folder) and forgets it.
void discardTemporary(const std::filesystem::path& path);

// Runs `change` while no interrupt can clean up: a rename into place and the registrations that
// go with it happen together (the cleanup waits for `change` to return).
void withTemporariesLocked(const std::function<void()>& change);

// A child process an interrupt stops first (SIGTERM, then SIGKILL after a few seconds), so that
// it does not write into a temporary folder being removed.
void registerChildProcess(pid_t pid);
void unregisterChildProcess(pid_t pid);

// Blocks SIGINT and SIGTERM in the calling thread (and so in every thread it starts later) and
// starts the thread that, on either signal, cleans up as above and ends the program by that
// signal. Call before any other thread starts; later calls do nothing.
void installInterruptCleanup();

}  // namespace iblkit
