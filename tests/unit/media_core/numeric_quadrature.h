#pragma once
// Test helper: composite Gauss–Legendre in long double, an independent judge for closed forms.
#include <cmath>
#include <functional>

namespace nimbus::media::test {

// ∫_a^b f(x) dx with `panels` panels of the 10-point Gauss–Legendre rule (exact to degree 19 per panel).
inline long double integrate(const std::function<long double(long double)>& f, long double a, long double b,
                             int panels = 256) {
    static const long double x[5] = {0.1488743389816312108848260011297200L, 0.4333953941292471907992659431657842L,
                                     0.6794095682990244062343273651148736L, 0.8650633666889845107320966884234930L,
                                     0.9739065285171717200779640120844521L};
    static const long double w[5] = {0.2955242247147528701738929946513383L, 0.2692667193099963550912269215694694L,
                                     0.2190863625159820439955349342281632L, 0.1494513491505805931457763396576973L,
                                     0.0666713443086881375935688098933318L};
    long double sum = 0.0L;
    const long double h = (b - a) / panels;
    for (int p = 0; p < panels; ++p) {
        const long double mid = a + (p + 0.5L) * h, half = 0.5L * h;
        long double s = 0.0L;
        for (int i = 0; i < 5; ++i) s += w[i] * (f(mid - half * x[i]) + f(mid + half * x[i]));
        sum += s * half;
    }
    return sum;
}

}  // namespace nimbus::media::test
