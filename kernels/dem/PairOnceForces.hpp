#pragma once
/// \file PairOnceForces.hpp
/// \brief computeForces() with each particle pair evaluated once (Newton's third law) instead of
/// from both rows (`DemConfig::pairOnceForces`, case key `neighbor.pair_once`, host backends;
/// perf/README.md, "Each pair evaluated once", version 5).
///
/// Each row evaluates only its neighbours of higher id (rows are sorted by id). The row owner sums
/// its own side in double, in neighbour order, as ForceFunctor does; the partner's side (the
/// opposite force, its own lever's torque) goes into the partner's exact integer sums
/// (detail::PartnerSums). The history is updated in the owner's slot only: mirrorPairOnceHistory()
/// copies it into the partner's slot, and DemSystem runs it before anything reads both rows
/// (samplers, energies, checkpoints, accessors), which then see the rows as the full-row kernel
/// leaves them; at sample times only, instead of a copy per contact and step. Integer sums do not
/// depend on the order of their terms, so a particle's force (its own sum, walls and gravity in a
/// fixed order, plus the partners' sum) does not depend on the thread count, the particle order or
/// the rebuild schedule: the guarantees of the full-row kernel, with the partners' side rounded to
/// 2^-50 of the force and torque scales (pairOnceScale()) instead of to the last bit of the sum.
///
/// Races: particles run in blocks of `block` consecutive indices, in three phases (blocks
/// b = 0, 1, 2 mod 3, one launch each). A pair's two blocks are at most one apart
/// (layOutPairOnce() after every rebuild), so the blocks of one phase write disjoint particles.
/// A GPU would rather use atomic integer additions; DemSystem keeps the full-row kernel there.

#include "kernels/dem/ForceKernel.hpp"

#include <Kokkos_Core.hpp>

#include <cmath>
#include <limits>
#include <string>

namespace hikiln::dem {

/// \brief What the pair-once pass keeps between steps.
template <class MemorySpace> struct PairOnceState {
  detail::PartnerSums<MemorySpace> partner; ///< sums (grown on demand; zero between steps), scales
  Kokkos::View<int*, MemorySpace> firstHigher; ///< per row: its first slot of a higher id
  int block = 1; ///< particles per block: above the largest index distance of a pair in the list
};

/// \brief The integers' scale for a force scale F (N; for torques N m), e.g. k_n times the
/// largest diameter (times the largest radius for torques): the power of two that puts F between
/// 2^50 and 2^51, so a resolution of at most 2^-50 F, and a single contribution up to about 2^5 F
/// still fits (larger ones, and NaN, turn the force into NaN).
inline double pairOnceScale(double forceScale) {
  const double f = forceScale > 0.0 && std::isfinite(forceScale) ? forceScale : 1.0;
  return std::ldexp(1.0, 50 - std::ilogb(f));
}

/// \brief What the pair-once pass needs of a freshly built list (call after every rebuild: both
/// hold until the next one, as rows and particle indices do): each row's first slot of a higher
/// id (rows are sorted by id; found once here, not at every step), and the block size, one more
/// than the largest |i - j| over the pairs (i, j) of rows [0, n), the smallest for which a pair's
/// blocks are at most one apart.
template <class ExecutionSpace, class MemorySpace>
void layOutPairOnce(ExecutionSpace const& space, NeighborList<MemorySpace> const& list,
                    Kokkos::View<std::int64_t*, MemorySpace> const& id, std::size_t n,
                    PairOnceState<MemorySpace>& state) {
  if (state.firstHigher.extent(0) < n) {
    state.firstHigher = Kokkos::View<int*, MemorySpace>(
        Kokkos::view_alloc(space, Kokkos::WithoutInitializing,
                           std::string("hikiln::dem::pairOnceFirstHigher")),
        id.extent(0) > n ? id.extent(0) : n);
  }
  auto firstHigher = state.firstHigher;
  auto count = list.count;
  auto index = list.index;
  const int width = list.capacity();
  int span = 0;
  Kokkos::parallel_reduce(
      "hikiln::dem::layOutPairOnce", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int i, int& largest) {
        const int c = count(i) < width ? count(i) : width;
        int first = c;
        for (int k = c - 1; k >= 0; --k) {
          const int j = index(i, k);
          first = id(j) > id(i) ? k : first;
          const int d = j > i ? j - i : i - j;
          largest = d > largest ? d : largest;
        }
        firstHigher(i) = first;
      },
      Kokkos::Max<int>(span));
  state.block = span + 1;
}

/// \brief The history of each pair into the slot of its partner (the lower id's row, which
/// computeForcesPairOnce() does not update), so that both rows hold it as after computeForces().
/// Each row writes only its own slots; a pair found in one row only (none, as lists are
/// symmetric) keeps its value.
template <class ExecutionSpace, class MemorySpace>
void mirrorPairOnceHistory(ExecutionSpace const& space, NeighborList<MemorySpace> const& list,
                           std::size_t n, PairOnceState<MemorySpace> const& state) {
  auto firstHigher = state.firstHigher;
  auto count = list.count;
  auto index = list.index;
  auto shear = list.shear;
  const int width = list.capacity();
  Kokkos::parallel_for(
      "hikiln::dem::mirrorPairOnceHistory", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int i) {
        for (int k = 0; k < firstHigher(i); ++k) { // partners of lower id own these pairs
          const int j = index(i, k);
          const int c = count(j) < width ? count(j) : width;
          for (int m = firstHigher(j); m < c; ++m) {
            if (index(j, m) == i) {
              shear(i, k) = shear(j, m);
              break;
            }
          }
        }
      });
}

/// \brief Forces and torques of particles [0, n) into p.force / p.torque as computeForces(), each
/// pair evaluated once (see the file comment); layOutPairOnce() must have seen the list, and
/// state.partner's scales must be set (pairOnceScale()).
template <class ExecutionSpace, class MemorySpace>
void computeForcesPairOnce(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                           NeighborList<MemorySpace> const& list,
                           WallContactState<MemorySpace> const& walls,
                           ForceSettings const& settings, SliceTable<MemorySpace> const& slices,
                           PairOnceState<MemorySpace>& state) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::computeForcesPairOnce: particle memory not accessible");
  const int n = static_cast<int>(p.count());
  if (state.partner.sums.extent(0) < p.count()) { // zero-filled; addPartnerSums clears after use
    state.partner.sums = Kokkos::View<std::int64_t* [4], MemorySpace>(
        Kokkos::view_alloc(space, std::string("hikiln::dem::partnerSums")), p.force.extent(0));
  }
  auto sums = state.partner.sums;
  auto fun = detail::makeForceFunctor<false, false, true>(p, list, walls, settings, slices,
                                                          p.velocity, p.angularVelocity);
  fun.partner = state.partner;
  fun.firstHigher = state.firstHigher;
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
        } else {
          f(i, 0) += static_cast<double>(sums(i, 0)) * forceStep;
          f(i, 1) += static_cast<double>(sums(i, 1)) * forceStep;
          tq(i) += static_cast<double>(sums(i, 2)) * torqueStep;
        }
        for (int c = 0; c < 4; ++c) { // ready for the next step (saves a launch)
          sums(i, c) = 0;
        }
      });
}

} // namespace hikiln::dem
