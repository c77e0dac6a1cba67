#include <modsynth/parts/stl_mesh.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace modsynth::parts {

namespace {

using geometry::Vec2;
using geometry::Vec3;
using Key = std::tuple<double, double, double>;

Key key_of(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

Mesh parse_binary(const std::string& bytes, const std::string& name) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    Mesh mesh;
    mesh.triangles.reserve(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        const char* p = bytes.data() + 84 + 50 * static_cast<std::size_t>(i) + 12;
        std::array<Vec3, 3> t;
        for (int v = 0; v < 3; ++v) {
            float xyz[3];
            std::memcpy(xyz, p + 12 * v, 12);
            t[v] = Vec3(xyz[0], xyz[1], xyz[2]);
        }
        mesh.triangles.push_back(t);
    }
    if (mesh.triangles.empty()) throw std::runtime_error(name + ": an STL file without triangles");
    return mesh;
}

}  // namespace

Mesh parse_stl(const std::string& bytes, const std::string& name) {
    if (bytes.size() >= 84) {
        std::uint32_t count = 0;
        std::memcpy(&count, bytes.data() + 80, 4);
        if (bytes.size() == 84 + 50 * static_cast<std::size_t>(count))
            return parse_binary(bytes, name);
    }
    if (bytes.compare(0, 5, "solid") != 0)
        throw std::runtime_error(name + ": not an STL file (neither ASCII nor binary)");
    std::istringstream in(bytes);
    Mesh mesh;
    std::string word;
    std::array<Vec3, 3> t;
    int v = 0;
    while (in >> word) {
        if (word != "vertex") continue;
        double x, y, z;
        if (!(in >> x >> y >> z)) throw std::runtime_error(name + ": a vertex without 3 numbers");
        t[v++] = Vec3(x, y, z);
        if (v == 3) {
            mesh.triangles.push_back(t);
            v = 0;
        }
    }
    if (v != 0) throw std::runtime_error(name + ": a facet without 3 vertices");
    if (mesh.triangles.empty()) throw std::runtime_error(name + ": an STL file without triangles");
    return mesh;
}

Mesh read_stl(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot be read");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return parse_stl(bytes.str(), path);
}

int bad_edges(const Mesh& mesh) {
    // Directed edge -> how many triangles run along it.
    std::map<std::pair<Key, Key>, int> directed;
    for (const auto& t : mesh.triangles)
        for (int i = 0; i < 3; ++i) ++directed[{key_of(t[i]), key_of(t[(i + 1) % 3])}];
    int bad = 0;
    for (const auto& [edge, count] : directed) {
        const auto back = directed.find({edge.second, edge.first});
        const int opposite = back == directed.end() ? 0 : back->second;
        // Each undirected edge is counted once, from its smaller end.
        if (edge.first < edge.second && (count != 1 || opposite != 1)) ++bad;
        if (edge.second < edge.first && opposite == 0) ++bad;
    }
    return bad;
}

MassProperties mass_properties(const Mesh& mesh) {
    MassProperties out;
    double volume = 0.0;
    Vec3 moment = Vec3::Zero();
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
    // Each triangle and the origin span a signed tetrahedron.
    for (const auto& t : mesh.triangles) {
        const Vec3 &a = t[0], &b = t[1], &c = t[2];
        const double det = a.dot(b.cross(c));
        const Vec3 s = a + b + c;
        volume += det / 6.0;
        moment += det / 24.0 * s;
        second += det / 120.0 *
                  (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
    }
    out.volume = volume;
    if (volume == 0.0) return out;
    out.centroid = moment / volume;
    const Eigen::Matrix3d about_centroid =
        second - volume * out.centroid * out.centroid.transpose();
    out.inertia = about_centroid.trace() * Eigen::Matrix3d::Identity() - about_centroid;
    return out;
}

std::vector<std::vector<Vec2>> section(const Mesh& mesh, double z) {
    // The crossing of an edge is computed from its ends in one order, so
    // that the two triangles sharing it give the same point.
    using Edge = std::pair<Key, Key>;
    std::map<Edge, std::vector<Edge>> next;
    std::map<Edge, Vec2> point;
    for (const auto& t : mesh.triangles) {
        std::vector<Edge> crossing;
        for (int i = 0; i < 3; ++i) {
            Vec3 p = t[i], q = t[(i + 1) % 3];
            if ((p.z() < z) == (q.z() < z)) continue;
            if (key_of(q) < key_of(p)) std::swap(p, q);
            const Edge e{key_of(p), key_of(q)};
            const double f = (z - p.z()) / (q.z() - p.z());
            point[e] = (p + f * (q - p)).head<2>();
            crossing.push_back(e);
        }
        if (crossing.size() != 2) continue;
        next[crossing[0]].push_back(crossing[1]);
        next[crossing[1]].push_back(crossing[0]);
    }
    std::vector<std::vector<Vec2>> loops;
    std::map<Edge, bool> seen;
    for (const auto& [start, unused] : next) {
        if (seen[start]) continue;
        std::vector<Vec2> loop;
        Edge previous = start, at = start;
        while (true) {
            seen[at] = true;
            loop.push_back(point[at]);
            const auto& n = next[at];
            const Edge step = n[0] == previous && n.size() > 1 ? n[1] : n[0];
            previous = at;
            at = step;
            if (at == start || seen[at]) break;
        }
        // A chain that does not come back to its start is a cut through an
        // open surface: no loop.
        if (at == start && loop.size() > 2) loops.push_back(std::move(loop));
    }
    return loops;
}

}  // namespace modsynth::parts
