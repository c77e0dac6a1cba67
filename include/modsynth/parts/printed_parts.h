#pragma once
// The printed parts of an arm, written to a folder: an OpenSCAD source per
// link (link_1.scad, ...), base_plate.scad and tool_holder.scad; each
// rendered to STL when openscad is installed, and every STL checked: a
// closed manifold (this code's own edge count, and admesh's report when
// admesh is installed), the links' axes link-length apart in the mesh, and
// the links' mass from the mesh's volume for the arm's dynamics.
#include <string>
#include <vector>

#include <modsynth/hardware/arm_model.h>
#include <modsynth/hardware/catalog.h>
#include <modsynth/hardware/dh_arm_model.h>
#include <modsynth/kinematics/dh_chain.h>
#include <modsynth/kinematics/robot.h>
#include <modsynth/parts/link_design.h>
#include <modsynth/parts/screws.h>
#include <modsynth/parts/stl_mesh.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/task.h>

namespace modsynth::parts {

struct PartFile {
    std::string name;    ///< "link_1"
    std::string scad;    ///< path of the source
    std::string stl;     ///< path of the mesh; "" when not rendered
    std::string checks;  ///< what the checks found, one line
    bool checks_ok = false;
};

struct PrintedParts {
    std::string folder;
    PrintSettings settings;
    std::vector<LinkDesign> links;
    std::vector<PartFile> files;  ///< the links, then the base plate and the tool holder
    std::vector<Screw> screws;
    /// One per link, from its mesh (kg, m, kg m^2 about the joint axis);
    /// empty when the links were not rendered.
    std::vector<hardware::PrintedLink> bodies;
    /// The same meshes as solids (link_solid), for a spatial arm's
    /// dynamics; empty when bodies is.
    std::vector<hardware::RigidBody> solids;
    bool rendered = false;           ///< every file has its STL
    bool checks_ok = false;          ///< rendered, and every check passed
    std::vector<std::string> notes;  ///< warnings: no openscad, a check that failed
};

/// Seconds openscad is given for one part.
inline constexpr double kRenderTimeLimit = 300.0;

/// Creates `folder` when it does not exist; throws task::InputError naming
/// "--parts FOLDER" when it is not a folder or cannot be created or
/// written to.
void prepare_parts_folder(const std::string& folder);

/// Every path the parts of an arm of up to `max_links` links may be
/// written to in `folder` (sources and meshes), for the checks made before
/// any work (io/output_check.h). A symbolic link at one of them is replaced
/// by the file, never written through: nothing outside the folder changes.
std::vector<std::string> part_paths(const std::string& folder, int max_links);

/// The links of a planar arm built from `modules` (one per joint), at the
/// robot's link lengths, each sized for its driving module's peak torque;
/// module housings without dimensions in the catalog take the task's
/// module size.
std::vector<LinkDesign> planar_links(const task::RobotSpec& spec, const kinematics::Robot& robot,
                                     const std::vector<const hardware::Actuator*>& modules,
                                     const PrintSettings& settings);

/// The printed links of a spatial arm (a DH chain): one for each link with
/// a common normal (a_k) longer than 1 mm, at that length, the horn of
/// module k at one end and module k + 1 (or the tool) at the other. The
/// offset d_k along the horn's axis and the twist alpha_k stay with the
/// tubes and brackets the build sheet lists; `notes` says which links have
/// them, and which have no printed link.
std::vector<LinkDesign> dh_links(const task::SpatialRobotSpec& spec,
                                 const kinematics::DhChain& chain,
                                 const std::vector<const hardware::Actuator*>& modules,
                                 const PrintSettings& settings, std::vector<std::string>& notes);

/// Writes the sources, renders and checks them. `title` heads every source.
/// Throws std::runtime_error naming a file that cannot be written.
PrintedParts write_printed_parts(const std::vector<LinkDesign>& links, const ModuleMount& first,
                                 double rod_diameter, const std::string& folder,
                                 const std::string& title, const PrintSettings& settings,
                                 double time_limit = kRenderTimeLimit);

/// A link's rigid body from its mesh (in mm, as the source draws it):
/// volume times the printed density, its centre of mass along the link,
/// its moment about the joint axis through that centre.
hardware::PrintedLink link_body(const Mesh& mesh_mm, const PrintSettings& settings);

/// The same link as a solid in m, in the frame the source draws it in
/// (scad_writer.h): its mass, centre of mass and inertia tensor about it.
hardware::RigidBody link_solid(const Mesh& mesh_mm, const PrintSettings& settings);

}  // namespace modsynth::parts
