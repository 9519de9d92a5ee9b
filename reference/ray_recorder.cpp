#include "reference/ray_recorder.h"

namespace iblkit {

std::vector<RecordedRay> RayRecorder::rays() const {
  std::vector<RecordedRay> all;
  all.reserve(size());
  for (const std::vector<RecordedRay>& list : perThread_) all.insert(all.end(), list.begin(), list.end());
  return all;
}

std::size_t RayRecorder::size() const {
  std::size_t count = 0;
  for (const std::vector<RecordedRay>& list : perThread_) count += list.size();
  return count;
}

void RayRecorder::clear() {
  for (std::vector<RecordedRay>& list : perThread_) list.clear();
}

}  // namespace iblkit
