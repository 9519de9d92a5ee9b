#pragma once
// Where the report's SVG plots put their text labels so that no two overlap (the ladder plot's
// environment names at the end of their lines, the cost plot's mode names beside their points).
// Greedy vertical nudge: the labels are placed in the order of their wanted height, each at the
// nearest free height (up or down in steps) to the one it wants, within the plot's band when it
// fits there.

#include <string>
#include <vector>

namespace iblkit {

// A label's box in SVG user units: (x, y) its top left corner.
struct LabelBox {
  double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
};

bool overlaps(const LabelBox& a, const LabelBox& b);

// The y of each box's top (same order as `wanted`): wanted[i].y moved by the least multiple of
// `step` that keeps it clear of the boxes placed before it, preferring positions within
// [top, bottom - height]. x and the sizes do not change.
std::vector<double> placeLabels(const std::vector<LabelBox>& wanted, double top, double bottom, double step = 1.0);

// A generous width of `text` in a sans-serif font of `fontSize` (0.62 em per character; the
// plots' labels are short ASCII names), so that boxes clear in placeLabels clear on screen too.
double labelWidth(const std::string& text, double fontSize);

}  // namespace iblkit
