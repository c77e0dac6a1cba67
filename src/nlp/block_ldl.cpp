#include <modsynth/nlp/block_ldl.h>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace modsynth::nlp::ldl {
namespace {

// A diagonal below this share of its row's largest off-diagonal entry is
// treated as zero when choosing pivots: such a row (a constraint row of a
// KKT matrix) cannot be a 1×1 pivot of its own.
constexpr double kNegligibleDiagonal = 1e-6;
// A pivot eigenvalue below kTinyPivot times the largest entry of its rows
// is replaced by kPivotFloor times that entry, with its sign (negative for
// an exact zero, as on a constraint row).
constexpr double kTinyPivot = 1e-13;
constexpr double kPivotFloor = 1e-9;

// A pivot block or a block of L, at most 2×2, row-major; a 1×1 block keeps
// zeros in its unused row and column, so one product serves every size.
using Block = std::array<double, 4>;

Block mul(const Block& a, const Block& b) {
    return {a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2],
            a[2] * b[1] + a[3] * b[3]};
}
Block transposed(const Block& a) { return {a[0], a[2], a[1], a[3]}; }
void subtract(Block& into, const Block& b) {
    for (int i = 0; i < 4; ++i) into[i] -= b[i];
}

// Layout of the order span: the row at each position, the block size at
// each position (2: a pair starts here, 0: the pair's second row, 1: a
// single row), and each row's partner (another row, kNoPartner, or
// kUnmatched for a negligible diagonal that no neighbour could take).
constexpr int kNoPartner = -1;
constexpr int kUnmatched = -2;
struct OrderView {
    int n;
    std::span<int> all;
    int& row_at(int p) { return all[p]; }
    int& block_at(int p) { return all[n + p]; }
    int& partner(int r) { return all[2 * n + r]; }
};

// Layout of the factor: n, number of blocks, stored blocks of L, then the
// row at each position, where each block starts, where each block column
// of L starts, and the block row of each stored block of L.
constexpr std::size_t kHeader = 3;
std::size_t ints_needed(int n, int blocks, long stored) {
    return kHeader + n + 2 * static_cast<std::size_t>(blocks + 1) + stored;
}
std::size_t reals_needed(int blocks, long stored) {
    return 4 * (blocks + static_cast<std::size_t>(stored));
}

// Scratch reused across calls: sized by the matrix, holding nothing a later
// call depends on. Each function binds it once as `s`: a thread_local in a
// shared library costs a __tls_get_addr call per access, which showed in
// the inner loops.
struct Scratch {
    std::vector<int> position, block_of, start;
    std::vector<int> cp, ci, cslot;
    std::vector<double> cx;
    std::vector<int> parent, count, flag, pattern;
    std::vector<Block> y;
    // pairing
    std::vector<double> diagonal, row_max, adj_value;
    std::vector<int> adj_start, adj, owner, seen, via, queue, super, first, second;
};
thread_local Scratch scratch;

int index_of(const SymmetricTriplets& m, std::span<const int> v, std::size_t t) {
    return v[t] - m.base;
}

bool indices_valid(const SymmetricTriplets& m) {
    for (std::size_t t = 0; t < m.rows.size(); ++t) {
        const int r = index_of(m, m.rows, t), c = index_of(m, m.cols, t);
        if (r < 0 || r >= m.n || c < 0 || c >= m.n) return false;
    }
    return true;
}

// Block structure of the order: block of each position and block starts.
int block_structure(OrderView order) {
    Scratch& s = scratch;
    const int n = order.n;
    s.block_of.resize(n);
    s.start.clear();
    for (int p = 0; p < n; ++p) {
        if (order.block_at(p) != 0) s.start.push_back(p);
        s.block_of[p] = static_cast<int>(s.start.size()) - 1;
    }
    s.start.push_back(n);
    s.position.resize(n);
    for (int p = 0; p < n; ++p) s.position[order.row_at(p)] = p;
    return static_cast<int>(s.start.size()) - 1;
}

