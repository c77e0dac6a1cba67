#pragma once
// What a variable or a constraint of a program stands for, as a value: its
// family, the role its maker gave it, and the place (a path point, a
// primitive, a transition pose) with the link and obstacle it concerns. A
// later refinement round's program is matched to the last round's by these
// keys (warm_start.h); labels say the same in words, for people.
#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>

namespace modsynth::nlp {

struct Key {
    /// What kind of variable or constraint it is.
    enum class Family : std::uint8_t {
        None,  ///< not keyed: never matched
        Base,
        LinkLength,  ///< the variable r_k, or |a - b| = r_k
        Elbow,
        Proximal,
        Lambda,
        ElbowSide,
        Bisector,
        Normal,  ///< a separating line's normal (keep_apart)
        Clearance,
        UnitNormal,
        SvNormal,
        SvDisc,
        SvVertex,
        SvPrimitive,
        SvUnit,
        SvArcMiddle,
        SvArcCorner,
        SvArcSide,
        SvTangent,
    };
    /// What the maker of a shared constraint (a link, a separating line)
    /// used it for.
    enum class Role : std::uint8_t {
        None,
        Distal,        ///< the distal pair's links (index 1, 2)
        Proximal,      ///< the proximal link
        SvArcMiddle,   ///< SV^app's arc middle
        LinkObstacle,  ///< link `link` clear of obstacle `obstacle`
        EeToProximal,  ///< the EE clear of link 1
    };
    /// Where along the task: nowhere in particular, a point of a primitive
    /// (`at` in micrometres of arc length), a whole primitive, or a pose of
    /// link 1 in the transition after a primitive (`at` in microradians).
    enum class Place : std::uint8_t { None, Trace, Primitive, Transition };

    Family family = Family::None;
    Role role = Role::None;
    /// The number in the family's name (r_k, distal link 1 or 2, tangent 1
    /// to 4, corner 1 or 2).
    int index = 0;
    /// Of a point or a normal: 0 for x, 1 for y; -1 otherwise.
    int coordinate = -1;
    int link = 0;
    int obstacle = -1;
    Place place = Place::None;
    int primitive = -1;
    std::int64_t at = 0;

    Key at_coordinate(int xy) const {
        Key k = *this;
        k.coordinate = xy;
        return k;
    }

    friend auto operator<=>(const Key&, const Key&) = default;
};

struct KeyHash {
    std::size_t operator()(const Key& k) const noexcept {
        std::size_t h = static_cast<std::size_t>(k.family);
        const auto mix = [&h](std::size_t v) {
            h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
        };
        mix(static_cast<std::size_t>(k.role));
        mix(static_cast<std::size_t>(k.index));
        mix(static_cast<std::size_t>(k.coordinate + 1));
        mix(static_cast<std::size_t>(k.link));
        mix(static_cast<std::size_t>(k.obstacle));
        mix(static_cast<std::size_t>(k.place));
        mix(static_cast<std::size_t>(k.primitive));
        mix(std::hash<std::int64_t>{}(k.at));
        return h;
    }
};

}  // namespace modsynth::nlp
