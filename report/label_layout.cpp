#include "report/label_layout.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace iblkit {

bool overlaps(const LabelBox& a, const LabelBox& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

std::vector<double> placeLabels(const std::vector<LabelBox>& wanted, double top, double bottom, double step) {
  std::vector<std::size_t> order(wanted.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return wanted[a].y < wanted[b].y; });
  std::vector<double> placedY(wanted.size());
  std::vector<LabelBox> placed;
  for (const std::size_t i : order) {
    const LabelBox& box = wanted[i];
    const auto isFree = [&](double y) {
      LabelBox candidate = box;
      candidate.y = y;
      return std::none_of(placed.begin(), placed.end(), [&](const LabelBox& other) { return overlaps(candidate, other); });
    };
    const auto inBand = [&](double y) { return y >= top && y + box.height <= bottom; };
    const bool fits = bottom - top >= box.height;
    double chosen = box.y;
    if (fits) chosen = std::clamp(box.y, top, bottom - box.height);
    // Every placed box blocks at most (its height + this height) / step candidates, so this many
    // steps each way always reach a free position.
    double reach = 0.0;
    for (const LabelBox& other : placed) reach += other.height + box.height + step;
    const int steps = int(std::ceil(reach / step)) + 1;
    bool found = false;
    for (const bool keepInBand : {true, false}) {
      if (keepInBand && !fits) continue;
      for (int k = 0; k <= steps && !found; ++k)
        for (const double y : {chosen + k * step, chosen - k * step})
          if ((!keepInBand || inBand(y)) && isFree(y)) {
            chosen = y;
            found = true;
            break;
          }
      if (found) break;
    }
    placedY[i] = chosen;
    LabelBox box2 = box;
    box2.y = chosen;
    placed.push_back(box2);
  }
  return placedY;
}

double labelWidth(const std::string& text, double fontSize) { return 0.62 * fontSize * double(text.size()); }

}  // namespace iblkit
