#pragma once
/// \file OpenEndKernels.hpp
/// \brief Kernels on the boundary faces of an open z end of the domain (a kiln's inlet and
/// discharge faces; TwoPhaseSolver's OpenSides): the given inflow, the zero-gradient outflow,
/// the ghost cells the volume-fraction fluxes read there, and the volume flux through the end.
/// Fields are z-face fields (w, inflow data) or cell fields (phi) on grid; side is ZLow or ZHigh.

#include "kernels/cfd/Grid.hpp"
#include "kernels/cfd/ShellGeometry.hpp"

#include <Kokkos_Core.hpp>

namespace hikiln::cfd {

/// \brief The boundary faces of a z side, in storage indices (kernels take (I, J, K)).
template <class ExecutionSpace>
GridPolicy<ExecutionSpace> endFacePolicy(ExecutionSpace const& space, Grid const& grid, int side) {
  const int g = grid.ghost, gz = grid.ghostZ();
  const int K = (side == ZLow ? 0 : grid.nz) + gz;
  return gridPolicy(space, {g, g, K}, {grid.nx + g, grid.ny + g, K + 1});
}

/// \brief to = scale x from on the boundary faces of a z side.
template <class ExecutionSpace, class MemorySpace>
void copyEndFaces(ExecutionSpace const& space, Grid const& grid, int side,
                  Field<MemorySpace> const& from, Field<MemorySpace> const& to,
                  double scale = 1.0) {
  Kokkos::parallel_for(
      "hikiln::cfd::copyEndFaces", endFacePolicy(space, grid, side),
      KOKKOS_LAMBDA(const int I, const int J, const int K) {
        to(I, J, K) = scale * from(I, J, K);
      });
}

/// \brief w on the boundary faces of a z side = w on the faces one cell inside (zero gradient).
template <class ExecutionSpace, class MemorySpace>
void extrapolateEndFaces(ExecutionSpace const& space, Grid const& grid, int side,
                         Field<MemorySpace> const& w) {
  const int inward = side == ZLow ? 1 : -1;
  Kokkos::parallel_for(
      "hikiln::cfd::extrapolateEndFaces", endFacePolicy(space, grid, side),
      KOKKOS_LAMBDA(const int I, const int J, const int K) { w(I, J, K) = w(I, J, K + inward); });
}

/// \brief The ghost cells of phi beyond a z side: phiIn (a z-face field) on an inflow side,
/// the cell inside (zero gradient) otherwise.
template <class ExecutionSpace, class MemorySpace>
void fillEndGhosts(ExecutionSpace const& space, Grid const& grid, int side, bool inflow,
                   Field<MemorySpace> const& phiIn, Field<MemorySpace> const& phi) {
  // storage offsets from the boundary face's K to the ghost cell and to the cell inside
  const int ghost = side == ZLow ? -1 : 0;
  const int inside = side == ZLow ? 0 : -1;
  Kokkos::parallel_for(
      "hikiln::cfd::fillEndGhosts", endFacePolicy(space, grid, side),
      KOKKOS_LAMBDA(const int I, const int J, const int K) {
        phi(I, J, K + ghost) = inflow ? phiIn(I, J, K) : phi(I, J, K + inside);
      });
}

/// \brief Evaluates an inflow (inflow.axialVelocity(x, y), speed into the domain, and
/// inflow.inflowPhi(x, y); KilnInlet) at the centroids of the open boundary faces of a z side
/// into the z-face fields w (signed along z) and phiIn (0 on closed faces); returns the range
/// of phiIn in lo, hi.
template <class ExecutionSpace, class MemorySpace, class Inflow>
void evaluateInflow(ExecutionSpace const& space, CutCells<MemorySpace> const& cc, int side,
                    Inflow const& inflow, Field<MemorySpace> const& w,
                    Field<MemorySpace> const& phiIn, double& lo, double& hi) {
  const auto ap = cc.aperture[2];
  const auto cx = cc.centroid[2][0], cy = cc.centroid[2][1];
  const double sign = side == ZLow ? 1.0 : -1.0;
  lo = 0.0;
  hi = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::cfd::evaluateInflow", endFacePolicy(space, cc.grid, side),
      KOKKOS_LAMBDA(const int I, const int J, const int K, double& mn, double& mx) {
        const bool open = ap(I, J, K) > 0.0;
        const double x = cx(I, J, K), y = cy(I, J, K);
        w(I, J, K) = open ? sign * inflow.axialVelocity(x, y) : 0.0;
        const double f = open ? inflow.inflowPhi(x, y) : 0.0;
        phiIn(I, J, K) = f;
        mn = math::fmin(mn, f);
        mx = math::fmax(mx, f);
      },
      Kokkos::Min<double>(lo), Kokkos::Max<double>(hi));
}

/// \brief Volume flux (m^3/s) through the open boundary faces of a z side, sum of aperture x w
/// x face area, positive out of the domain.
template <class ExecutionSpace, class MemorySpace>
double endVolumeOutflow(ExecutionSpace const& space, CutCells<MemorySpace> const& cc, int side,
                        Field<MemorySpace> const& w) {
  const auto ap = cc.aperture[2];
  double sum = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::cfd::endVolumeOutflow", endFacePolicy(space, cc.grid, side),
      KOKKOS_LAMBDA(const int I, const int J, const int K, double& f) {
        f += ap(I, J, K) * w(I, J, K);
      },
      sum);
  return (side == ZLow ? -1.0 : 1.0) * sum * cc.grid.hx * cc.grid.hy;
}

} // namespace hikiln::cfd
