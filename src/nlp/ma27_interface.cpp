// The block LDLᵀ (block_ldl.h) behind the calling convention of HSL's MA27,
// built as a shared library named libhsl.so.
//
// Debian's Ipopt 3.11 has no MA27 of its own: for `linear_solver ma27` it
// dlopen()s "libhsl.so" and looks these four symbols up. modsynth links
// this library, so it is loaded at start-up under that soname, and glibc's
// dlopen hands the loaded copy back instead of searching the disk.
//
// Ipopt keeps MA27's state in arrays it owns: IKEEP (3n ints) from the
// analysis to every factorization, and A and IW from a factorization to its
// solves. The order and the factor live there, so this file holds no state.
// Only what Ipopt's MA27 interface reads is filled in: INFO(1) (0, or -3/-4
// with the size needed in INFO(2) when IW or A is too small), INFO(5) and
// INFO(6) after the analysis (the sizes of A and IW to allocate), INFO(15)
// (negative eigenvalues) and MAXFRT/NSTEPS (the sizes of the solve's
// scratch arrays).
#include <modsynth/nlp/block_ldl.h>

#include <dlfcn.h>

#include <algorithm>
#include <limits>
#include <span>
#include <vector>

namespace {

using namespace modsynth::nlp::ldl;

constexpr int kInfoLength = 20;

int clamp_int(std::size_t v) {
    return static_cast<int>(std::min<std::size_t>(v, std::numeric_limits<int>::max()));
}

SymmetricTriplets triplets(const int* n, const int* nz, const int* irn, const int* icn,
                           const double* a) {
    const std::size_t count = *nz > 0 ? static_cast<std::size_t>(*nz) : 0;
    SymmetricTriplets m;
    m.n = *n;
    m.rows = {irn, count};
    m.cols = {icn, count};
    if (a) m.values = {a, count};
    m.base = 1;
    return m;
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) void ma27id_(int* icntl, double* cntl) {
    std::fill(icntl, icntl + 30, 0);
    std::fill(cntl, cntl + 5, 0.0);
    cntl[0] = 0.1;
}

__attribute__((visibility("default"))) void ma27ad_(int* n, int* nz, const int* irn, const int* icn,
                                                    int* /*iw*/, int* /*liw*/, int* ikeep,
                                                    int* /*iw1*/, int* nsteps, int* /*iflag*/,
                                                    int* /*icntl*/, double* /*cntl*/, int* info,
                                                    double* ops) {
    std::fill(info, info + kInfoLength, 0);
    *nsteps = 1;
    *ops = 0.0;
    const SymmetricTriplets pattern = triplets(n, nz, irn, icn, nullptr);
    if (*n < 1 || *nz < 0) {
        info[0] = -1;
        return;
    }
    const Workspace w = choose_order(pattern, {ikeep, order_size(*n)});
    if (w.ints == 0) {
        info[0] = -1;  // an index out of range
        return;
    }
    info[4] = clamp_int(w.reals);
    info[5] = clamp_int(w.ints);
}

__attribute__((visibility("default"))) void ma27bd_(int* n, int* nz, const int* irn, const int* icn,
                                                    double* a, int* la, int* iw, int* liw,
                                                    int* ikeep, int* nsteps, int* maxfrt,
                                                    int* /*iw1*/, int* /*icntl*/, double* /*cntl*/,
                                                    int* info) {
    std::fill(info, info + kInfoLength, 0);
    // The values arrive in the first NZ entries of A, which the factor
    // overwrites: factorize from a copy.
    const std::vector<double> values(a, a + std::max(*nz, 0));
    const SymmetricTriplets m = triplets(n, nz, irn, icn, values.data());
    const Factorization f =
        factorize(m, {ikeep, order_size(*n)}, {iw, static_cast<std::size_t>(std::max(*liw, 0))},
                  {a, static_cast<std::size_t>(std::max(*la, 0))});
    switch (f.status) {
        case Factorization::Status::Ok:
            break;
        case Factorization::Status::NeedInts:
            info[0] = -3;
            info[1] = clamp_int(f.needed.ints);
            return;
        case Factorization::Status::NeedReals:
            info[0] = -4;
            info[1] = clamp_int(f.needed.reals);
            return;
        case Factorization::Status::BadIndex:
            info[0] = -1;
            return;
    }
    *maxfrt = *n;  // the solve's scratch: one vector
    *nsteps = 1;
    info[1] = *n;
    info[14] = f.negative;
}

__attribute__((visibility("default"))) void ma27cd_(int* n, double* a, int* la, int* iw, int* liw,
                                                    double* w, int* /*maxfrt*/, double* rhs,
                                                    int* /*iw1*/, int* /*nsteps*/, int* /*icntl*/,
                                                    int* /*info*/) {
    const auto size = static_cast<std::size_t>(*n);
    solve({iw, static_cast<std::size_t>(*liw)}, {a, static_cast<std::size_t>(*la)}, {rhs, size},
          {w, size});
}
}

bool modsynth::nlp::ldl::serves_as_ma27() {
    // RTLD_NOLOAD: only a library already loaded answers, none is read from
    // disk; and it must be this one, not another libhsl.so.
    void* loaded = dlopen("libhsl.so", RTLD_LAZY | RTLD_NOLOAD);
    if (!loaded) return false;
    const bool ours = dlsym(loaded, "ma27ad_") == reinterpret_cast<void*>(&ma27ad_);
    dlclose(loaded);
    return ours;
}
