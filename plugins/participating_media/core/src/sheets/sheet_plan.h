#pragma once
// Where the sheets of `sheets` mode lie this frame: planes of constant view depth from the medium's
// near side to its far side at one spacing, and for each sheet the run of ranks (in the order by
// view depth, farthest first) whose particles may reach into it.
//
// Does not: depend on the order the particles are listed in, or move a sheet by a jump as the view
// turns: the planes start where the medium starts (or at the near plane), which moves smoothly.
#include <cstdint>
#include <vector>

namespace nimbus::media {

inline constexpr int kMaxSheets = 256;  // beyond it the spacing widens to fit (SheetPlan::widened)

struct Sheet {
    float nearDepth = 0.0f, farDepth = 0.0f;  // view depth (m)
    std::uint32_t firstRank = 0, ranks = 0;   // the particles drawn into it
};

struct SheetPlan {
    std::vector<Sheet> sheets;  // back to front (the order they are composited in)
    float spacing = 0.0f;       // as used (m)
    bool widened = false;       // the asked spacing would have taken more than kMaxSheets
};

// The spacing from the particle size: `perRadius` times the median radius (positive radii).
// `scratch` is reused between calls (steady frames allocate nothing).
double sheetSpacingFor(const std::vector<float>& radii, double perRadius, std::vector<float>& scratch);

// `rankDepths`: the centres' view depths in draw order (non-increasing), `maxRadius` the largest
// radius, [mediumNear, mediumFar] the view depths the medium spans, `znear` the camera's near
// plane, `spacing` > 0 in metres. No sheets when the medium lies behind the camera.
SheetPlan planSheets(const std::vector<float>& rankDepths, float maxRadius, double mediumNear, double mediumFar, double znear,
                     double spacing);

}  // namespace nimbus::media
