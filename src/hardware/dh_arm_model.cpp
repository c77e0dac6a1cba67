#include <modsynth/hardware/dh_arm_model.h>

#include <algorithm>
#include <stdexcept>

#include <Eigen/Geometry>

#include <modsynth/geometry/vec.h>
#include <modsynth/hardware/dh_stack.h>

namespace modsynth::hardware {

using geometry::Vec3;

void add_part(RigidBody& body, double mass, const Vec3& com, const Eigen::Matrix3d& inertia) {
    if (mass <= 0.0) return;
    const double total = body.mass + mass;
    const Vec3 c = (body.mass * body.com + mass * com) / total;
    // Each inertia moved from its own centre to the joint one: I + m (|r|^2 E - r r^T).
    const auto shift = [](double m, const Vec3& r) {
        return Eigen::Matrix3d(m *
                               (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose()));
    };
    body.inertia = body.inertia + shift(body.mass, body.com - c) + inertia + shift(mass, com - c);
    body.com = c;
    body.mass = total;
}

Eigen::Matrix3d tube_inertia(double mass, const Vec3& a, const Vec3& b, double diameter) {
    const Vec3 d = b - a;
    const double l = d.norm();
    const Vec3 u = l > 0.0 ? Vec3(d / l) : Vec3::UnitZ();
    const double r2 = diameter * diameter / 4.0;
    // Thin wall: m r^2 about the axis, m r^2 / 2 + m l^2 / 12 across it.
    const double axial = mass * r2;
    const double across = mass * r2 / 2.0 + mass * l * l / 12.0;
    return across * Eigen::Matrix3d::Identity() + (axial - across) * u * u.transpose();
}

Eigen::Matrix3d box_inertia(double mass, const Vec3& size, const Eigen::Matrix3d& R) {
    const Vec3 s2 = size.cwiseProduct(size);
    const Eigen::Vector3d diagonal(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y());
    return R * (mass / 12.0 * diagonal).asDiagonal() * R.transpose();
}

const Adapter& mount_part(const Catalog& catalog, bool bracket) {
    if (bracket) {
        if (const Adapter* a = catalog.adapter("right-angle bracket")) return *a;
    }
    return catalog.adapter();
}

DhArmModel dh_arm_model(const task::SpatialRobotSpec& spec, const kinematics::DhChain& chain,
                        const Catalog& catalog, const std::vector<const Actuator*>& modules,
                        const std::vector<PrintedDhLink>& printed) {
    const int n = chain.dof();
    if (static_cast<int>(modules.size()) != n)
        throw std::invalid_argument("dh_arm_model: one module per joint");
    std::vector<bool> is_printed(static_cast<std::size_t>(n), false);
    for (const PrintedDhLink& p : printed) {
        if (p.link < 0 || p.link >= n || chain.rows[static_cast<std::size_t>(p.link)].a == 0.0)
            throw std::invalid_argument("dh_arm_model: a printed link on a link without an a part");
        is_printed[static_cast<std::size_t>(p.link)] = true;
    }
    DhArmModel model;
    model.chain = chain;
    model.gravity = spec.gravity;
    model.links.resize(static_cast<std::size_t>(n));
    const Tube& tube = catalog.tube_closest_to(chain.link_diameter);
    const Tube& rod = catalog.tube_closest_to(spec.ee_rod_diameter);
    const double adapter = catalog.adapter().mass;
    const double corner_bracket = mount_part(catalog, true).mass;
    const DhStack stack = dh_stack(spec, chain);
    const auto corner = [&](int link) {
        return std::find(stack.corners.begin(), stack.corners.end(), link) != stack.corners.end();
    };
    for (const DhTube& t : stack.tubes) {
        RigidBody& body = model.links[static_cast<std::size_t>(t.link)];
        // The printed link bolts to the horn and to the next housing (or
        // the bracket): no tube, no adapters.
        if (!t.along_axis && is_printed[static_cast<std::size_t>(t.link)]) continue;
        const Vec3 u = (t.to - t.from).normalized();
        if (t.cut_length > 0.0) {
            const Vec3 a = t.from + t.proximal_allowance * u;
            const Vec3 b = t.to - t.distal_allowance * u;
            const double m = tube.mass_per_metre * t.cut_length;
            add_part(body, m, (a + b) / 2.0, tube_inertia(m, a, b, chain.link_diameter));
        }
        // An adapter where the tube meets a module's output, or the next
        // module's housing when a tube adapter mounts it; a bracket at a
        // corner or a mount is counted once, below.
        const bool from_corner = !t.along_axis && corner(t.link);
        const bool to_corner = t.along_axis && corner(t.link);
        if (!from_corner)
            add_part(body, adapter,
                     t.from + (t.proximal_allowance - spec.adapter_length / 2.0) * u);
        if (!t.last && !to_corner && t.link + 1 < n &&
            stack.mounts[static_cast<std::size_t>(t.link)].kind == DhMountKind::TubeAdapter)
            add_part(body, adapter, t.to - (t.distal_allowance - spec.adapter_length / 2.0) * u);
    }
    for (const PrintedDhLink& p : printed) {
        const kinematics::DhRow& r = chain.rows[static_cast<std::size_t>(p.link)];
        // The part is drawn along +x from the horn, standing on it along
        // +z. A negative a turns it about the axis; below a module (d < 0)
        // it hangs from the output, turned over about x. Like every part of
        // the model it sits on the chain's lines: the horn's face on the a
        // segment, where the tube ran.
        Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
        if (r.a < 0.0) R = Eigen::AngleAxisd(geometry::kPi, Vec3::UnitZ()) * R;
        if (r.d < 0.0) R = R * Eigen::AngleAxisd(geometry::kPi, Vec3::UnitX());
        add_part(model.links[static_cast<std::size_t>(p.link)], p.part.mass,
                 R * p.part.com + Vec3(0.0, 0.0, r.d), R * p.part.inertia * R.transpose());
    }
    for (int k : stack.corners) {
        const kinematics::DhRow& r = chain.rows[static_cast<std::size_t>(k)];
        add_part(model.links[static_cast<std::size_t>(k)], corner_bracket, Vec3(0.0, 0.0, r.d));
    }
    for (int k = 0; k < n; ++k) {
        const kinematics::DhRow& r = chain.rows[static_cast<std::size_t>(k)];
        RigidBody& body = model.links[static_cast<std::size_t>(k)];
        const Vec3 end(r.a, 0.0, r.d);
        if (k + 1 < n) {
            const DhMount& mount = stack.mounts[static_cast<std::size_t>(k)];
            if (mount.kind != DhMountKind::TubeAdapter)
                add_part(body, mount_part(catalog, true).mass, end);
            // The next module's housing, centred on its axis at o_k; its
            // output turns with the next link, but its rotor and gears are
            // light next to the housing, so all of its mass is counted here.
            const Actuator& next = *modules[static_cast<std::size_t>(k + 1)];
            const Eigen::Matrix3d R =
                Eigen::AngleAxisd(r.alpha, Eigen::Vector3d::UnitX()).toRotationMatrix();
            add_part(
                body, next.mass, end,
                box_inertia(next.mass,
                            Vec3(spec.module_length, spec.module_width, spec.module_height), R));
        } else {
            // The tool is the last tool_length m of the chain's last
            // segment; when that segment is not the last link's own (a last
            // row of zeros), its mass is taken at the EE.
            const double m = rod.mass_per_metre * spec.tool_length;
            if (!stack.tubes.empty() && stack.tubes.back().link == k) {
                const DhTube& last = stack.tubes.back();
                const Vec3 a = last.to - spec.tool_length * (last.to - last.from).normalized();
                add_part(body, m, (a + last.to) / 2.0, tube_inertia(m, a, last.to, rod.diameter));
            } else {
                add_part(body, m, end);
            }
            add_part(body, spec.payload, end);
        }
    }
    return model;
}

}  // namespace modsynth::hardware
