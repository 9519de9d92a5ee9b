#pragma once
// The report page's large view of a case (docs/report.md, "The page"): one image at full size,
// flipping between the reference, each mode and its FLIP heat map by keys (left/right or n/p:
// previous/next; 1..9: the reference and the modes; h: the mode's heat map), by hovering or
// clicking its buttons; a zoom and an exposure control. At the case's own exposure it shows the
// report's PNGs; at any other it tone-maps the case's linear images (page_images.h) in the
// browser with the tone curve of core/ (ACES fitted, sRGB), whose constants it is written with
// (core/tone_curve_constants.h), so the page and the PNGs agree. Plain JavaScript, no server:
// it works from file://.

#include <string>

#include "report/report_case.h"

namespace iblkit {

// The page's style rules and its one script (the tone curve's constants in it).
std::string compareViewStyle();
std::string compareViewScript();

// The large view of one case: `caseName` as case_pictures.h names its files, `width` x `height`
// the images' size.
std::string compareViewHtml(const CaseResult& result, const std::string& caseName, int width, int height);

}  // namespace iblkit
