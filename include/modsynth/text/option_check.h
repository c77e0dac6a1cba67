#pragma once
// Validation of a stage's options, after Ceres' Solver::Options::IsValid:
// every options struct has `bool IsValid(std::string* error) const`, which
// on a bad value writes one line naming the struct, the field, its value
// and the rule it breaks ("SolverOptions::max_iterations = 0: must be at
// least 1"), and returns false. Each stage calls require_valid() on entry,
// so a bad value stops the run before any work with an exception that names
// it, instead of a solver misbehaving later.
#include <stdexcept>
#include <string>

namespace modsynth::text {

/// Collects the first broken rule of one options struct. Every check after
/// a failed one is skipped, so the message names exactly one field.
class OptionCheck {
public:
    /// `owner` names the struct ("SolverOptions"); `error` may be null.
    OptionCheck(const char* owner, std::string* error) : owner_(owner), error_(error) {}

    /// A finite number greater than `lo`.
    OptionCheck& greater(const char* field, double value, double lo);
    /// A finite number of at least `lo`.
    OptionCheck& at_least(const char* field, double value, double lo);
    /// A finite number in [lo, hi].
    OptionCheck& within(const char* field, double value, double lo, double hi);
    /// Any other rule: `rule` says what the field must be.
    OptionCheck& holds(const char* field, bool ok, const std::string& rule);
    /// A member that is itself an options struct: its own message, prefixed
    /// with this struct and field.
    template <typename Nested>
    OptionCheck& nested(const char* field, const Nested& options) {
        std::string inner;
        if (ok_ && !options.IsValid(&inner))
            fail(std::string(owner_) + "::" + field + ": " + inner);
        return *this;
    }

    bool ok() const { return ok_; }

private:
    void fail(const std::string& message);
    void fail(const char* field, double value, const std::string& rule);

    const char* owner_;
    std::string* error_;
    bool ok_ = true;
};

/// Throws std::invalid_argument with the options' own message when they
/// are not valid.
template <typename Options>
void require_valid(const Options& options) {
    std::string error;
    if (!options.IsValid(&error)) throw std::invalid_argument(error);
}

}  // namespace modsynth::text
