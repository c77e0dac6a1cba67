#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>

#include <cmath>

namespace modsynth::text {

void OptionCheck::fail(const std::string& message) {
    ok_ = false;
    if (error_) *error_ = message;
}

void OptionCheck::fail(const char* field, double value, const std::string& rule) {
    fail(std::string(owner_) + "::" + field + " = " + format("%.10g", value) + ": " + rule);
}

OptionCheck& OptionCheck::greater(const char* field, double value, double lo) {
    if (!ok_) return *this;
    if (!std::isfinite(value)) {
        fail(field, value, "must be a finite number");
    } else if (value <= lo) {
        fail(field, value, format("must be greater than %.10g", lo));
    }
    return *this;
}

OptionCheck& OptionCheck::at_least(const char* field, double value, double lo) {
    if (!ok_) return *this;
    if (!std::isfinite(value)) {
        fail(field, value, "must be a finite number");
    } else if (value < lo) {
        fail(field, value, format("must be at least %.10g", lo));
    }
    return *this;
}

OptionCheck& OptionCheck::within(const char* field, double value, double lo, double hi) {
    if (!ok_) return *this;
    if (!std::isfinite(value) || value < lo || value > hi)
        fail(field, value, format("must be a number from %.10g to %.10g", lo, hi));
    return *this;
}

OptionCheck& OptionCheck::holds(const char* field, bool ok, const std::string& rule) {
    if (ok_ && !ok) fail(std::string(owner_) + "::" + field + ": " + rule);
    return *this;
}

}  // namespace modsynth::text