// The upper block triangle in block columns: for each entry its block row,
// its slot in the 2×2 block (row * 2 + column), and its value.
void upper_blocks(const SymmetricTriplets& m, int blocks) {
    Scratch& s = scratch;
    const std::size_t nz = m.rows.size();
    s.cp.assign(blocks + 1, 0);
    s.ci.resize(nz);
    s.cslot.resize(nz);
    s.cx.resize(nz);
    auto place = [&](std::size_t t, int& column, int& row, int& slot) {
        int pr = s.position[index_of(m, m.rows, t)], pc = s.position[index_of(m, m.cols, t)];
        if (s.block_of[pr] > s.block_of[pc]) std::swap(pr, pc);
        row = s.block_of[pr];
        column = s.block_of[pc];
        slot = (pr - s.start[row]) * 2 + (pc - s.start[column]);
    };
    for (std::size_t t = 0; t < nz; ++t) {
        int column, row, slot;
        place(t, column, row, slot);
        ++s.cp[column + 1];
    }
    for (int k = 0; k < blocks; ++k) s.cp[k + 1] += s.cp[k];
    std::vector<int>& next = s.pattern;
    next.assign(s.cp.begin(), s.cp.end() - 1);
    for (std::size_t t = 0; t < nz; ++t) {
        int column, row, slot;
        place(t, column, row, slot);
        const int p = next[column]++;
        s.ci[p] = row;
        s.cslot[p] = slot;
        s.cx[p] = m.values.empty() ? 0.0 : m.values[t];
    }
}

// Elimination tree of the blocks and the number of stored blocks in each
// block column of L.
long block_symbolic(int blocks) {
    Scratch& s = scratch;
    s.parent.assign(blocks, -1);
    s.count.assign(blocks, 0);
    s.flag.assign(blocks, -1);
    for (int k = 0; k < blocks; ++k) {
        s.flag[k] = k;
        for (int p = s.cp[k]; p < s.cp[k + 1]; ++p)
            for (int i = s.ci[p]; s.flag[i] != k; i = s.parent[i]) {
                if (s.parent[i] == -1) s.parent[i] = k;
                ++s.count[i];
                s.flag[i] = k;
            }
    }
    long stored = 0;
    for (int k = 0; k < blocks; ++k) stored += s.count[k];
    return stored;
}

Workspace workspace_for(const SymmetricTriplets& m, OrderView order) {
    const int blocks = block_structure(order);
    upper_blocks(m, blocks);
    const long stored = block_symbolic(blocks);
    return {ints_needed(m.n, blocks, stored), reals_needed(blocks, stored)};
}

// Approximate minimum degree over groups of rows (a pair is one node).
void amd_over_groups(const SymmetricTriplets& m, int groups, OrderView order) {
    Scratch& s = scratch;
    std::vector<Eigen::Triplet<double, int>> entries;
    entries.reserve(m.rows.size() + groups);
    for (std::size_t t = 0; t < m.rows.size(); ++t)
        entries.emplace_back(s.super[index_of(m, m.rows, t)], s.super[index_of(m, m.cols, t)], 1.0);
    for (int g = 0; g < groups; ++g) entries.emplace_back(g, g, 1.0);
    Eigen::SparseMatrix<double, Eigen::ColMajor, int> graph(groups, groups);
    graph.setFromTriplets(entries.begin(), entries.end());
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> eliminated;
    Eigen::AMDOrdering<int>()(graph, eliminated);  // indices()[k]: the group eliminated k-th
    int p = 0;
    for (int k = 0; k < groups; ++k) {
        const int g = eliminated.indices()[k];
        const bool pair = s.second[g] >= 0;
        order.row_at(p) = s.first[g];
        order.block_at(p++) = pair ? 2 : 1;
        if (pair) {
            order.row_at(p) = s.second[g];
            order.block_at(p++) = 0;
        }
    }
}

void ungrouped(int n) {
    Scratch& s = scratch;
    s.super.resize(n);
    s.first.resize(n);
    s.second.assign(n, -1);
    for (int r = 0; r < n; ++r) s.super[r] = s.first[r] = r;
}

