#pragma once
// One visitor from several lambdas, for std::visit over the variants of
// spatial primitives and obstacles: a kind without a lambda does not compile.

namespace modsynth::geometry {

template <class... F>
struct Overload : F... {
    using F::operator()...;
};
template <class... F>
Overload(F...) -> Overload<F...>;

}  // namespace modsynth::geometry
