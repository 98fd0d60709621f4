#pragma once
/// \file Reorder.hpp
/// \brief Reordering of particles (e.g. by cell, for memory locality) together with their contact
/// history rows. Rows store neighbour indices, so a reorder remaps them through the inverse
/// permutation: the permuted list is valid for the permuted particles at once (and a rebuild
/// carries its history over by id as usual).

#include "kernels/dem/NeighborList.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/Walls.hpp"

#include <Kokkos_Core.hpp>

#include <string>

namespace hikiln::dem {

/// \brief dst(k) = src(permutation(k)) for every particle field, k in [0, src.count()); dst must
/// have at least that capacity and must not alias src. dst's count is set to src's.
template <class ExecutionSpace, class MemorySpace, class PermutationView>
void permuteParticles(ExecutionSpace const& space, PermutationView const& permutation,
                      ParticleArrays<MemorySpace> const& src, ParticleArrays<MemorySpace>& dst) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::permuteParticles: particle memory not accessible");
  dst.setCount(src.count());
  const ParticleArrays<MemorySpace> s = src;
  const ParticleArrays<MemorySpace> d = dst;
  Kokkos::parallel_for(
      "hikiln::dem::permuteParticles", Kokkos::RangePolicy<ExecutionSpace>(space, 0, src.count()),
      KOKKOS_LAMBDA(int k) {
        const int o = permutation(k);
        for (int c = 0; c < 2; ++c) {
          d.position(k, c) = s.position(o, c);
          d.velocity(k, c) = s.velocity(o, c);
          d.force(k, c) = s.force(o, c);
        }
        d.angularVelocity(k) = s.angularVelocity(o);
        d.torque(k) = s.torque(o);
        d.radius(k) = s.radius(o);
        d.mass(k) = s.mass(o);
        d.inertia(k) = s.inertia(o);
        d.inverseMass(k) = s.inverseMass(o);
        d.inverseInertia(k) = s.inverseInertia(o);
        d.id(k) = s.id(o);
        d.kind(k) = s.kind(o);
      });
}

namespace detail {
/// \brief out(k) = in(o) for a rank-1 View, out(k, :) = in(o, :) for rank 2. The rank switch lives
/// here because CUDA extended lambdas may not capture variables inside `if constexpr`.
template <class View>
KOKKOS_INLINE_FUNCTION void copyEntry(View const& out, int k, View const& in, int o) {
  if constexpr (View::rank == 2) {
    for (std::size_t c = 0; c < in.extent(1); ++c) {
      out(k, c) = in(o, c);
    }
  } else {
    out(k) = in(o);
  }
}
} // namespace detail

/// \brief view = view permuted: entry k becomes entry permutation(k), k in [0, n), for a rank-1
/// or rank-2 View (all columns). The data move to a new allocation (zero-filled beyond n, labelled
/// like the old one) whose handle replaces `view`; the old allocation is released when no other
/// handle holds it. Only one field's worth of scratch is alive at a time.
template <class ExecutionSpace, class PermutationView, class View>
void permuteView(ExecutionSpace const& space, PermutationView const& permutation, std::size_t n,
                 View& view) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, typename View::memory_space>::accessible,
                "hikiln::dem::permuteView: view memory not accessible");
  static_assert(View::rank == 1 || View::rank == 2, "hikiln::dem::permuteView: rank 1 or 2");
  View out;
  if constexpr (View::rank_dynamic == 2) {
    out = View(Kokkos::view_alloc(space, view.label()), view.extent(0), view.extent(1));
  } else { // rank 1, or rank 2 with a compile-time column count
    out = View(Kokkos::view_alloc(space, view.label()), view.extent(0));
  }
  const View in = view;
  Kokkos::parallel_for(
      "hikiln::dem::permuteView", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int k) { detail::copyEntry(out, k, in, permutation(k)); });
  view = out;
}

