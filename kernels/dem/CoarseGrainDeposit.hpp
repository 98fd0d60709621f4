#pragma once
/// \file CoarseGrainDeposit.hpp
/// \brief Deposits one sample of a DEM slice into the cell accumulators of a grid (CellSum
/// columns): each particle adds its area, mass, momentum, m v v and its contact virial (pairs
/// from its own neighbour row, plus wall contacts) to the cell of its centre.
///
/// One thread per particle sums its own contacts in registers, then adds CellSum::Size values to
/// its cell with atomics. The order in which particles of a cell are added therefore depends on
/// the thread schedule: the sums agree across thread counts and backends to round-off, not
/// bitwise (they are sampled every few thousand steps; speed is secondary).

#include "kernels/common/Compat.hpp"
#include "kernels/dem/CoarseGrainContact.hpp"
#include "kernels/dem/CoarseGrainGrid.hpp"
#include "kernels/dem/NeighborList.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/Periodic.hpp"
#include "kernels/dem/Walls.hpp"

#include <Kokkos_Core.hpp>

#include <stdexcept>

namespace hikiln::dem::cg {

/// \brief Contact virial of particle i: its neighbour-row contacts (last stored F_n, F_t; slots
/// that are not touching hold zeros) and its wall contacts.
template <class PositionView, class RadiusView, class MemorySpace, class WallView>
KOKKOS_INLINE_FUNCTION Tensor2 particleVirial(int i, PositionView const& x,
                                              RadiusView const& radius,
                                              NeighborList<MemorySpace> const& list,
                                              WallView const& wallFn, WallView const& wallFt,
                                              WallSet const& walls, PeriodicX const& periodic) {
  Tensor2 w;
  const double xi = x(i, 0), yi = x(i, 1), ri = radius(i);
  const int capacity = static_cast<int>(list.index.extent(1));
  const int n = list.count(i) < capacity ? list.count(i) : capacity;
  double nx = 0.0, ny = 0.0, overlap = 0.0;
  for (int k = 0; k < n; ++k) {
    const double fn = list.normalForce(i, k), ft = list.tangentialForce(i, k);
    if (fn == 0.0 && ft == 0.0) {
      continue;
    }
    const int j = list.index(i, k);
    if (pairGeometry(periodic.minimumImage(x(j, 0) - xi), x(j, 1) - yi, ri, radius(j), nx, ny,
                     overlap)) {
      addContactVirial(nx, ny, contactBranchLength(ri, overlap), fn, ft, w);
    }
  }
  for (int s = 0; s < wallSlotCount; ++s) {
    const double fn = wallFn(i, s), ft = wallFt(i, s);
    if ((fn != 0.0 || ft != 0.0) && wallGeometry(walls, s, xi, yi, ri, nx, ny, overlap)) {
      addContactVirial(nx, ny, contactBranchLength(ri, overlap), fn, ft, w);
    }
  }
  return w;
}

/// \brief Adds one sample of particles [0, p.count()) to `sums` (grid.cellCount() x CellSum::Size)
/// on `grid` (PolarGrid or CartesianGrid). `list` and `walls` hold the contact forces of the
/// current positions (as DemSystem leaves them between steps); `wallSet` and `periodic` are the
/// system's. Blocky particles pass their contact virials (n x 4: xx, xy, yx, yy, from
/// computeBlockyContactForces()) and true areas; empty Views: discs (virial from the stored
/// forces and the centre geometry, area pi r^2).
template <class ExecutionSpace, class MemorySpace, class Grid>
void depositCells(ExecutionSpace const& space, Grid const& grid,
                  ParticleArrays<MemorySpace> const& p, NeighborList<MemorySpace> const& list,
                  WallContactState<MemorySpace> const& walls, WallSet const& wallSet,
                  PeriodicX const& periodic, Kokkos::View<double**, MemorySpace> const& sums,
                  Kokkos::View<double* [4], MemorySpace> const& blockyVirial = {},
                  Kokkos::View<double*, MemorySpace> const& blockyArea = {}) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::cg::depositCells: particle memory not accessible");
  auto x = p.position;
  auto v = p.velocity;
  auto radius = p.radius;
  auto mass = p.mass;
  auto wallFn = walls.normalForce;
  auto wallFt = walls.tangentialForce;
  auto kind = p.kind;
  const bool blocky = blockyVirial.extent(0) >= p.count() && blockyArea.extent(0) >= p.count();
  if (!blocky && (blockyVirial.extent(0) > 0 || blockyArea.extent(0) > 0)) {
    throw std::invalid_argument("hikiln::dem::cg::depositCells: blocky virials and areas must "
                                "both cover every particle");
  }
  Kokkos::parallel_for(
      "hikiln::dem::cg::depositCells", Kokkos::RangePolicy<ExecutionSpace>(space, 0, p.count()),
      KOKKOS_LAMBDA(int i) {
        if (!isFree(kind(i))) { // fixed and shell discs are boundary, not bed
          return;
        }
        const int c = grid.cellOf(x(i, 0), x(i, 1));
        const double m = mass(i), r = radius(i), vx = v(i, 0), vy = v(i, 1);
        Tensor2 w;
        if (blocky) {
          w.xx = blockyVirial(i, 0);
          w.xy = blockyVirial(i, 1);
          w.yx = blockyVirial(i, 2);
          w.yy = blockyVirial(i, 3);
        } else {
          w = particleVirial(i, x, radius, list, wallFn, wallFt, wallSet, periodic);
        }
        Kokkos::atomic_add(&sums(c, CellSum::Count), 1.0);
        Kokkos::atomic_add(&sums(c, CellSum::Area), blocky ? blockyArea(i) : constants::pi * r * r);
        Kokkos::atomic_add(&sums(c, CellSum::Mass), m);
        Kokkos::atomic_add(&sums(c, CellSum::MomentumX), m * vx);
        Kokkos::atomic_add(&sums(c, CellSum::MomentumY), m * vy);
        Kokkos::atomic_add(&sums(c, CellSum::MvvXX), m * vx * vx);
        Kokkos::atomic_add(&sums(c, CellSum::MvvXY), m * vx * vy);
        Kokkos::atomic_add(&sums(c, CellSum::MvvYY), m * vy * vy);
        Kokkos::atomic_add(&sums(c, CellSum::VirialXX), w.xx);
        Kokkos::atomic_add(&sums(c, CellSum::VirialXY), w.xy);
        Kokkos::atomic_add(&sums(c, CellSum::VirialYX), w.yx);
        Kokkos::atomic_add(&sums(c, CellSum::VirialYY), w.yy);
      });
}

} // namespace hikiln::dem::cg
