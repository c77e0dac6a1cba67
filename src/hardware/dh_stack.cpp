#include <modsynth/hardware/dh_stack.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace modsynth::hardware {

using geometry::Vec3;

double box_exit(const Vec3& half, const Vec3& u) {
    double t = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i)
        if (std::abs(u[i]) > 1e-12) t = std::min(t, half[i] / std::abs(u[i]));
    return std::isfinite(t) ? t : 0.0;
}

DhMountKind mount_kind(double twist) {
    const double a = std::abs(std::remainder(twist, 2.0 * geometry::kPi));
    if (a < kTwistTolerance || std::abs(a - geometry::kPi) < kTwistTolerance)
        return DhMountKind::TubeAdapter;
    if (std::abs(a - geometry::kPi / 2.0) < kTwistTolerance) return DhMountKind::RightAngleBracket;
    return DhMountKind::OtherBracket;
}

DhStack dh_stack(const task::SpatialRobotSpec& spec, const kinematics::DhChain& chain) {
    DhStack out;
    const int n = chain.dof();
    const double D = chain.link_diameter;
    const Vec3 housing(spec.module_length / 2.0, spec.module_width / 2.0, spec.module_height / 2.0);
    const std::vector<kinematics::SegmentLayout> layout = kinematics::segment_layout(chain);
    for (std::size_t i = 0; i < layout.size(); ++i) {
        const kinematics::SegmentLayout& seg = layout[i];
        const kinematics::DhRow& r = chain.rows[static_cast<std::size_t>(seg.link)];
        DhTube t;
        t.link = seg.link;
        t.along_axis = seg.along_axis;
        t.segment_length = seg.length;
        t.from = seg.along_axis ? Vec3::Zero() : Vec3(0.0, 0.0, r.d);
        t.to = seg.along_axis ? Vec3(0.0, 0.0, r.d) : Vec3(r.a, 0.0, r.d);
        t.last = i + 1 == layout.size();
        const bool corner =
            std::abs(r.d) > kinematics::kZeroSegment && std::abs(r.a) > kinematics::kZeroSegment;
        // Leaving the module's output along its axis, the tube starts at
        // the housing's face; across it, at the edge of the output.
        if (!seg.along_axis && corner)
            t.proximal_allowance = D / 2.0 + spec.adapter_length;
        else
            t.proximal_allowance =
                (seg.along_axis ? housing.z() : housing.y()) + spec.adapter_length;
        if (t.last) {
            t.distal_allowance = spec.tool_length;
        } else if (seg.along_axis && corner) {
            t.distal_allowance = D / 2.0 + spec.adapter_length;
        } else {
            // The next housing is fixed in frame k = joint frame * Rx(alpha);
            // the tube runs into it from o_k back along the segment.
            const Vec3 back = (t.from - t.to).normalized();
            const Eigen::Matrix3d R =
                Eigen::AngleAxisd(r.alpha, Eigen::Vector3d::UnitX()).toRotationMatrix();
            t.distal_allowance = box_exit(housing, R.transpose() * back) + spec.adapter_length;
        }
        t.cut_length = t.segment_length - t.proximal_allowance - t.distal_allowance;
        out.tubes.push_back(t);
    }
    for (int k = 0; k < n; ++k) {
        const kinematics::DhRow& r = chain.rows[static_cast<std::size_t>(k)];
        if (std::abs(r.d) > kinematics::kZeroSegment && std::abs(r.a) > kinematics::kZeroSegment)
            out.corners.push_back(k);
        if (k + 1 < n) {
            DhMount m;
            m.joint = k + 2;
            m.twist = r.alpha;
            m.kind = mount_kind(r.alpha);
            m.on_tube = std::any_of(out.tubes.begin(), out.tubes.end(),
                                    [&](const DhTube& t) { return t.link == k; });
            out.mounts.push_back(m);
        }
    }
    return out;
}

}  // namespace modsynth::hardware
