#pragma once
// A spatial arm as rigid bodies for its dynamics: each link of the DH chain
// with what rides on it (hardware/dh_stack.h): its tubes as uniform rods,
// their adapters, the corner and mount brackets, the next module's housing,
// and on the last link the tool and the payload. Module 1's housing stands
// on the base and loads no joint.
#include <vector>

#include <Eigen/Core>

#include <modsynth/geometry/vec3.h>
#include <modsynth/hardware/catalog.h>
#include <modsynth/kinematics/dh_chain.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::hardware {

/// Mass, centre of mass and inertia about it, in a link's joint frame
/// (dh_stack.h).
struct RigidBody {
    double mass = 0.0;                                  ///< kg
    geometry::Vec3 com = geometry::Vec3::Zero();        ///< m
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< kg m^2, about com
};

/// Adds a part to a body (the parallel-axis theorem); parts without mass
/// change nothing.
void add_part(RigidBody& body, double mass, const geometry::Vec3& com,
              const Eigen::Matrix3d& inertia = Eigen::Matrix3d::Zero());

/// About its centre: a thin-walled tube of `diameter` from a to b.
Eigen::Matrix3d tube_inertia(double mass, const geometry::Vec3& a, const geometry::Vec3& b,
                             double diameter);
/// About its centre: a box of sizes (x, y, z) along the columns of R.
Eigen::Matrix3d box_inertia(double mass, const geometry::Vec3& size, const Eigen::Matrix3d& R);

struct DhArmModel {
    kinematics::DhChain chain;
    std::vector<RigidBody> links;  ///< one per joint, in its joint frame
    geometry::Vec3 gravity = geometry::Vec3(0.0, 0.0, -9.81);  ///< m/s^2, task frame
};

/// A link printed in one piece for the a part of a DH link (parts/): what
/// its mesh weighs, in the frame the part is drawn in (parts/scad_writer.h,
/// in m): the origin on the horn's axis at the face the horn bolts to, z
/// along that axis away from the module, x towards the next axis.
struct PrintedDhLink {
    int link = 0;  ///< 0-based: the a part of link link + 1
    RigidBody part;
};

/// The model of `chain` built from `modules` (one per joint, module k at
/// joint k). Tubes are the catalog's closest to the link diameter, the tool
/// a rod of the one closest to `ee_rod_diameter` over `tool_length`; the
/// payload sits at the EE. With `printed` (`modsynth solve --parts`), a
/// printed link's part replaces the a tube of its link and that tube's
/// adapters (it bolts straight to the modules); it lies along a_k with the
/// horn's face at the height d_k where the tube ran (turned over below a
/// module, d_k < 0), and the d tubes, brackets and housings stay. Throws std::invalid_argument when
/// the module count is not the joint count, or a printed link names no link with an a part.
DhArmModel dh_arm_model(const task::SpatialRobotSpec& spec, const kinematics::DhChain& chain,
                        const Catalog& catalog, const std::vector<const Actuator*>& modules,
                        const std::vector<PrintedDhLink>& printed = {});

/// The catalog's part for a mount or corner bracket of that kind (the
/// tube adapter, else the right-angle bracket, whose mass stands in for a
/// bracket made for another angle).
const Adapter& mount_part(const Catalog& catalog, bool bracket);

}  // namespace modsynth::hardware
