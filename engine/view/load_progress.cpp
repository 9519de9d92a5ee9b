#include "engine/view/load_progress.h"

#include <iomanip>
#include <sstream>

namespace iblkit {

void LoadProgress::report(const char* step, std::size_t done, std::size_t total) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (step_ == step && total == total_ && done < done_) return;
  step_ = step;
  done_ = done;
  total_ = total;
}

std::string LoadProgress::describe(const std::filesystem::path& file, double seconds) const {
  std::ostringstream line;
  line << "opening " << file.filename().string() << ": ";
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (step_.empty()) {
      line << "reading";
    } else {
      const double percent = total_ > 0 ? 100.0 * double(done_) / double(total_) : 100.0;
      line << step_ << ' ' << std::fixed << std::setprecision(0) << percent << '%';
    }
  }
  line << ", " << std::fixed << std::setprecision(1) << seconds << " s ...";
  return line.str();
}

}  // namespace iblkit
