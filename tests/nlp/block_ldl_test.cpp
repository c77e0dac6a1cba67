#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

#include <modsynth/nlp/block_ldl.h>
#include <modsynth/nlp/quadratic_program.h>
#include <modsynth/nlp/solver.h>

using namespace modsynth;
namespace ldl = nlp::ldl;

namespace {

// A symmetric matrix as lower-triangle triplets and as a dense copy.
struct Matrix {
    int n = 0;
    std::vector<int> rows, cols;
    std::vector<double> values;
    Eigen::MatrixXd dense;

    explicit Matrix(int size) : n(size), dense(Eigen::MatrixXd::Zero(size, size)) {}
    void add(int i, int j, double v) {
        rows.push_back(i);
        cols.push_back(j);
        values.push_back(v);
        dense(i, j) += v;
        if (i != j) dense(j, i) += v;
    }
    ldl::SymmetricTriplets triplets() const { return {n, rows, cols, values, 0}; }
    ldl::SymmetricTriplets pattern() const { return {n, rows, cols, {}, 0}; }
    int negative_eigenvalues() const {
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(dense);
        return static_cast<int>((eigen.eigenvalues().array() < 0.0).count());
    }
};

// An interior-point KKT matrix [H J'; J 0] with `nv` variables and `nc`
// constraints of three variables each; H is diagonal plus a few couplings,
// with `h_shift` moving its diagonal (negative: H indefinite). The
// constraint block's diagonal is given, as zeros, like Ipopt's.
Matrix kkt(std::mt19937& rng, int nv, int nc, double h_shift) {
    std::normal_distribution<double> normal;
    Matrix m(nv + nc);
    for (int i = 0; i < nv; ++i) m.add(i, i, std::fabs(normal(rng)) + h_shift);
    for (int i = 1; i < nv; i += 3) m.add(i, i - 1, 0.3 * normal(rng));
    for (int k = 0; k < nc; ++k) {
        m.add(nv + k, nv + k, 0.0);
        for (int t = 0; t < 3; ++t) m.add(nv + k, (5 * k + 7 * t) % nv, normal(rng));
    }
    return m;
}

struct Factored {
    std::vector<int> order, ints;
    std::vector<double> reals;
    ldl::Factorization result;
};

Factored factor(const Matrix& m) {
    Factored f;
    f.order.resize(ldl::order_size(m.n));
    const ldl::Workspace w = ldl::choose_order(m.pattern(), f.order);
    // Pairing rows changes the factor's size: room for what it may need.
    f.ints.resize(4 * w.ints);
    f.reals.resize(4 * w.reals);
    f.result = ldl::factorize(m.triplets(), f.order, f.ints, f.reals);
    return f;
}

double residual(const Matrix& m, const Factored& f, const Eigen::VectorXd& b) {
    std::vector<double> x(b.data(), b.data() + m.n), work(m.n);
    ldl::solve(f.ints, f.reals, x, work);
    const Eigen::Map<const Eigen::VectorXd> solution(x.data(), m.n);
    return (m.dense * solution - b).norm() / b.norm();
}

}  // namespace

TEST_CASE("the block LDLt solves KKT matrices and counts their negative eigenvalues", "[nlp]") {
    std::mt19937 rng(7);
    for (double shift : {0.1, 1.0, -0.4}) {
        for (int trial = 0; trial < 10; ++trial) {
            const Matrix m = kkt(rng, 40, 15, shift);
            const Factored f = factor(m);
            INFO("shift " << shift << ", trial " << trial);
            REQUIRE(f.result.status == ldl::Factorization::Status::Ok);
            CHECK(f.result.regularized == 0);
            CHECK(f.result.negative == m.negative_eigenvalues());
            // Every zero diagonal made the order be chosen again, with pairs.
            CHECK(f.result.reordered);
            CHECK(residual(m, f, Eigen::VectorXd::Random(m.n)) < 1e-10);
        }
    }
}

TEST_CASE("the block LDLt keeps its order while the pattern and the pairs hold", "[nlp]") {
    std::mt19937 rng(11);
    Matrix m = kkt(rng, 30, 10, 0.5);
    Factored f = factor(m);
    REQUIRE(f.result.status == ldl::Factorization::Status::Ok);
    // New values in the same places: the order is reused, the answer exact.
    for (double& v : m.values) v *= 1.5;
    m.dense *= 1.5;
    f.result = ldl::factorize(m.triplets(), f.order, f.ints, f.reals);
    REQUIRE(f.result.status == ldl::Factorization::Status::Ok);
    CHECK_FALSE(f.result.reordered);
    CHECK(f.result.negative == m.negative_eigenvalues());
    CHECK(residual(m, f, Eigen::VectorXd::Random(m.n)) < 1e-10);
}

TEST_CASE("a slack beside its constraint is a pivot pair, not a singular one", "[nlp]") {
    // [s -1; -1 0] with a huge barrier term s: eigenvalues s and -1/s, but
    // the inverse [0 -1; -1 -s] is exact, so nothing is replaced.
    Matrix m(3);
    m.add(0, 0, 2.5e7);
    m.add(1, 1, 0.0);
    m.add(1, 0, -1.0);
    m.add(2, 2, 1.0);
    m.add(2, 1, 0.5);
    const Factored f = factor(m);
    REQUIRE(f.result.status == ldl::Factorization::Status::Ok);
    CHECK(f.result.regularized == 0);
    CHECK(f.result.negative == 1);
    // Relative to b; the solution is about s times larger than b, so this
    // is a backward error near machine precision.
    CHECK(residual(m, f, Eigen::Vector3d(1.0, -2.0, 0.5)) < 1e-8);
}

