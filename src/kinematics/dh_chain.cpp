#include <modsynth/kinematics/dh_chain.h>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace modsynth::kinematics {

using geometry::Vec3;

double DhChain::total_length() const {
    double sum = 0.0;
    for (const DhRow& r : rows) sum += std::abs(r.a) + std::abs(r.d);
    return sum;
}

std::vector<SegmentLayout> segment_layout(const DhChain& chain) {
    std::vector<SegmentLayout> out;
    double at = 0.0;
    for (int k = 0; k < chain.dof(); ++k) {
        const DhRow& r = chain.rows[static_cast<std::size_t>(k)];
        for (const bool axis : {true, false}) {
            const double len = std::abs(axis ? r.d : r.a);
            if (len > kZeroSegment) out.push_back({k, axis, len, at});
            at += len;
        }
    }
    return out;
}

std::vector<SegmentPart> clearance_parts(const std::vector<SegmentLayout>& layout,
                                         double tool_length, double mount) {
    std::vector<SegmentPart> keep;
    double left = tool_length;
    for (int i = static_cast<int>(layout.size()) - 1; i >= 0; --i) {
        const double len = layout[static_cast<std::size_t>(i)].length;
        const double to = left <= 0.0 ? 1.0 : std::max(0.0, 1.0 - left / len);
        left -= len;
        if (to > 0.0) keep.push_back({i, 0.0, to});
    }
    std::reverse(keep.begin(), keep.end());
    left = mount;
    for (SegmentPart& part : keep) {
        if (left <= 0.0) break;
        const double len = layout[static_cast<std::size_t>(part.segment)].length;
        part.from = std::min(part.to, left / len);
        left -= len;
    }
    std::vector<SegmentPart> out;
    for (const SegmentPart& part : keep)
        if (part.to > part.from) out.push_back(part);
    return out;
}

std::vector<Eigen::Isometry3d> frames(const DhChain& chain, const std::vector<double>& q) {
    assert(static_cast<int>(q.size()) == chain.dof());
    std::vector<Eigen::Isometry3d> out;
    out.reserve(q.size() + 1);
    Eigen::Isometry3d f = Eigen::Isometry3d::Identity();
    f.translation() = chain.base;
    out.push_back(f);
    for (std::size_t k = 0; k < q.size(); ++k) {
        const DhRow& r = chain.rows[k];
        const double cq = std::cos(q[k]), sq = std::sin(q[k]);
        const double ca = std::cos(r.alpha), sa = std::sin(r.alpha);
        // Rz(q) Tz(d) Tx(a) Rx(alpha) in one matrix.
        Eigen::Matrix4d t;
        t << cq, -sq * ca, sq * sa, r.a * cq,  //
            sq, cq * ca, -cq * sa, r.a * sq,   //
            0.0, sa, ca, r.d,                  //
            0.0, 0.0, 0.0, 1.0;
        f = f * Eigen::Isometry3d(t);
        out.push_back(f);
    }
    return out;
}

Vec3 end_effector(const DhChain& chain, const std::vector<double>& q) {
    return frames(chain, q).back().translation();
}

std::vector<Segment3> chain_segments(const DhChain& chain,
                                     const std::vector<Eigen::Isometry3d>& fr) {
    std::vector<Segment3> out;
    for (int k = 0; k < chain.dof(); ++k) {
        const DhRow& r = chain.rows[static_cast<std::size_t>(k)];
        const Eigen::Isometry3d& f0 = fr[static_cast<std::size_t>(k)];
        const Vec3 o0 = f0.translation();
        const Vec3 mid = o0 + r.d * f0.linear().col(2);
        const Vec3 o1 = fr[static_cast<std::size_t>(k) + 1].translation();
        if (std::abs(r.d) > kZeroSegment) out.push_back({o0, mid});
        if (std::abs(r.a) > kZeroSegment) out.push_back({mid, o1});
    }
    return out;
}

std::vector<Segment3> chain_segments(const DhChain& chain, const std::vector<double>& q) {
    return chain_segments(chain, frames(chain, q));
}

Eigen::Matrix<double, 3, Eigen::Dynamic> position_jacobian(const DhChain& chain,
                                                           const std::vector<double>& q) {
    const auto fr = frames(chain, q);
    const Vec3 ee = fr.back().translation();
    Eigen::Matrix<double, 3, Eigen::Dynamic> j(3, chain.dof());
    for (int k = 0; k < chain.dof(); ++k) {
        const Eigen::Isometry3d& f = fr[static_cast<std::size_t>(k)];
        j.col(k) = f.linear().col(2).cross(ee - f.translation());
    }
    return j;
}

}  // namespace modsynth::kinematics