// Diagonal, largest off-diagonal entry per row and adjacency, from values.
void read_rows(const SymmetricTriplets& m) {
    Scratch& s = scratch;
    const int n = m.n;
    s.diagonal.assign(n, 0.0);
    s.row_max.assign(n, 0.0);
    s.adj_start.assign(n + 1, 0);
    for (std::size_t t = 0; t < m.rows.size(); ++t) {
        const int r = index_of(m, m.rows, t), c = index_of(m, m.cols, t);
        if (r == c) {
            s.diagonal[r] += m.values[t];
            continue;
        }
        ++s.adj_start[r + 1];
        ++s.adj_start[c + 1];
        s.row_max[r] = std::max(s.row_max[r], std::fabs(m.values[t]));
        s.row_max[c] = std::max(s.row_max[c], std::fabs(m.values[t]));
    }
    for (int k = 0; k < n; ++k) s.adj_start[k + 1] += s.adj_start[k];
    s.adj.resize(s.adj_start[n]);
    s.adj_value.resize(s.adj_start[n]);
    std::vector<int>& next = s.pattern;
    next.assign(s.adj_start.begin(), s.adj_start.end() - 1);
    for (std::size_t t = 0; t < m.rows.size(); ++t) {
        const int r = index_of(m, m.rows, t), c = index_of(m, m.cols, t);
        if (r == c) continue;
        const double v = std::fabs(m.values[t]);
        s.adj[next[r]] = c;
        s.adj_value[next[r]++] = v;
        s.adj[next[c]] = r;
        s.adj_value[next[c]++] = v;
    }
}

// An entry that can hold a pair together: not negligible in its row.
constexpr double kPairEntry = 1e-3;
bool pairs_with(const Scratch& s, int r, double entry) { return entry > kPairEntry * s.row_max[r]; }

bool negligible_diagonal(const Scratch& s, int r) {
    return s.row_max[r] > 0.0 && std::fabs(s.diagonal[r]) <= kNegligibleDiagonal * s.row_max[r];
}

// Pairs every row with a negligible diagonal with a neighbour: first with
// rows of a proper diagonal, as a maximum matching (greedy by entry size,
// then augmenting paths), then what is left with one another.
void pair_rows(OrderView order) {
    Scratch& s = scratch;
    const int n = order.n;
    s.owner.assign(n, -1);
    for (int r = 0; r < n; ++r) {
        order.partner(r) = kNoPartner;
        if (!negligible_diagonal(s, r)) continue;
        order.partner(r) = kUnmatched;
        int best = -1;
        double best_value = 0.0;
        for (int p = s.adj_start[r]; p < s.adj_start[r + 1]; ++p) {
            const int v = s.adj[p];
            if (negligible_diagonal(s, v) || s.owner[v] >= 0 || s.adj_value[p] <= best_value ||
                !pairs_with(s, r, s.adj_value[p]))
                continue;
            best = v;
            best_value = s.adj_value[p];
        }
        if (best >= 0) {
            s.owner[best] = r;
            order.partner(r) = best;
        }
    }
    s.seen.assign(n, -1);
    s.via.assign(n, -1);
    for (int root = 0; root < n; ++root) {
        if (order.partner(root) != kUnmatched) continue;
        s.queue.assign(1, root);
        int free_row = -1;
        for (std::size_t h = 0; h < s.queue.size() && free_row < 0; ++h) {
            const int r = s.queue[h];
            for (int p = s.adj_start[r]; p < s.adj_start[r + 1]; ++p) {
                const int v = s.adj[p];
                if (negligible_diagonal(s, v) || s.seen[v] == root ||
                    !pairs_with(s, r, s.adj_value[p]))
                    continue;
                s.seen[v] = root;
                s.via[v] = r;
                if (s.owner[v] < 0) {
                    free_row = v;
                    break;
                }
                s.queue.push_back(s.owner[v]);
            }
        }
        // Flip the path: each row on it takes the proper row before it.
        for (int v = free_row; v >= 0;) {
            const int r = s.via[v];
            const int previous = order.partner(r) >= 0 ? order.partner(r) : -1;
            s.owner[v] = r;
            order.partner(r) = v;
            v = r == root ? -1 : previous;
        }
    }
    for (int v = 0; v < n; ++v)
        if (s.owner[v] >= 0) order.partner(v) = s.owner[v];
    for (int r = 0; r < n; ++r) {
        if (order.partner(r) != kUnmatched) continue;
        for (int p = s.adj_start[r]; p < s.adj_start[r + 1]; ++p) {
            const int v = s.adj[p];
            if (v != r && order.partner(v) == kUnmatched && pairs_with(s, r, s.adj_value[p]) &&
                pairs_with(s, v, s.adj_value[p])) {
                order.partner(r) = v;
                order.partner(v) = r;
                break;
            }
        }
    }
    s.super.assign(n, -1);
    s.first.clear();
    s.second.clear();
    for (int r = 0; r < n; ++r) {
        if (s.super[r] >= 0) continue;
        const int mate = order.partner(r);
        s.super[r] = static_cast<int>(s.first.size());
        s.first.push_back(r);
        s.second.push_back(mate >= 0 ? mate : -1);
        if (mate >= 0) s.super[mate] = s.super[r];
    }
}

