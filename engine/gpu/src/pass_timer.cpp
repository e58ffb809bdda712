#include "nimbus/gpu/pass_timer.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace nimbus::gpu {

void GlPassTimer::begin(std::string_view) {
    glFinish();
    start_ = std::chrono::steady_clock::now();
}

void GlPassTimer::end(std::string_view pass) {
    glFinish();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
    samples_[std::string(pass)].push_back(ms);
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const std::size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
    const double upper = values[mid];
    if (values.size() % 2 == 1) return upper;
    const double lower = *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid));
    return 0.5 * (lower + upper);
}

}  // namespace nimbus::gpu
