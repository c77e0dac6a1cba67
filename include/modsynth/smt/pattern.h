#pragma once
// The conditions an arm family puts on its designs for the front stage, in
// a small language of its own: polynomials over named real variables,
// relations between them, and the Boolean connectives. The front stage
// decides them with Z3 over nonlinear real arithmetic; the families write
// them without knowing Z3 (arms/family.h), as one reads them on paper:
//
//     const Term d2 = square(p.x() - base_x) + square(p.y() - base_y);
//     pattern.require({part}, d2 <= square(a1 + a2));
//
// The base's variables are "base_x", "base_y" and "base_z": the front stage
// puts them in the skeleton's base region.
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include <modsynth/task/part.h>

namespace modsynth::smt {

class Term {
public:
    enum class Op { Constant, Variable, Add, Sub, Mul, Neg };
    struct Node {
        Op op = Op::Constant;
        double value = 0.0;
        std::string name;
        std::shared_ptr<const Node> a, b;
    };

    Term(double value);  // NOLINT: numbers read as terms
    static Term variable(std::string name);
    const Node& node() const { return *node_; }
    const std::shared_ptr<const Node>& shared() const { return node_; }

    friend Term operator+(const Term& x, const Term& y);
    friend Term operator-(const Term& x, const Term& y);
    friend Term operator*(const Term& x, const Term& y);
    friend Term operator-(const Term& x);

private:
    explicit Term(std::shared_ptr<const Node> node) : node_(std::move(node)) {}
    std::shared_ptr<const Node> node_;
};

inline Term square(const Term& x) { return x * x; }

class Condition {
public:
    enum class Op { Le, Ge, Eq, And, Or, Not, Boolean, True };
    struct Node {
        Op op = Op::True;
        std::shared_ptr<const Term::Node> left, right;  ///< relations
        std::shared_ptr<const Node> a, b;               ///< connectives
        std::string name;                               ///< Boolean variables
    };

    Condition();  ///< true
    static Condition boolean(std::string name);
    const Node& node() const { return *node_; }
    const std::shared_ptr<const Node>& shared() const { return node_; }

    friend Condition operator<=(const Term& x, const Term& y);
    friend Condition operator>=(const Term& x, const Term& y);
    friend Condition operator==(const Term& x, const Term& y);
    friend Condition operator&&(const Condition& x, const Condition& y);
    friend Condition operator||(const Condition& x, const Condition& y);
    friend Condition operator!(const Condition& x);

private:
    explicit Condition(std::shared_ptr<const Node> node) : node_(std::move(node)) {}
    std::shared_ptr<const Node> node_;
};

// Visible to ordinary lookup, not only through a Condition argument: a
// relation is written between terms.
Condition operator<=(const Term& x, const Term& y);
Condition operator>=(const Term& x, const Term& y);
Condition operator==(const Term& x, const Term& y);

inline Condition implies(const Condition& x, const Condition& y) { return !x || y; }

/// An arm family's conditions on the designs of one skeleton. Each holds
/// where the task parts it comes from are assumed, so that a front stage
/// could name them; the pattern's answer only chooses skeletons.
struct Pattern {
    struct Guarded {
        Condition condition;
        std::vector<task::TaskPart> parts;
    };
    std::vector<Guarded> conditions;
    /// Variables whose values the front stage's model gives back (a coarse
    /// point of the pattern), in this order.
    std::vector<std::string> reported;

    void require(std::initializer_list<task::TaskPart> parts, const Condition& c) {
        conditions.push_back({c, parts});
    }
    void require(const Condition& c) { conditions.push_back({c, {}}); }
};

}  // namespace modsynth::smt
