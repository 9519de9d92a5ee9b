#include "core/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "core/error.h"

namespace iblkit {

namespace {

// What a file that is not regular is, for the message.
std::string fileKind(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

void requireRegularStat(const std::filesystem::path& file, const struct stat& info, std::uintmax_t limitBytes) {
  if (!S_ISREG(info.st_mode))
    fail(file, "not a regular file (" + fileKind(info.st_mode) + "); only regular files are read");
  if (static_cast<std::uintmax_t>(info.st_size) > limitBytes)
    fail(file, "file is " + std::to_string(info.st_size) + " bytes, more than the limit of " +
                   std::to_string(limitBytes));
}

class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }

 private:
  int fd_;
};

}  // namespace

void requireRegularInputFile(const std::filesystem::path& file, std::uintmax_t limitBytes) {
  struct stat info {};
  if (::stat(file.c_str(), &info) != 0) fail(file, std::string("cannot open: ") + std::strerror(errno));
  requireRegularStat(file, info, limitBytes);
}

std::vector<char> readInputFile(const std::filesystem::path& file, std::uintmax_t limitBytes) {
  requireRegularInputFile(file, limitBytes);
  const FileDescriptor fd(::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
  if (fd.get() < 0) fail(file, std::string("cannot open: ") + std::strerror(errno));
  struct stat info {};
  if (::fstat(fd.get(), &info) != 0) fail(file, std::string("cannot read: ") + std::strerror(errno));
  requireRegularStat(file, info, limitBytes);
  std::vector<char> bytes(static_cast<std::size_t>(info.st_size));
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t count = ::read(fd.get(), bytes.data() + done, bytes.size() - done);
    if (count < 0 && errno == EINTR) continue;
    if (count < 0) fail(file, std::string("cannot read: ") + std::strerror(errno));
    if (count == 0) break;  // shrank meanwhile
    done += static_cast<std::size_t>(count);
  }
  bytes.resize(done);
  if (bytes.empty()) fail(file, "empty file (0 bytes)");
  return bytes;
}

void requireJsonNesting(std::string_view text, const std::filesystem::path& file) {
  int depth = 0;
  bool inString = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        inString = false;
      continue;
    }
    if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonNesting)
        fail(file, "JSON nests arrays and objects more than " + std::to_string(kMaxJsonNesting) + " deep");
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

std::string readJsonText(const std::filesystem::path& file) {
  const std::vector<char> bytes = readInputFile(file, kMaxJsonInputBytes);
  std::string text(bytes.begin(), bytes.end());
  requireJsonNesting(text, file);
  return text;
}

}  // namespace iblkit
