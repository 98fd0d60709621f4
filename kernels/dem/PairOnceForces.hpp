#pragma once
/// \file PairOnceForces.hpp
/// \brief computeForces() with each particle pair evaluated once (Newton's third law) instead of
/// from both rows (`DemConfig::pairOnceForces`, case key `neighbor.pair_once`, host backends;
/// perf/README.md, "Each pair evaluated once", version 5).
///
/// Each row evaluates only its neighbours of higher id (rows are sorted by id). The row owner sums
/// its own side in double, in neighbour order, as ForceFunctor does; the partner's side (the
/// opposite force, its own lever's torque) goes into the partner's exact integer sums
/// (detail::PartnerSums), and the updated history into the partner's slot too, so that samplers,
/// energies and checkpoints read both rows as before. Integer sums do not depend on the order of
/// their terms, so a particle's force (its own sum, walls and gravity in a fixed order, plus the
/// partners' sum) does not depend on the thread count, the particle order or the rebuild schedule:
/// the guarantees of the full-row kernel, with the partners' side rounded to 2^-50 of the force
/// and torque scales (pairOnceScale()) instead of to the last bit of the sum.
///
/// Races: particles run in blocks of `block` consecutive indices, in three phases (blocks
/// b = 0, 1, 2 mod 3, one launch each). A pair's two blocks are at most one apart
/// (pairOnceBlockSize() after every rebuild), so the blocks of one phase write disjoint particles.
/// A GPU would rather use atomic integer additions; DemSystem keeps the full-row kernel there.

#include "kernels/dem/ForceKernel.hpp"

#include <Kokkos_Core.hpp>

#include <cmath>
#include <limits>
#include <string>

namespace hikiln::dem {

/// \brief What the pair-once pass keeps between steps.
template <class MemorySpace> struct PairOnceState {
  detail::PartnerSums<MemorySpace> partner; ///< sums (grown on demand) and the integer scale
  int block = 1; ///< particles per block: above the largest index distance of a pair in the list
};

/// \brief The integers' scale for a force scale F (N; for torques N m), e.g. k_n times the
/// largest diameter (times the largest radius for torques): the power of two that puts F between
/// 2^50 and 2^51, so a resolution of at most 2^-50 F, and a single contribution up to about 2^7 F
/// still fits (larger ones, and NaN, turn the force into NaN).
inline double pairOnceScale(double forceScale) {
  const double f = forceScale > 0.0 && std::isfinite(forceScale) ? forceScale : 1.0;
  return std::ldexp(1.0, 50 - std::ilogb(f));
}

/// \brief One more than the largest |i - j| over the pairs (i, j) of rows [0, n) of `list`: the
/// smallest block size for which a pair's blocks are at most one apart.
template <class ExecutionSpace, class MemorySpace>
int pairOnceBlockSize(ExecutionSpace const& space, NeighborList<MemorySpace> const& list,
                      std::size_t n) {
  auto count = list.count;
  auto index = list.index;
  const int width = list.capacity();
  int span = 0;
  Kokkos::parallel_reduce(
      "hikiln::dem::pairOnceBlockSize", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int i, int& largest) {
        const int c = count(i) < width ? count(i) : width;
        for (int k = 0; k < c; ++k) {
          const int d = index(i, k) > i ? index(i, k) - i : i - index(i, k);
          largest = d > largest ? d : largest;
        }
      },
      Kokkos::Max<int>(span));
  return span + 1;
}

/// \brief Forces and torques of particles [0, n) into p.force / p.torque as computeForces(), each
/// pair evaluated once (see the file comment); state.block must be pairOnceBlockSize() of the
/// list and state.partner's scales set (pairOnceScale()).
template <class ExecutionSpace, class MemorySpace>
void computeForcesPairOnce(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                           NeighborList<MemorySpace> const& list,
                           WallContactState<MemorySpace> const& walls,
                           ForceSettings const& settings, SliceTable<MemorySpace> const& slices,
                           PairOnceState<MemorySpace>& state) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::computeForcesPairOnce: particle memory not accessible");
  const int n = static_cast<int>(p.count());
  if (state.partner.sums.extent(0) < p.count()) {
    state.partner.sums = Kokkos::View<std::int64_t* [4], MemorySpace>(
        Kokkos::view_alloc(space, std::string("hikiln::dem::partnerSums")), p.force.extent(0));
  }
  auto sums = state.partner.sums;
  Kokkos::parallel_for(
      "hikiln::dem::clearPartnerSums", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int i) {
        for (int c = 0; c < 4; ++c) {
          sums(i, c) = 0;
        }
      });
  auto fun = detail::makeForceFunctor<false, false, true>(p, list, walls, settings, slices,
                                                          p.velocity, p.angularVelocity);
  fun.partner = state.partner;
  const int block = state.block > 0 ? state.block : 1;
  const int blocks = (n + block - 1) / block;
  for (int phase = 0; phase < 3; ++phase) {
    const int inPhase = (blocks - phase + 2) / 3;
    if (inPhase <= 0) {
      continue;
    }
    Kokkos::parallel_for(
        "hikiln::dem::computeForcesPairOnce",
        Kokkos::RangePolicy<ExecutionSpace, Kokkos::Schedule<Kokkos::Dynamic>>(space, 0, inPhase)
            .set_chunk_size(1),
        KOKKOS_LAMBDA(int q) {
          const int b = phase + 3 * q;
          const int end = (b + 1) * block < n ? (b + 1) * block : n;
          for (int i = b * block; i < end; ++i) {
            fun(i);
          }
        });
  }
  auto f = p.force;
  auto tq = p.torque;
  const double forceStep = 1.0 / state.partner.forceScale; // powers of two: exact
  const double torqueStep = 1.0 / state.partner.torqueScale;
  const double notANumber = std::numeric_limits<double>::quiet_NaN();
  Kokkos::parallel_for(
      "hikiln::dem::addPartnerSums", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int i) {
        if (sums(i, 3) != 0) { // a contribution did not fit: let the run's checks see it
          f(i, 0) = f(i, 1) = tq(i) = notANumber;
          return;
        }
        f(i, 0) += static_cast<double>(sums(i, 0)) * forceStep;
        f(i, 1) += static_cast<double>(sums(i, 1)) * forceStep;
        tq(i) += static_cast<double>(sums(i, 2)) * torqueStep;
      });
}

} // namespace hikiln::dem
