#include "sheets/sheet_plan.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace nimbus::media {

double sheetSpacingFor(const std::vector<float>& radii, double perRadius, std::vector<float>& scratch) {
    if (radii.empty()) return perRadius;
    scratch.assign(radii.begin(), radii.end());
    auto middle = scratch.begin() + static_cast<std::ptrdiff_t>(scratch.size() / 2);
    std::nth_element(scratch.begin(), middle, scratch.end());
    return perRadius * static_cast<double>(*middle);
}

SheetPlan planSheets(const std::vector<float>& rankDepths, float maxRadius, double mediumNear, double mediumFar, double znear,
                     double spacing) {
    SheetPlan plan;
    const double start = std::max(mediumNear, znear);
    if (rankDepths.empty() || !(mediumFar > start) || !(spacing > 0.0)) return plan;
    const double span = mediumFar - start;
    double count = std::ceil(span / spacing);
    if (count > kMaxSheets) {
        count = kMaxSheets;
        spacing = span / kMaxSheets;
        plan.widened = true;
    }
    plan.spacing = static_cast<float>(spacing);
    const int sheets = std::max(1, static_cast<int>(count));
    plan.sheets.reserve(static_cast<std::size_t>(sheets));
    for (int k = sheets - 1; k >= 0; --k) {
        Sheet sheet;
        sheet.nearDepth = static_cast<float>(start + spacing * k);
        sheet.farDepth = static_cast<float>(start + spacing * (k + 1));
        // The depths fall with the rank: the run whose centres lie within maxRadius of the sheet.
        const auto first = std::upper_bound(rankDepths.begin(), rankDepths.end(), sheet.farDepth + maxRadius, std::greater<float>());
        const auto last = std::lower_bound(first, rankDepths.end(), sheet.nearDepth - maxRadius, std::greater<float>());
        sheet.firstRank = static_cast<std::uint32_t>(first - rankDepths.begin());
        sheet.ranks = static_cast<std::uint32_t>(last - first);
        if (sheet.ranks > 0) plan.sheets.push_back(sheet);
    }
    return plan;
}

}  // namespace nimbus::media