// The order still serves while it is one (the caller's memory may hold
// anything), every negligible diagonal has its partner (or had none to
// take) and every pair is adjacent in it.
bool order_serves(OrderView order) {
    Scratch& s = scratch;
    const int n = order.n;
    s.flag.assign(n, 0);
    for (int p = 0; p < n; ++p) {
        const int r = order.row_at(p), b = order.block_at(p);
        if (r < 0 || r >= n || s.flag[r]++ || b < 0 || b > 2) return false;
        if ((b == 2) != (p + 1 < n && order.block_at(p + 1) == 0)) return false;
        if (b == 0 && (p == 0 || order.block_at(p - 1) != 2)) return false;
        const int mate = order.partner(r);
        if (mate < kUnmatched || mate >= n) return false;
        if ((b == 2 && mate != order.row_at(p + 1)) || (b == 0 && mate != order.row_at(p - 1)) ||
            (b == 1 && mate >= 0))
            return false;
    }
    for (int r = 0; r < n; ++r) {
        const int mate = order.partner(r);
        if (negligible_diagonal(s, r) && mate == kNoPartner) return false;
        if (mate >= 0 && order.partner(mate) != r) return false;
    }
    return true;
}

// Inverse of a symmetric pivot block of `size` rows, with eigenvalues below
// `tiny` replaced by ±`floor`. Counts its negative eigenvalues.
Block invert_pivot(const Block& d, int size, double tiny, double floor, int& negative,
                   int& regularized) {
    bool replaced = false;
    auto fix = [&](double lambda, double below) {
        if (std::fabs(lambda) > below) return lambda;
        replaced = true;
        return lambda > 0.0 ? floor : -floor;
    };
    if (size == 1) {
        const double v = fix(d[0], tiny);
        negative += v < 0.0;
        regularized += replaced;
        return {1.0 / v, 0.0, 0.0, 0.0};
    }
    const double p = d[0], q = 0.5 * (d[1] + d[2]), r = d[3];
    const double mean = 0.5 * (p + r), half = std::hypot(0.5 * (p - r), q);
    // The eigenvalue of larger size directly, the other from the
    // determinant: mean - half would cancel when one diagonal is large.
    const double det = p * r - q * q;
    const double big = mean >= 0.0 ? mean + half : mean - half;
    const double little = big != 0.0 ? det / big : 0.0;
    // Singular in working precision: the determinant cancelled, or the
    // coupling that made the pair is gone and an eigenvalue with it. A
    // large diagonal beside a small eigenvalue is fine (a slack and its
    // constraint: the inverse is exact).
    const bool cancelled = std::fabs(det) <= kTinyPivot * std::max(std::fabs(p * r), q * q);
    const bool uncoupled = q * q <= tiny * tiny / kTinyPivot && std::fabs(little) <= tiny;
    if (!cancelled && !uncoupled) {
        negative += (big < 0.0) + (little < 0.0);
        return {r / det, -q / det, -q / det, p / det};
    }
    const double theta = 0.5 * std::atan2(2.0 * q, p - r);
    const double c = std::cos(theta), sn = std::sin(theta);
    // along (c, sn): mean + half; along (-sn, c): mean - half
    const double below = std::max(tiny, kTinyPivot * std::fabs(big));
    const double a = fix(mean >= 0.0 ? big : little, below);
    const double b = fix(mean >= 0.0 ? little : big, below);
    negative += (a < 0.0) + (b < 0.0);
    regularized += replaced;
    return {c * c / a + sn * sn / b, c * sn / a - sn * c / b, c * sn / a - sn * c / b,
            sn * sn / a + c * c / b};
}

