#include <modsynth/kinematics/arm_model.h>

#include <algorithm>
#include <cmath>

namespace modsynth::kinematics {
namespace {

std::vector<double> lerp(const std::vector<double>& a, const std::vector<double>& b, double t) {
    std::vector<double> out(a.size());
    for (std::size_t k = 0; k < a.size(); ++k) out[k] = a[k] + t * (b[k] - a[k]);
    return out;
}

/// The free numbers at the start (end) of primitive j.
std::vector<double> end_of(const ArmDesign& d, int j, bool at_end) {
    if (d.along.empty()) return {};
    const std::vector<double>& v = d.along[static_cast<std::size_t>(j)];
    const auto half = static_cast<std::ptrdiff_t>(v.size() / 2);
    return at_end ? std::vector<double>(v.begin() + half, v.end())
                  : std::vector<double>(v.begin(), v.begin() + half);
}

}  // namespace

DhChain ArmDesign::chain() const { return model->chain(*this); }

std::vector<double> ArmDesign::along_at(int j, double u) const {
    return lerp(end_of(*this, j, false), end_of(*this, j, true), u);
}

std::vector<double> ArmDesign::transition_along(int j, double t) const {
    return lerp(end_of(*this, j, true), end_of(*this, j + 1, false), t);
}

bool ArmDesign::sweeps_after(int j) const {
    const auto a = end_of(*this, j, true);
    const auto b = end_of(*this, j + 1, false);
    for (std::size_t k = 0; k < a.size(); ++k)
        if (std::abs(b[k] - a[k]) > 1e-12) return true;
    return false;
}

}  // namespace modsynth::kinematics
