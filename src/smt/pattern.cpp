#include <modsynth/smt/pattern.h>

#include <utility>

namespace modsynth::smt {
namespace {

std::shared_ptr<const Term::Node> term_node(Term::Op op, std::shared_ptr<const Term::Node> a,
                                            std::shared_ptr<const Term::Node> b = nullptr) {
    auto n = std::make_shared<Term::Node>();
    n->op = op;
    n->a = std::move(a);
    n->b = std::move(b);
    return n;
}

std::shared_ptr<const Term::Node> share(const Term& t) { return t.shared(); }

std::shared_ptr<const Condition::Node> relation(Condition::Op op, const Term& x, const Term& y) {
    auto n = std::make_shared<Condition::Node>();
    n->op = op;
    n->left = share(x);
    n->right = share(y);
    return n;
}

std::shared_ptr<const Condition::Node> connective(Condition::Op op, const Condition& x,
                                                  const Condition* y) {
    auto n = std::make_shared<Condition::Node>();
    n->op = op;
    n->a = x.shared();
    if (y) n->b = y->shared();
    return n;
}

}  // namespace

Term::Term(double value) {
    auto n = std::make_shared<Node>();
    n->value = value;
    node_ = std::move(n);
}

Term Term::variable(std::string name) {
    auto n = std::make_shared<Node>();
    n->op = Op::Variable;
    n->name = std::move(name);
    return Term(std::shared_ptr<const Node>(std::move(n)));
}

Term operator+(const Term& x, const Term& y) {
    return Term(term_node(Term::Op::Add, share(x), share(y)));
}
Term operator-(const Term& x, const Term& y) {
    return Term(term_node(Term::Op::Sub, share(x), share(y)));
}
Term operator*(const Term& x, const Term& y) {
    return Term(term_node(Term::Op::Mul, share(x), share(y)));
}
Term operator-(const Term& x) { return Term(term_node(Term::Op::Neg, share(x))); }

Condition::Condition() : node_(std::make_shared<Node>()) {}

Condition Condition::boolean(std::string name) {
    auto n = std::make_shared<Node>();
    n->op = Op::Boolean;
    n->name = std::move(name);
    return Condition(std::shared_ptr<const Node>(std::move(n)));
}

Condition operator<=(const Term& x, const Term& y) {
    return Condition(relation(Condition::Op::Le, x, y));
}
Condition operator>=(const Term& x, const Term& y) {
    return Condition(relation(Condition::Op::Ge, x, y));
}
Condition operator==(const Term& x, const Term& y) {
    return Condition(relation(Condition::Op::Eq, x, y));
}
Condition operator&&(const Condition& x, const Condition& y) {
    return Condition(connective(Condition::Op::And, x, &y));
}
Condition operator||(const Condition& x, const Condition& y) {
    return Condition(connective(Condition::Op::Or, x, &y));
}
Condition operator!(const Condition& x) {
    return Condition(connective(Condition::Op::Not, x, nullptr));
}

}  // namespace modsynth::smt