Factorization numeric(const SymmetricTriplets& m, OrderView order, std::span<int> ints,
                      std::span<double> reals) {
    Scratch& s = scratch;
    const int n = m.n;
    const int blocks = block_structure(order);
    upper_blocks(m, blocks);
    const long stored = block_symbolic(blocks);
    Factorization f;
    f.needed = {ints_needed(n, blocks, stored), reals_needed(blocks, stored)};
    if (f.needed.ints > ints.size()) {
        f.status = Factorization::Status::NeedInts;
        return f;
    }
    if (f.needed.reals > reals.size()) {
        f.status = Factorization::Status::NeedReals;
        return f;
    }

    ints[0] = n;
    ints[1] = blocks;
    ints[2] = static_cast<int>(stored);
    int* row_at = ints.data() + kHeader;
    int* start = row_at + n;
    int* lp = start + blocks + 1;
    int* li = lp + blocks + 1;
    for (int p = 0; p < n; ++p) row_at[p] = order.row_at(p);
    std::copy(s.start.begin(), s.start.end(), start);
    lp[0] = 0;
    for (int k = 0; k < blocks; ++k) lp[k + 1] = lp[k] + s.count[k];
    auto* dinv = reinterpret_cast<Block*>(reals.data());
    Block* lx = dinv + blocks;

    s.y.assign(blocks, Block{});
    s.pattern.resize(blocks);
    s.flag.assign(blocks, -1);
    std::vector<int>& filled = s.count;
    std::fill(filled.begin(), filled.end(), 0);
    for (int k = 0; k < blocks; ++k) {
        // Scatter block column k of the upper triangle and find which block
        // rows of L row k are nonzero (its reach in the elimination tree),
        // in an order where each comes after those it depends on.
        int top = blocks;
        s.flag[k] = k;
        for (int p = s.cp[k]; p < s.cp[k + 1]; ++p) {
            int i = s.ci[p];
            const int slot = s.cslot[p];
            s.y[i][slot] += s.cx[p];
            if (i == k && slot == 1) s.y[k][2] += s.cx[p];
            if (i == k && slot == 2) s.y[k][1] += s.cx[p];
            int length = 0;
            for (; s.flag[i] != k; i = s.parent[i]) {
                s.pattern[length++] = i;
                s.flag[i] = k;
            }
            while (length > 0) s.pattern[--top] = s.pattern[--length];
        }
        Block d = s.y[k];
        s.y[k] = Block{};
        for (; top < blocks; ++top) {
            const int i = s.pattern[top];
            const Block yi = s.y[i];
            s.y[i] = Block{};
            const int end = lp[i] + filled[i];
            for (int p = lp[i]; p < end; ++p) subtract(s.y[li[p]], mul(lx[p], yi));
            const Block l = transposed(mul(dinv[i], yi));
            subtract(d, mul(l, yi));
            li[end] = k;
            lx[end] = l;
            ++filled[i];
        }
        // The size of the block's rows: the smaller, for a pair, so that a
        // slack's large diagonal does not make its constraint look tiny.
        double scale = std::numeric_limits<double>::infinity();
        for (int p = start[k]; p < start[k + 1]; ++p) {
            const int r = row_at[p];
            scale = std::min(scale, std::max(std::fabs(s.diagonal[r]), s.row_max[r]));
        }
        dinv[k] =
            invert_pivot(d, start[k + 1] - start[k], kTinyPivot * scale,
                         kPivotFloor * (scale > 0.0 ? scale : 1.0), f.negative, f.regularized);
    }
    return f;
}

}  // namespace