TEST_CASE("a singular matrix is factorized with its null pivots replaced", "[nlp]") {
    // Two equal rows: rank 2 of 3.
    Matrix m(3);
    m.add(0, 0, 1.0);
    m.add(1, 0, 1.0);
    m.add(1, 1, 1.0);
    m.add(2, 2, 2.0);
    const Factored f = factor(m);
    REQUIRE(f.result.status == ldl::Factorization::Status::Ok);
    CHECK(f.result.regularized == 1);
    std::vector<double> x{1.0, 1.0, 1.0}, work(3);
    ldl::solve(f.ints, f.reals, x, work);
    for (double v : x) CHECK(std::isfinite(v));
    CHECK(x[2] == Approx(0.5));
}

TEST_CASE("the block LDLt asks for room it lacks and rejects bad indices", "[nlp]") {
    std::mt19937 rng(3);
    const Matrix m = kkt(rng, 20, 8, 1.0);
    std::vector<int> order(ldl::order_size(m.n));
    ldl::choose_order(m.pattern(), order);
    std::vector<int> ints(4);
    std::vector<double> reals(4);
    ldl::Factorization f = ldl::factorize(m.triplets(), order, ints, reals);
    REQUIRE(f.status == ldl::Factorization::Status::NeedInts);
    ints.resize(f.needed.ints);
    f = ldl::factorize(m.triplets(), order, ints, reals);
    REQUIRE(f.status == ldl::Factorization::Status::NeedReals);
    reals.resize(f.needed.reals);
    f = ldl::factorize(m.triplets(), order, ints, reals);
    REQUIRE(f.status == ldl::Factorization::Status::Ok);
    CHECK(f.negative == m.negative_eigenvalues());

    const std::vector<int> rows{0, 5}, cols{0, 0};  // row 5 of a 2×2 matrix
    const std::vector<double> values{1.0, 1.0};
    std::vector<int> bad_order(ldl::order_size(2));
    CHECK(ldl::choose_order({2, rows, cols, {}, 0}, bad_order).ints == 0);
    CHECK(ldl::factorize({2, rows, cols, values, 0}, bad_order, ints, reals).status ==
          ldl::Factorization::Status::BadIndex);
}

TEST_CASE("an order the caller's memory scrambled is chosen again", "[nlp]") {
    std::mt19937 rng(5);
    const Matrix m = kkt(rng, 25, 9, 1.0);
    Factored f = factor(m);
    REQUIRE(f.result.status == ldl::Factorization::Status::Ok);
    std::fill(f.order.begin(), f.order.end(), 3);  // not a permutation
    f.result = ldl::factorize(m.triplets(), f.order, f.ints, f.reals);
    REQUIRE(f.result.status == ldl::Factorization::Status::Ok);
    CHECK(f.result.reordered);
    CHECK(residual(m, f, Eigen::VectorXd::Random(m.n)) < 1e-10);
}

TEST_CASE("Ipopt's MA27 is the block LDLt and agrees with MUMPS", "[nlp]") {
    REQUIRE(ldl::serves_as_ma27());
    // min (x - 2)^2 + (y - 1)^2 + z on the unit disc, z >= 0.5, z^2 <= 9.
    nlp::QuadraticProgram qp;
    const int z = qp.add_variable(0.5, 3.0, 2.0, "z");
    const int x = qp.add_variable(-nlp::kInfinity, nlp::kInfinity, 0.0, "x");
    const int y = qp.add_variable(-nlp::kInfinity, nlp::kInfinity, 0.0, "y");
    qp.set_objective(
        nlp::Quadratic{}.add(5.0).add(x, x, 1.0).add(x, -4.0).add(y, y, 1.0).add(y, -2.0).add(z,
                                                                                              1.0));
    qp.add_constraint(nlp::Quadratic{}.add(z, z, 1.0), 0.0, 9.0, "z box");
    qp.add_constraint(nlp::Quadratic{}.add(x, x, 1.0).add(y, y, 1.0), -nlp::kInfinity, 1.0, "disc");
    qp.add_constraint(nlp::Quadratic{}.add(x, 1.0).add(y, -2.0), 0.0, 0.0, "line");
    qp.finalize();
    nlp::SolverOptions block, mumps;
    mumps.linear_solver = nlp::SolverOptions::LinearSolver::Mumps;
    const nlp::SolverResult a = nlp::minimize(qp, block), b = nlp::minimize(qp, mumps);
    REQUIRE(a.usable());
    REQUIRE(b.usable());
    // x = 2y on the disc's rim, nearest (2, 1): (2, 1)/sqrt(5).
    CHECK(a.x[x] == Approx(2.0 / std::sqrt(5.0)).margin(1e-6));
    CHECK(a.x[y] == Approx(1.0 / std::sqrt(5.0)).margin(1e-6));
    CHECK(a.x[z] == Approx(0.5).margin(1e-6));
    for (int i = 0; i < 3; ++i) CHECK(a.x[i] == Approx(b.x[i]).margin(1e-6));
}
