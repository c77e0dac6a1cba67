#include <modsynth/synth/blockers.h>

#include <algorithm>
#include <vector>

#include <modsynth/text/format.h>

namespace modsynth::synth {
namespace {

std::string span(const std::function<std::string(int)>& name, int first, int last) {
    if (first < 0) return "";
    return first == last ? name(first) : name(first) + " to " + name(last);
}

std::string links_of(unsigned links) {
    std::vector<std::string> names;
    for (int k = 0; k < 32; ++k)
        if (links & (1u << k)) names.push_back(std::to_string(k + 1));
    std::string s = names.size() == 1 ? "link " : "links ";
    for (std::size_t i = 0; i < names.size(); ++i)
        s += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return s;
}

}  // namespace

Blockers::Tally& Blockers::tally(int dof, Kind kind, int index, int primitive) {
    Tally& t = by_dof_[dof][{kind, index}];
    ++t.count;
    if (primitive >= 0) {
        t.first = t.first < 0 ? primitive : std::min(t.first, primitive);
        t.last = std::max(t.last, primitive);
    }
    return t;
}

void Blockers::obstacle(int dof, int obstacle, int link, int primitive) {
    Tally& t = tally(dof, Kind::Obstacle, obstacle, primitive);
    if (link >= 0 && link < 32) t.links |= 1u << link;
}

void Blockers::self_collision(int dof, int primitive) {
    tally(dof, Kind::SelfCollision, -1, primitive);
}

void Blockers::out_of_reach(int dof, int primitive, bool transition) {
    tally(dof, transition ? Kind::TransitionReach : Kind::Reach, -1, primitive);
}

void Blockers::no_travel(int dof, int primitive) { tally(dof, Kind::Travel, -1, primitive); }

void Blockers::not_converged(int dof) { tally(dof, Kind::Refinement, -1, -1); }

std::string Blockers::describe_with(const std::function<std::string(int)>& name) const {
    std::string out;
    for (const auto& [dof, tallies] : by_dof_) {
        std::vector<std::pair<std::pair<Kind, int>, Tally>> most(tallies.begin(), tallies.end());
        std::stable_sort(most.begin(), most.end(), [](const auto& a, const auto& b) {
            return a.second.count > b.second.count;
        });
        if (most.size() > 4) most.resize(4);
        std::string said;
        for (const auto& [key, t] : most) {
            const std::string where = span(name, t.first, t.last);
            std::string item;
            switch (key.first) {
                case Kind::Obstacle:
                    item = text::format("obstacles[%d] in the way of ", key.second) +
                           links_of(t.links) + text::format(" (%d, at ", t.count) + where + ")";
                    break;
                case Kind::SelfCollision:
                    item = text::format("the tool too near its own links (%d, at ", t.count) +
                           where + ")";
                    break;
                case Kind::Reach:
                    item = text::format("out of reach (%d, at ", t.count) + where + ")";
                    break;
                case Kind::TransitionReach:
                    item = text::format("out of reach in the transitions (%d, after ", t.count) +
                           where + ")";
                    break;
                case Kind::Travel:
                    item = text::format("no clear travel (%d, after ", t.count) + where + ")";
                    break;
                case Kind::Refinement:
                    item = text::format("refinements that did not converge (%d)", t.count);
                    break;
            }
            said += (said.empty() ? "" : ", ") + item;
        }
        out += (out.empty() ? "" : "; ") + text::format("with %d joints: ", dof) + said;
    }
    return out;
}

}  // namespace modsynth::synth