/// \brief Permutes every field of p's live particles (entry k becomes entry permutation(k)) one
/// field at a time with permuteView(), so a reorder needs one field of scratch, not a second
/// particle container. p's Views are replaced (other handles keep the old order).
template <class ExecutionSpace, class MemorySpace, class PermutationView>
void permuteParticlesInPlace(ExecutionSpace const& space, PermutationView const& permutation,
                             ParticleArrays<MemorySpace>& p) {
  const std::size_t n = p.count();
  permuteView(space, permutation, n, p.position);
  permuteView(space, permutation, n, p.velocity);
  permuteView(space, permutation, n, p.angularVelocity);
  permuteView(space, permutation, n, p.force);
  permuteView(space, permutation, n, p.torque);
  permuteView(space, permutation, n, p.radius);
  permuteView(space, permutation, n, p.mass);
  permuteView(space, permutation, n, p.inertia);
  permuteView(space, permutation, n, p.inverseMass);
  permuteView(space, permutation, n, p.inverseInertia);
  permuteView(space, permutation, n, p.id);
  permuteView(space, permutation, n, p.kind);
}

/// \brief inverse(permutation(k)) = k for k in [0, n).
template <class ExecutionSpace, class PermutationView>
Kokkos::View<int*, typename PermutationView::memory_space>
inversePermutation(ExecutionSpace const& space, PermutationView const& permutation, std::size_t n) {
  Kokkos::View<int*, typename PermutationView::memory_space> inverse(
      Kokkos::view_alloc(space, Kokkos::WithoutInitializing,
                         std::string("hikiln::dem::inversePermutation")),
      n);
  Kokkos::parallel_for(
      "hikiln::dem::inversePermutation", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int k) { inverse(permutation(k)) = k; });
  return inverse;
}

/// \brief Row k of the destination history = row permutation(k) of the source with its neighbour
/// indices mapped to the new order, for the neighbour list (count, index, shear and the optional
/// views both lists have) and the wall contact state (shear, and the forces when both have them).
/// Source rows wider than the destination are truncated.
template <class ExecutionSpace, class MemorySpace, class PermutationView>
void permuteContactRows(ExecutionSpace const& space, PermutationView const& permutation,
                        std::size_t n, NeighborList<MemorySpace> const& src,
                        NeighborList<MemorySpace> const& dst,
                        WallContactState<MemorySpace> const& wallSrc,
                        WallContactState<MemorySpace> const& wallDst) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::permuteContactRows: list memory not accessible");
  const auto inverse = inversePermutation(space, permutation, n);
  const int capacity = src.capacity() < dst.capacity() ? src.capacity() : dst.capacity();
  const bool ids = src.neighborId.extent(0) >= n && dst.neighborId.extent(0) >= n;
  const bool forces = src.normalForce.extent(0) >= n && dst.normalForce.extent(0) >= n &&
                      src.tangentialForce.extent(0) >= n && dst.tangentialForce.extent(0) >= n;
  const bool wallForces = wallSrc.normalForce.extent(0) >= n && wallDst.normalForce.extent(0) >= n;
  const bool angles = src.normalAngle.extent(0) >= n && dst.normalAngle.extent(0) >= n;
// GCC 12 at -O3 flags the guarded wall-force copy for empty (unallocated) force views as out of
// bounds although `wallForces` is false then: a known false positive of -Warray-bounds.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#endif
  Kokkos::parallel_for(
      "hikiln::dem::permuteContactRows", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int k) {
        const int o = permutation(k);
        const int c = src.count(o) < capacity ? src.count(o) : capacity;
        dst.count(k) = c;
        for (int m = 0; m < c; ++m) {
          dst.index(k, m) = inverse(src.index(o, m));
          dst.shear(k, m) = src.shear(o, m);
          if (ids) {
            dst.neighborId(k, m) = src.neighborId(o, m);
          }
          if (forces) {
            dst.normalForce(k, m) = src.normalForce(o, m);
            dst.tangentialForce(k, m) = src.tangentialForce(o, m);
          }
          if (angles) {
            dst.normalAngle(k, m) = src.normalAngle(o, m);
          }
        }
        for (int m = 0; m < wallSlotCount; ++m) {
          wallDst.shear(k, m) = wallSrc.shear(o, m);
          if (wallForces) {
            wallDst.normalForce(k, m) = wallSrc.normalForce(o, m);
            wallDst.tangentialForce(k, m) = wallSrc.tangentialForce(o, m);
          }
        }
      });
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
}

} // namespace hikiln::dem
