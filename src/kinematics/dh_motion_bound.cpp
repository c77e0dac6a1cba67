#include <modsynth/kinematics/dh_motion_bound.h>

#include <algorithm>
#include <cmath>

namespace modsynth::kinematics {

double chord_gap(const DhChain& chain, const std::vector<double>& dq, int frame, int last_joint,
                 double reach) {
    // Chain length from the base to o_{i-1}, for i = 1 .. n.
    double at = 0.0;
    std::vector<double> lever;  // L_i for joints frame + 1 .. last_joint
    std::vector<double> step;   // |dq_i| for the same joints
    for (int i = 1; i <= last_joint; ++i) {
        if (i > frame) {
            lever.push_back(std::max(0.0, reach - at));
            step.push_back(std::abs(dq[static_cast<std::size_t>(i - 1)]));
        }
        const DhRow& r = chain.rows[static_cast<std::size_t>(i - 1)];
        at += std::abs(r.a) + std::abs(r.d);
    }
    double e = 0.0, before = 0.0;
    for (std::size_t i = 0; i < step.size(); ++i) {
        double after = 0.0;
        for (std::size_t j = i; j < step.size(); ++j) after += step[j] * lever[j];
        e += step[i] * (2.0 * before * lever[i] + after);
        before += step[i];
    }
    return e / 8.0;
}

}  // namespace modsynth::kinematics
