#pragma once
// A DXF HATCH's boundary paths, read from its group codes as the DXF
// reference lays them out. dxflib (3.26) hands a hatch's edges out, but a
// polyline boundary's vertex count (group 93) opens a second, empty loop,
// the seed points after a last polyline boundary (98, then 10/20) come out
// as one more boundary, and a count is never checked against what follows;
// so the DXF reader's pre-scan of the groups reads the boundaries here, and
// dxflib's hatch callback only says which entity (in block or model space)
// they belong to.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <modsynth/drawing/curve.h>

namespace modsynth::drawing {

/// What a HATCH's boundary draws: each boundary path (loop) as the runs of
/// its edges that meet end to start (a closed loop is one run), in world
/// coordinates (the entity's OCS turned over when its extrusion points
/// down), and what had to be left out.
struct HatchBoundary {
    struct Run {
        std::size_t path = 0;  ///< which boundary path, from 1
        std::vector<Segment> segments;
    };
    std::vector<Run> runs;
    /// Edges that cannot be traced, each by its place ("boundary path 2,
    /// edge 3 (line 140): a spline given by fit points only").
    std::vector<std::string> left_out;
    /// Why the boundary cannot be read at all (a count that does not match
    /// the items that follow, an unknown edge type, a negative radius):
    /// empty when it can.
    std::string problem;
    /// The layer the HATCH names (group 8), to check that dxflib's
    /// callbacks and the pre-scan speak of the same entity.
    std::string layer = "0";
};

/// Reads one HATCH entity's groups, fed in file order from the group after
/// its `0 HATCH` up to the next entity. Numbers come already checked (the
/// pre-scan refuses a group whose value is not a whole, finite number).
class HatchReader {
public:
    /// A group whose value is a number (real or integer code).
    void number(int code, double value, std::size_t line);
    /// A group whose value is text (the layer, handles, the pattern name).
    void text(int code, const std::string& value);
    HatchBoundary finish();

private:
    struct Edge {
        int type = 0;  ///< 1 line, 2 circular arc, 3 elliptic arc, 4 spline
        std::size_t line = 0;
        Vec2 p10 = Vec2::Zero(), p11 = Vec2::Zero();  ///< by group code
        double g40 = 0.0, g50 = 0.0, g51 = 0.0;
        bool ccw = true;
        int degree = 3;
        std::optional<long long> declared_knots, declared_control;
        std::vector<double> knots;
        std::vector<Vec2> control;
        std::vector<double> weights;
        std::size_t fit_points = 0;
    };
    struct Vertex {
        Vec2 p = Vec2::Zero();
        double bulge = 0.0;
    };
    struct Path {
        bool polyline = false;
        std::size_t line = 0;
        std::optional<long long> declared;  ///< group 93: vertices or edges
        std::vector<Vertex> vertices;
        std::vector<Edge> edges;
    };
    enum class Phase { Header, Paths, After };

    void end_path();
    void fail(const std::string& problem);
    std::string where(std::size_t path, std::size_t line) const;

    Phase phase_ = Phase::Header;
    std::optional<long long> declared_paths_;
    std::size_t paths_ = 0;
    std::optional<Path> path_;
    bool mirrored_ = false;
    HatchBoundary out_;
};

}  // namespace modsynth::drawing