std::size_t order_size(int n) { return 3 * static_cast<std::size_t>(n); }

Workspace choose_order(const SymmetricTriplets& pattern, std::span<int> order_span) {
    OrderView order{pattern.n, order_span};
    if (!indices_valid(pattern) || order_span.size() < order_size(pattern.n)) return {};
    ungrouped(pattern.n);
    amd_over_groups(pattern, pattern.n, order);
    for (int r = 0; r < pattern.n; ++r) order.partner(r) = kNoPartner;
    return workspace_for(pattern, order);
}

Factorization factorize(const SymmetricTriplets& matrix, std::span<int> order_span,
                        std::span<int> ints, std::span<double> reals) {
    Scratch& s = scratch;
    OrderView order{matrix.n, order_span};
    if (!indices_valid(matrix) || matrix.values.size() != matrix.rows.size() ||
        order_span.size() < order_size(matrix.n)) {
        Factorization bad;
        bad.status = Factorization::Status::BadIndex;
        return bad;
    }
    read_rows(matrix);
    bool reordered = false;
    if (!order_serves(order)) {
        pair_rows(order);
        amd_over_groups(matrix, static_cast<int>(s.first.size()), order);
        reordered = true;
    }
    Factorization f = numeric(matrix, order, ints, reals);
    if (f.status == Factorization::Status::Ok && f.regularized > 0 && !reordered) {
        // The pairs were chosen for earlier values: choose again for these.
        pair_rows(order);
        amd_over_groups(matrix, static_cast<int>(s.first.size()), order);
        reordered = true;
        f = numeric(matrix, order, ints, reals);
    }
    f.reordered = reordered;
    return f;
}

void solve(std::span<const int> ints, std::span<const double> reals, std::span<double> rhs,
           std::span<double> work) {
    const int n = ints[0], blocks = ints[1];
    const int* row_at = ints.data() + kHeader;
    const int* start = row_at + n;
    const int* lp = start + blocks + 1;
    const int* li = lp + blocks + 1;
    const auto* dinv = reinterpret_cast<const Block*>(reals.data());
    const Block* lx = dinv + blocks;
    double* b = work.data();
    for (int p = 0; p < n; ++p) b[p] = rhs[row_at[p]];
    auto load = [&](int k) {
        const int size = start[k + 1] - start[k];
        return std::array<double, 2>{b[start[k]], size == 2 ? b[start[k] + 1] : 0.0};
    };
    auto add = [&](int k, double x0, double x1) {
        b[start[k]] += x0;
        if (start[k + 1] - start[k] == 2) b[start[k] + 1] += x1;
    };
    for (int k = 0; k < blocks; ++k) {
        const auto x = load(k);
        for (int p = lp[k]; p < lp[k + 1]; ++p) {
            const Block& l = lx[p];
            add(li[p], -(l[0] * x[0] + l[1] * x[1]), -(l[2] * x[0] + l[3] * x[1]));
        }
    }
    for (int k = 0; k < blocks; ++k) {
        const auto x = load(k);
        const Block& d = dinv[k];
        b[start[k]] = d[0] * x[0] + d[1] * x[1];
        if (start[k + 1] - start[k] == 2) b[start[k] + 1] = d[2] * x[0] + d[3] * x[1];
    }
    for (int k = blocks - 1; k >= 0; --k) {
        double x0 = 0.0, x1 = 0.0;
        for (int p = lp[k]; p < lp[k + 1]; ++p) {
            const Block& l = lx[p];
            const auto y = load(li[p]);
            x0 += l[0] * y[0] + l[2] * y[1];
            x1 += l[1] * y[0] + l[3] * y[1];
        }
        add(k, -x0, -x1);
    }
    for (int p = 0; p < n; ++p) rhs[row_at[p]] = b[p];
}

}  // namespace modsynth::nlp::ldl
