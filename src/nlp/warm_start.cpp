#include <modsynth/nlp/warm_start.h>

#include <unordered_map>
#include <vector>

namespace modsynth::nlp {

WarmStart carry_over(const QuadraticProgram& from, const SolverResult& solved,
                     const QuadraticProgram& to) {
    WarmStart w;
    w.x = to.start();
    w.z_lower.assign(to.num_variables(), 0.0);
    w.z_upper.assign(to.num_variables(), 0.0);
    w.lambda.assign(to.num_constraints(), 0.0);
    const bool primal = solved.x.size() == static_cast<std::size_t>(from.num_variables());
    const bool dual = primal && solved.z_lower.size() == solved.x.size() &&
                      solved.z_upper.size() == solved.x.size() &&
                      solved.lambda.size() == static_cast<std::size_t>(from.num_constraints());
    if (!primal) return w;
    std::unordered_map<Key, int, KeyHash> variable;
    variable.reserve(from.num_variables());
    for (int i = 0; i < from.num_variables(); ++i)
        if (from.variable_key(i).family != Key::Family::None)
            variable.emplace(from.variable_key(i), i);
    for (int i = 0; i < to.num_variables(); ++i) {
        const auto it = variable.find(to.variable_key(i));
        if (it == variable.end()) continue;
        w.x[i] = solved.x[it->second];
        if (dual)
            w.z_lower[i] = solved.z_lower[it->second], w.z_upper[i] = solved.z_upper[it->second];
    }
    if (!dual) return w;
    // Keys repeat (both ends of a separating line share one): the k-th of
    // a key matches the k-th.
    std::unordered_map<Key, std::vector<int>, KeyHash> constraint;
    for (int k = 0; k < from.num_constraints(); ++k)
        if (from.constraint_key(k).family != Key::Family::None)
            constraint[from.constraint_key(k)].push_back(k);
    std::unordered_map<Key, std::size_t, KeyHash> used;
    for (int k = 0; k < to.num_constraints(); ++k) {
        const auto it = constraint.find(to.constraint_key(k));
        if (it == constraint.end()) continue;
        std::size_t& next = used[it->first];
        if (next < it->second.size()) w.lambda[k] = solved.lambda[it->second[next++]];
    }
    return w;
}

}  // namespace modsynth::nlp
